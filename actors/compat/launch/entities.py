"""What a launch description is made of: entities, actions, substitutions, conditions, the context.

A launch file describes; :mod:`actors.compat.launch.service` does.  Visiting an
entity in a :class:`LaunchContext` returns the entities it stands for (a group
its actions, an include the included description), depth first, as ROS's
launch visits them; actions that start something (a node, a process, a timer)
hand it to the context's ``service``.  Each action remembers the file and line
that made it (:attr:`LaunchDescriptionEntity.where`), so an error it meets later
names that place.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from actors.errors import LaunchFileError

__all__ = [
    "LaunchDescriptionEntity",
    "Action",
    "Substitution",
    "TextSubstitution",
    "Condition",
    "LaunchDescription",
    "LaunchContext",
    "Event",
    "EventHandler",
    "SomeSubstitutionsType",
    "normalize_to_list_of_substitutions",
    "perform_substitutions",
    "caller_location",
]

_HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # actors/compat


def caller_location() -> str | None:
    """``file:line`` of the nearest frame outside actors' launch and launch_ros: the launch file's line."""
    frame = sys._getframe(1)
    while frame is not None:
        name = frame.f_code.co_filename
        if not os.path.abspath(name).startswith(_HERE) and not name.startswith("<frozen"):
            return f"{name}:{frame.f_lineno}"
        frame = frame.f_back  # type: ignore[assignment]  # None ends the loop
    return None


class LaunchDescriptionEntity:
    """Anything a launch description holds."""

    where: str | None = None  # file:line of the launch file that made it

    def visit(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        """What this entity stands for, to be visited next (None: nothing)."""
        return None

    def describe(self) -> str:
        """A short name for messages."""
        return type(self).__name__

    def declared_arguments(self) -> list[Any]:
        """The launch arguments it declares, its own sub-entities' included (not those of included files)."""
        return []


class Action(LaunchDescriptionEntity):
    """An entity that does something when visited, if its ``condition`` holds."""

    def __init__(self, *, condition: Condition | None = None) -> None:
        self.condition = condition
        self.where = caller_location()

    @property
    def parent(self) -> None:
        """ROS's actions know their parent; nothing here needs it."""
        return None

    completes_later = False
    """Whether it is done only later (a process when it exits, a timer when it fires), not once executed."""

    def visit(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        if self.condition is not None and not self.condition.evaluate(context):
            return None
        result = self.execute(context)
        if not self.completes_later and context.service is not None:
            context.service.completed(self)
        return result

    def execute(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        """What the action does; its result is visited next."""
        return None


class Substitution:
    """A piece of text known only when the launch runs."""

    def perform(self, context: LaunchContext) -> str:
        """The text, in ``context``; LaunchFileError when it cannot be had."""
        raise NotImplementedError

    def describe(self) -> str:
        """A short form for messages."""
        return type(self).__name__

    def __add__(self, other: Any) -> list[Any]:
        return [self, other]


class TextSubstitution(Substitution):
    """Text as it is."""

    def __init__(self, *, text: str) -> None:
        self.text = str(text)

    def perform(self, context: LaunchContext) -> str:
        return self.text

    def describe(self) -> str:
        return repr(self.text)


SomeSubstitutionsType = str | Substitution | Iterable[str | Substitution]


def normalize_to_list_of_substitutions(value: Any) -> list[Substitution]:
    """A string, a substitution, or a sequence of both, as a list of substitutions."""
    if isinstance(value, str | int | float | bool) and not isinstance(value, Substitution):
        return [TextSubstitution(text=str(value))]
    if isinstance(value, Substitution):
        return [value]
    if isinstance(value, Iterable):
        out: list[Substitution] = []
        for item in value:
            out += normalize_to_list_of_substitutions(item)
        return out
    raise LaunchFileError(f"expected text or a substitution, got {value!r}")


def perform_substitutions(context: LaunchContext, value: Any) -> str:
    """The text of a string, substitution or sequence of them."""
    return "".join(sub.perform(context) for sub in normalize_to_list_of_substitutions(value))


class Condition:
    """Whether an action runs: ``predicate(context)``."""

    def __init__(self, *, predicate: Callable[[LaunchContext], bool] | None = None) -> None:
        self._predicate = predicate

    def evaluate(self, context: LaunchContext) -> bool:
        """True when the action should run."""
        return bool(self._predicate(context)) if self._predicate else True


class Event:
    """Something that happened during a launch (a process started, exited; a shutdown asked)."""

    name = "launch.event"


class EventHandler:
    """Entities to visit when a matching event happens."""

    def __init__(self, *, matcher: Callable[[Event], bool], entities: Any = None) -> None:
        self.matcher = matcher
        self.entities = entities
        self.where = caller_location()

    def matches(self, event: Event) -> bool:
        """Whether ``event`` is one for this handler."""
        return self.matcher(event)

    def handle(self, event: Event, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        """The entities to visit for ``event``."""
        entities = self.entities
        if callable(entities):
            entities = entities(event, context)
        if entities is None:
            return None
        if isinstance(entities, LaunchDescriptionEntity):
            return [entities]
        return list(entities)


class LaunchDescription(LaunchDescriptionEntity):
    """The entities of a launch file, in order."""

    def __init__(
        self, initial_entities: Iterable[LaunchDescriptionEntity] | None = None, *, deprecated_reason: str | None = None
    ) -> None:
        self.entities = list(initial_entities or [])
        self.where = caller_location()

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        """Append an entity."""
        self.entities.append(entity)

    def add_action(self, action: Action) -> None:
        """Append an action."""
        self.entities.append(action)

    def visit(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity]:
        return self.entities

    def get_launch_arguments(self) -> list[Any]:
        """The DeclareLaunchArgument actions it holds, groups and all, includes not followed."""
        return self.declared_arguments()

    def declared_arguments(self) -> list[Any]:
        return [found for entity in self.entities for found in entity.declared_arguments()]


class LaunchContext:
    """The state a launch is visited in: launch configurations (scoped), the file being read, the service."""

    def __init__(self, service: Any = None, argv: Sequence[str] = ()) -> None:
        self.launch_configurations: dict[str, Any] = {}
        self._stack: list[dict[str, Any]] = []
        self.locals: dict[str, Any] = {}
        self.service = service
        self.argv = list(argv)
        self.environment = os.environ

    def push_configurations(self) -> None:
        """Open a scope: what is set inside is forgotten by :meth:`pop_configurations`."""
        self._stack.append(dict(self.launch_configurations))

    def pop_configurations(self) -> None:
        """Close the innermost scope."""
        self.launch_configurations = self._stack.pop()

    def extend_locals(self, values: dict[str, Any]) -> None:
        """Set context locals (the launch file being read)."""
        self.locals.update(values)

    def get_locals_as_dict(self) -> dict[str, Any]:
        """The context's locals."""
        return dict(self.locals)

    def emit_event_sync(self, event: Event) -> None:
        """Emit ``event`` (its handlers run once the current visit is done)."""
        self.service.emit(event)

    async def emit_event(self, event: Event) -> None:
        """Emit ``event``."""
        self.service.emit(event)
