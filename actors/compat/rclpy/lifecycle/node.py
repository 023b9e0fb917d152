"""``rclpy.lifecycle.node``: LifecycleNode, a managed node over :mod:`actors.ros.lifecycle`'s state machine.

A LifecycleNode starts unconfigured.  ``trigger_configure()`` and its
siblings, or a request to its ``~/change_state`` service (``actors lifecycle
set``), take a primary transition, run the matching ``on_*`` callback and
follow the result: SUCCESS to the next state, FAILURE back, ERROR (or an
exception) into errorprocessing, where ``on_error`` decides.  The default
callbacks call those of the node's managed entities (its lifecycle
publishers), which is how a publisher learns it may deliver.  With the
communication interface (the default) the node serves ``~/change_state``,
``~/get_state``, ``~/get_available_states``, ``~/get_available_transitions``
and ``~/get_transition_graph`` and publishes each move on
``~/transition_event``, as an rclpy lifecycle node does.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from actors.compat.rclpy.callback_groups import CallbackGroup
from actors.compat.rclpy.lifecycle.managed_entity import ManagedEntity
from actors.compat.rclpy.lifecycle.publisher import LifecyclePublisher
from actors.compat.rclpy.node import Node
from actors.ros.lifecycle import STATES, TRANSITIONS, LifecycleError, LifecycleMachine, TransitionSpec
from actors.ros.lifecycle import CallbackResult as TransitionCallbackReturn
from interfaces.lifecycle_msgs.msg import State, TransitionDescription, TransitionEvent
from interfaces.lifecycle_msgs.srv import ChangeState, GetAvailableStates, GetAvailableTransitions, GetState

__all__ = ["LifecycleNode", "LifecycleNodeMixin", "LifecycleState", "TransitionCallbackReturn"]

# The transition state each callback runs in, by the callback's name.
_CALLBACKS = {
    10: "on_configure",
    11: "on_cleanup",
    12: "on_shutdown",
    13: "on_activate",
    14: "on_deactivate",
    15: "on_error",
}
_SHUTDOWN_FROM = {1: 5, 2: 6, 3: 7}  # the shutdown transition's id out of each primary state


class LifecycleState(NamedTuple):
    """The state a transition started from, as the ``on_*`` callbacks get it."""

    label: str
    state_id: int


class _StateMachine:
    """rclpy's view of the state machine: the current state as (id, label), and the services made for it."""

    def __init__(self, publish: Callable[[Any], None] | None) -> None:
        self.machine = LifecycleMachine()
        self.initialized = True
        self._publish = publish
        self.service_change_state: Any = None
        self.service_get_state: Any = None
        self.service_get_available_states: Any = None
        self.service_get_available_transitions: Any = None
        self.service_get_transition_graph: Any = None

    @property
    def current_state(self) -> tuple[int, str]:
        return self.machine.current

    @property
    def available_states(self) -> list[tuple[int, str]]:
        return list(STATES.items())

    @property
    def available_transitions(self) -> list[TransitionSpec]:
        return self.machine.available()

    @property
    def transition_graph(self) -> tuple[TransitionSpec, ...]:
        return TRANSITIONS

    def take(self, transition: TransitionSpec) -> None:
        # Move, and tell ~/transition_event where from and where to (rcl fills nothing else in).
        self.machine.take(transition)
        if self._publish is not None:
            self._publish(TransitionEvent(start_state=_state(transition.start), goal_state=_state(transition.goal)))


def _state(state_id: int) -> State:
    return State(id=state_id, label=STATES[state_id])


def _description(transition: TransitionSpec) -> TransitionDescription:
    item = TransitionDescription()
    item.transition.id, item.transition.label = transition.id, transition.label
    item.start_state, item.goal_state = _state(transition.start), _state(transition.goal)
    return item


class LifecycleNodeMixin(ManagedEntity):
    """The lifecycle part of LifecycleNode, for a class that is also a :class:`Node`."""

    def __init__(self, *, enable_communication_interface: bool = True, callback_group: CallbackGroup | None = None):
        if not isinstance(self, Node):
            raise RuntimeError("LifecycleNodeMixin uses Node fields so Node needs to be in the inheritance tree.")
        if not isinstance(enable_communication_interface, bool):
            raise TypeError(f"enable_communication_interface must be a bool, got {enable_communication_interface!r}")
        self._managed_entities: set[ManagedEntity] = set()
        publish = None
        if enable_communication_interface:
            publish = self.create_publisher(TransitionEvent, "~/transition_event", 10).publish
        self._state_machine = _StateMachine(publish)
        if enable_communication_interface:
            self._serve(callback_group or self.default_callback_group)

    def _serve(self, group: CallbackGroup) -> None:
        assert isinstance(self, Node)
        machine = self._state_machine
        for name, srv_type, handler in (
            ("change_state", ChangeState, self._on_change_state),
            ("get_state", GetState, self._on_get_state),
            ("get_available_states", GetAvailableStates, self._on_get_states),
            ("get_available_transitions", GetAvailableTransitions, self._on_get_available),
            ("get_transition_graph", GetAvailableTransitions, self._on_get_graph),
        ):
            service = self.create_service(srv_type, f"~/{name}", handler, callback_group=group)
            setattr(machine, f"service_{name}", service)
            setattr(self, f"_service_{name}", service)

    def trigger_configure(self) -> TransitionCallbackReturn:
        """configure: unconfigured -> inactive (see the module's docstring)."""
        return self._change_state(1)

    def trigger_cleanup(self) -> TransitionCallbackReturn:
        """cleanup: inactive -> unconfigured."""
        return self._change_state(2)

    def trigger_activate(self) -> TransitionCallbackReturn:
        """activate: inactive -> active."""
        return self._change_state(3)

    def trigger_deactivate(self) -> TransitionCallbackReturn:
        """deactivate: active -> inactive."""
        return self._change_state(4)

    def trigger_shutdown(self) -> TransitionCallbackReturn:
        """shutdown from unconfigured, inactive or active -> finalized; LifecycleError from elsewhere."""
        state_id = self._state_machine.current_state[0]
        if state_id not in _SHUTDOWN_FROM:
            raise LifecycleError(f"Shutdown transition not possible from state {STATES[state_id]}")
        return self._change_state(_SHUTDOWN_FROM[state_id])

    def add_managed_entity(self, entity: ManagedEntity) -> None:
        """Have ``entity``'s ``on_*`` callbacks called by the default ones of this node."""
        if not isinstance(entity, ManagedEntity):
            raise TypeError("Expected a rclpy.lifecycle.ManagedEntity instance.")
        self._managed_entities.add(entity)

    def _entities_do(self, name: str, state: LifecycleState) -> TransitionCallbackReturn:
        # The default callbacks: each managed entity's, until one does not succeed.
        for entity in self._managed_entities:
            result = getattr(entity, name)(state)
            if not isinstance(result, TransitionCallbackReturn):
                raise TypeError(f"{name}() of {entity!r} returned {result!r}, not a TransitionCallbackReturn")
            if result != TransitionCallbackReturn.SUCCESS:
                return result
        return TransitionCallbackReturn.SUCCESS

    def on_configure(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Configure the node; by default its managed entities."""
        return self._entities_do("on_configure", state)

    def on_cleanup(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Clean the node up; by default its managed entities."""
        return self._entities_do("on_cleanup", state)

    def on_shutdown(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Shut the node down; by default its managed entities."""
        return self._entities_do("on_shutdown", state)

    def on_activate(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Activate the node; by default its managed entities (lifecycle publishers start delivering)."""
        return self._entities_do("on_activate", state)

    def on_deactivate(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Deactivate the node; by default its managed entities."""
        return self._entities_do("on_deactivate", state)

    def on_error(self, state: LifecycleState) -> TransitionCallbackReturn:
        """Handle an error of a transition; by default its managed entities'."""
        return self._entities_do("on_error", state)

    def create_lifecycle_publisher(
        self, msg_type: type[Any], topic: str, qos_profile: Any, *, publisher_class: None = None, **kwargs: Any
    ) -> LifecyclePublisher:
        """A publisher that delivers only while this node is active."""
        assert isinstance(self, Node)
        if publisher_class:
            raise TypeError("create_publisher() got an unexpected keyword argument 'publisher_class'")
        publisher = self.create_publisher(msg_type, topic, qos_profile, publisher_class=LifecyclePublisher, **kwargs)
        assert isinstance(publisher, LifecyclePublisher)
        self._managed_entities.add(publisher)
        return publisher

    def destroy_lifecycle_publisher(self, publisher: LifecyclePublisher) -> bool:
        """Forget ``publisher`` and destroy it."""
        assert isinstance(self, Node)
        self._managed_entities.discard(publisher)
        return self.destroy_publisher(publisher)

    def _run_callback(self, state_id: int, started: LifecycleState) -> TransitionCallbackReturn:
        name = _CALLBACKS.get(state_id)
        if name is None:
            return TransitionCallbackReturn.SUCCESS
        try:
            result = getattr(self, name)(started)
        except Exception:  # as rclpy: a callback that raises is an error of the transition
            return TransitionCallbackReturn.ERROR
        return TransitionCallbackReturn(result)

    def _change_state(self, transition_id: int) -> TransitionCallbackReturn:
        # A primary transition, its callback, the result's transition, and on ERROR on_error's.
        assert isinstance(self, Node)
        machine = self._state_machine
        started = LifecycleState(label=machine.current_state[1], state_id=machine.current_state[0])
        try:
            machine.take(machine.machine.find(id=transition_id))
        except LifecycleError:
            self.get_logger().error(
                f"Unable to start transition {transition_id} from current state {machine.current_state}"
            )
            return TransitionCallbackReturn.ERROR
        result = self._run_callback(machine.current_state[0], started)
        machine.take(machine.machine.find(label=result.to_label()))
        if result == TransitionCallbackReturn.ERROR:
            on_error = self._run_callback(machine.current_state[0], started)
            machine.take(machine.machine.find(label=on_error.to_label()))
        return result

    def _on_change_state(self, request: Any, response: Any) -> Any:
        transition_id = request.transition.id
        if request.transition.label:
            try:
                transition_id = self._state_machine.machine.find(label=request.transition.label).id
            except LifecycleError:
                response.success = False
                return response
        response.success = self._change_state(transition_id) == TransitionCallbackReturn.SUCCESS
        return response

    def _on_get_state(self, request: Any, response: Any) -> Any:
        response.current_state = _state(self._state_machine.current_state[0])
        return response

    def _on_get_states(self, request: Any, response: Any) -> Any:
        response.available_states = [State(id=i, label=label) for i, label in self._state_machine.available_states]
        return response

    def _on_get_available(self, request: Any, response: Any) -> Any:
        response.available_transitions = [_description(t) for t in self._state_machine.available_transitions]
        return response

    def _on_get_graph(self, request: Any, response: Any) -> Any:
        response.available_transitions = [_description(t) for t in self._state_machine.transition_graph]
        return response


class LifecycleNode(LifecycleNodeMixin, Node):
    """A managed node: a Node with the lifecycle state machine, its services and lifecycle publishers."""

    def __init__(
        self,
        node_name: str,
        *,
        enable_communication_interface: bool = True,
        callback_group: CallbackGroup | None = None,
        **kwargs: Any,
    ) -> None:
        Node.__init__(self, node_name, **kwargs)
        LifecycleNodeMixin.__init__(
            self, enable_communication_interface=enable_communication_interface, callback_group=callback_group
        )
