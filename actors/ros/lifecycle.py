"""The managed-node state machine of ROS 2 (rcl_lifecycle's default one): states, transitions, their ids.

A managed (lifecycle) node is in one of four primary states, unconfigured,
inactive, active or finalized.  A primary transition (configure, cleanup,
activate, deactivate, shutdown) moves it into a transition state
(configuring...), where the node's callback runs; the callback's result
(``transition_success``, ``transition_failure``, ``transition_error``) then
takes it to the next primary state, or into errorprocessing, whose own
callback decides between unconfigured and finalized.  Ids and labels are
lifecycle_msgs', so what the services answer reads as ROS's.

:class:`LifecycleMachine` holds one node's current state and moves it; it
runs no callback itself (the node does, between the two moves).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

from actors.errors import ActorsError

__all__ = [
    "STATES",
    "TRANSITIONS",
    "CallbackResult",
    "LifecycleError",
    "LifecycleMachine",
    "TransitionSpec",
]


class LifecycleError(ActorsError):
    """A transition that the current state does not offer."""


#: Every state by id: the primary ones, then the transition states (lifecycle_msgs/msg/State's ids).
STATES: dict[int, str] = {
    0: "unknown",
    1: "unconfigured",
    2: "inactive",
    3: "active",
    4: "finalized",
    10: "configuring",
    11: "cleaningup",
    12: "shuttingdown",
    13: "activating",
    14: "deactivating",
    15: "errorprocessing",
}
_UNCONFIGURED, _INACTIVE, _ACTIVE, _FINALIZED = 1, 2, 3, 4
_ERRORPROCESSING = 15


class CallbackResult(IntEnum):
    """What a transition callback returns (lifecycle_msgs' TRANSITION_CALLBACK_* values)."""

    SUCCESS = 97
    FAILURE = 98
    ERROR = 99

    def to_label(self) -> str:
        """The label of the transition this result triggers: ``transition_success``..."""
        return f"transition_{self.name.lower()}"


@dataclass(frozen=True, slots=True)
class TransitionSpec:
    """One edge of the graph: its id and label, and the states it leaves and reaches."""

    id: int
    label: str
    start: int
    goal: int

    @property
    def start_label(self) -> str:
        """The label of the state it leaves."""
        return STATES[self.start]

    @property
    def goal_label(self) -> str:
        """The label of the state it reaches."""
        return STATES[self.goal]


def _primary(id_: int, label: str, start: int, through: int, success: int, failure: int) -> list[TransitionSpec]:
    # A primary transition into its transition state ``through``, then the three results out of it,
    # numbered as lifecycle_msgs numbers them (configure 1 -> 10, 11, 12; activate 3 -> 30...).
    results = (("success", success), ("failure", failure), ("error", _ERRORPROCESSING))
    return [TransitionSpec(id_, label, start, through)] + [
        TransitionSpec(id_ * 10 + n, f"transition_{name}", through, goal) for n, (name, goal) in enumerate(results)
    ]


#: Every transition, in the order rcl_lifecycle registers them (what ``get_transition_graph`` lists).
TRANSITIONS: tuple[TransitionSpec, ...] = (
    *_primary(1, "configure", _UNCONFIGURED, 10, _INACTIVE, _UNCONFIGURED),
    *_primary(2, "cleanup", _INACTIVE, 11, _UNCONFIGURED, _INACTIVE),
    *_primary(3, "activate", _INACTIVE, 13, _ACTIVE, _INACTIVE),
    *_primary(4, "deactivate", _ACTIVE, 14, _INACTIVE, _ACTIVE),
    TransitionSpec(5, "shutdown", _UNCONFIGURED, 12),
    TransitionSpec(6, "shutdown", _INACTIVE, 12),
    TransitionSpec(7, "shutdown", _ACTIVE, 12),
    TransitionSpec(50, "transition_success", 12, _FINALIZED),
    TransitionSpec(51, "transition_failure", 12, _FINALIZED),
    TransitionSpec(52, "transition_error", 12, _ERRORPROCESSING),
    TransitionSpec(60, "transition_success", _ERRORPROCESSING, _UNCONFIGURED),
    TransitionSpec(61, "transition_failure", _ERRORPROCESSING, _FINALIZED),
    TransitionSpec(62, "transition_error", _ERRORPROCESSING, _FINALIZED),
)


class LifecycleMachine:
    """One node's place in the graph: it starts unconfigured and moves one transition at a time."""

    def __init__(self) -> None:
        self.state = _UNCONFIGURED

    @property
    def current(self) -> tuple[int, str]:
        """The current state's id and label."""
        return self.state, STATES[self.state]

    def available(self) -> list[TransitionSpec]:
        """The transitions that leave the current state, in the graph's order."""
        return [t for t in TRANSITIONS if t.start == self.state]

    def find(self, *, id: int | None = None, label: str | None = None) -> TransitionSpec:
        """The transition out of the current state with this id (or label); LifecycleError if none."""
        for transition in self.available():
            if transition.id == id or (label is not None and transition.label == label):
                return transition
        wanted = f"id {id}" if label is None else f"label {label!r}"
        raise LifecycleError(f"no transition with {wanted} from state {STATES[self.state]}")

    def take(self, transition: TransitionSpec) -> None:
        """Move along ``transition``, which must leave the current state (LifecycleError otherwise)."""
        if transition.start != self.state:
            raise LifecycleError(f"transition {transition.label} does not leave state {STATES[self.state]}")
        self.state = transition.goal
