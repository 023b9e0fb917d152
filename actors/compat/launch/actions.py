"""``launch.actions``: arguments, includes, groups, timers, processes, events and logging."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from actors.compat.launch.entities import (
    Action,
    Condition,
    Event,
    EventHandler,
    LaunchContext,
    LaunchDescription,
    LaunchDescriptionEntity,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from actors.errors import LaunchFileError

__all__ = [
    "DeclareLaunchArgument",
    "SetLaunchConfiguration",
    "IncludeLaunchDescription",
    "GroupAction",
    "TimerAction",
    "LogInfo",
    "ExecuteProcess",
    "RegisterEventHandler",
    "EmitEvent",
    "OpaqueFunction",
    "Shutdown",
    "SetEnvironmentVariable",
]


class DeclareLaunchArgument(Action):
    """A launch argument: its value is what the command line or an include gives, else ``default_value``."""

    def __init__(
        self,
        name: str,
        *,
        default_value: Any = None,
        description: str | None = None,
        choices: Sequence[str] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)
        self.description = description or "no description given"
        self.choices = list(choices) if choices is not None else None

    def execute(self, context: LaunchContext) -> None:
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                raise LaunchFileError(
                    f"{self.where}: launch argument {self.name!r} is required and not given "
                    f"(give it as {self.name}:=VALUE; description: {self.description})"
                )
            context.launch_configurations[self.name] = perform_substitutions(context, self.default_value)
        value = context.launch_configurations[self.name]
        if self.choices is not None and value not in self.choices:
            raise LaunchFileError(
                f"{self.where}: launch argument {self.name!r} is {value!r}, not one of {', '.join(self.choices)}"
            )

    def declared_arguments(self) -> list[Any]:
        return [self]

    def default_text(self) -> str | None:
        """The default as text, when it is plain text (for ``--show-args``)."""
        if self.default_value is None:
            return None
        return "".join(s.describe() for s in self.default_value)


class SetLaunchConfiguration(Action):
    """Set a launch configuration (in the current scope)."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform_substitutions(context, self.name)] = perform_substitutions(
            context, self.value
        )


class SetEnvironmentVariable(Action):
    """Set an environment variable for what starts after."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        os.environ[perform_substitutions(context, self.name)] = perform_substitutions(context, self.value)


class IncludeLaunchDescription(Action):
    """Another launch file, its arguments set as launch configurations first (not scoped: use a group)."""

    def __init__(
        self, launch_description_source: Any, *, launch_arguments: Iterable[Any] | None = None, **kwargs: Any
    ) -> None:
        super().__init__(**kwargs)
        from actors.compat.launch.launch_description_sources import AnyLaunchDescriptionSource

        if isinstance(launch_description_source, LaunchDescription):
            self.source: Any = _Given(launch_description_source)
        elif hasattr(launch_description_source, "get_launch_description"):
            self.source = launch_description_source
        else:
            self.source = AnyLaunchDescriptionSource(launch_description_source)
        self.launch_arguments = [
            (normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v))
            for k, v in (launch_arguments or [])
        ]

    def execute(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity]:
        values = [
            (perform_substitutions(context, name), perform_substitutions(context, value))
            for name, value in self.launch_arguments
        ]
        description = self.source.get_launch_description(context, self.where)
        given = {name for name, _ in values} | set(context.launch_configurations)
        for argument in description.get_launch_arguments():
            if argument.default_value is None and argument.condition is None and argument.name not in given:
                raise LaunchFileError(
                    f"{self.where}: the included {self.source.location(context)} needs launch argument "
                    f"{argument.name!r} (description: {argument.description}), given: [{', '.join(sorted(given))}]"
                )
        context.launch_configurations.update(values)
        return [description]


class _Given:
    """An include of a LaunchDescription object rather than a file."""

    def __init__(self, description: LaunchDescription) -> None:
        self.description = description

    def get_launch_description(self, context: LaunchContext, where: str | None) -> LaunchDescription:
        return self.description

    def location(self, context: LaunchContext) -> str:
        return "launch description"


class _PopScope(Action):
    def __init__(self) -> None:
        super().__init__()

    def execute(self, context: LaunchContext) -> None:
        context.pop_configurations()


class GroupAction(Action):
    """Actions together, under one condition; ``scoped``: what they set is forgotten after them."""

    def __init__(
        self,
        actions: Iterable[LaunchDescriptionEntity],
        *,
        scoped: bool = True,
        forwarding: bool = True,
        launch_configurations: dict[Any, Any] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped = scoped
        self.forwarding = forwarding
        self.configurations = [
            (normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v))
            for k, v in (launch_configurations or {}).items()
        ]

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The actions of the group."""
        return self.actions

    def declared_arguments(self) -> list[Any]:
        return [found for action in self.actions for found in action.declared_arguments()]

    def execute(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity]:
        values = [
            (perform_substitutions(context, k), perform_substitutions(context, v)) for k, v in self.configurations
        ]
        if not self.scoped:
            context.launch_configurations.update(values)
            return self.actions
        context.push_configurations()
        if not self.forwarding:
            kept = {k: v for k, v in context.launch_configurations.items() if k.startswith("__actors_")}
            context.launch_configurations.clear()
            context.launch_configurations.update(kept)
        context.launch_configurations.update(values)
        return [*self.actions, _PopScope()]


class TimerAction(Action):
    """Actions visited ``period`` seconds (of the runtime's clock) from now."""

    completes_later = True

    def __init__(
        self, *, period: Any, actions: Iterable[LaunchDescriptionEntity], cancel_on_shutdown: bool = True, **kwargs: Any
    ) -> None:
        super().__init__(**kwargs)
        self.period = normalize_to_list_of_substitutions(period)
        self.actions = list(actions)

    def execute(self, context: LaunchContext) -> None:
        text = perform_substitutions(context, self.period)
        try:
            seconds = float(text)
        except ValueError:
            raise LaunchFileError(f"{self.where}: TimerAction period {text!r} is not a number of seconds") from None
        context.service.after(seconds, self.actions, context, self)


class LogInfo(Action):
    """Log a message, as ``[INFO] [launch.user]: msg``."""

    def __init__(self, *, msg: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.msg = normalize_to_list_of_substitutions(msg)

    def execute(self, context: LaunchContext) -> None:
        context.service.log("launch.user", perform_substitutions(context, self.msg))


class ExecuteProcess(Action):
    """A real subprocess: ``cmd`` (words, each text or substitutions), with ``cwd``, ``env``, ``shell``."""

    completes_later = True

    def __init__(
        self,
        *,
        cmd: Iterable[Any],
        name: Any = None,
        cwd: Any = None,
        env: dict[Any, Any] | None = None,
        additional_env: dict[Any, Any] | None = None,
        shell: bool = False,
        output: Any = "log",
        respawn: Any = False,
        respawn_delay: float | None = None,
        sigterm_timeout: Any = 5,
        sigkill_timeout: Any = 5,
        emulate_tty: bool = False,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.cmd = [normalize_to_list_of_substitutions(word) for word in cmd]
        self.name = None if name is None else normalize_to_list_of_substitutions(name)
        self.cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.env = env
        self.additional_env = additional_env or {}
        self.shell = shell
        self.output = output
        self.respawn = respawn
        self.respawn_delay = respawn_delay

    def execute(self, context: LaunchContext) -> None:
        words = [perform_substitutions(context, word) for word in self.cmd]
        environment = dict(os.environ if self.env is None else {})
        for mapping in (self.env or {}, self.additional_env):
            for key, value in mapping.items():
                environment[perform_substitutions(context, key)] = perform_substitutions(context, value)
        cwd = None if self.cwd is None else perform_substitutions(context, self.cwd)
        name = (
            perform_substitutions(context, self.name)
            if self.name
            else os.path.basename(words[0])
            if words
            else "process"
        )
        context.service.start_process(self, name, words, environment, cwd, self.shell, str(self.output))


class RegisterEventHandler(Action):
    """Add an event handler for what happens after."""

    def __init__(self, event_handler: EventHandler, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        context.service.handlers.append(self.event_handler)


class EmitEvent(Action):
    """Emit an event (``Shutdown()`` ends the launch)."""

    def __init__(self, *, event: Event, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        context.service.emit(self.event)


class Shutdown(EmitEvent):
    """End the launch."""

    def __init__(self, *, reason: str = "reason not given", **kwargs: Any) -> None:
        from actors.compat.launch.events import Shutdown as ShutdownEvent

        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)


class OpaqueFunction(Action):
    """``function(context, *args, **kwargs)``, which may return entities to visit."""

    def __init__(
        self,
        *,
        function: Callable[..., Any],
        args: Sequence[Any] | None = None,
        kwargs: dict[str, Any] | None = None,
        condition: Condition | None = None,
    ) -> None:
        super().__init__(condition=condition)
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})

    def execute(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        result = self.function(context, *self.args, **self.kwargs)
        return list(result) if result else None
