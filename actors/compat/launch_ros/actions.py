"""``launch_ros.actions``: a package's executable as a node, and the namespace, parameters and remappings
a group gives the nodes in it."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

from actors.compat.launch.entities import (
    Action,
    LaunchContext,
    Substitution,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from actors.errors import LaunchFileError, PackageError

__all__ = [
    "Node",
    "PushRosNamespace",
    "PushROSNamespace",
    "SetParameter",
    "SetRemap",
    "NAMESPACE",
    "PARAMETERS",
    "REMAPS",
]

# Kept among the launch configurations, so that a scoped group forgets them with the rest.
NAMESPACE = "__actors_ros_namespace"
PARAMETERS = "__actors_ros_parameters"
REMAPS = "__actors_ros_remaps"


def _join_namespace(outer: str, inner: str) -> str:
    if inner.startswith("/"):
        return inner
    parts = [part for part in (outer.strip("/"), inner.strip("/")) if part]
    return "/" + "/".join(parts) if parts else ""


class PushRosNamespace(Action):
    """Nodes after it (in its group) go in this namespace, appended to the one pushed before."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = normalize_to_list_of_substitutions(namespace)

    def execute(self, context: LaunchContext) -> None:
        pushed = context.launch_configurations.get(NAMESPACE, "")
        context.launch_configurations[NAMESPACE] = _join_namespace(
            pushed, perform_substitutions(context, self.namespace)
        )


class SetParameter(Action):
    """A parameter every node after it (in its group) gets."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = value

    def execute(self, context: LaunchContext) -> None:
        value = _value(context, self.value)
        pushed = context.launch_configurations.get(PARAMETERS, ())
        context.launch_configurations[PARAMETERS] = (*pushed, (perform_substitutions(context, self.name), value))


class SetRemap(Action):
    """A remapping every node after it (in its group) gets."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src = normalize_to_list_of_substitutions(src)
        self.dst = normalize_to_list_of_substitutions(dst)

    def execute(self, context: LaunchContext) -> None:
        pushed = context.launch_configurations.get(REMAPS, ())
        rule = (perform_substitutions(context, self.src), perform_substitutions(context, self.dst))
        context.launch_configurations[REMAPS] = (*pushed, rule)


def _value(context: LaunchContext, value: Any) -> Any:
    """A parameter's value: substitutions become text read as YAML (``'2'`` is 2), as launch_ros reads them."""
    import yaml

    if isinstance(value, Substitution) or (
        isinstance(value, list | tuple) and value and any(isinstance(v, Substitution) for v in value)
    ):
        text = perform_substitutions(context, value)
        try:
            return yaml.safe_load(text) if text else text
        except yaml.YAMLError:
            return text
    if isinstance(value, list | tuple):
        return [_value(context, v) for v in value]
    if isinstance(value, dict):
        return {k: _value(context, v) for k, v in value.items()}
    return value


def _flatten(prefix: str, values: dict[str, Any], out: dict[str, Any]) -> None:
    for key, value in values.items():
        name = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, dict):
            _flatten(name, value, out)
        else:
            out[name] = value


class Node(Action):
    """A package's executable, run as a node of the launch (in this runtime): rclpy's or a native one."""

    completes_later = True

    def __init__(
        self,
        *,
        executable: Any,
        package: Any = None,
        name: Any = None,
        namespace: Any = None,
        exec_name: Any = None,
        parameters: Iterable[Any] | None = None,
        remappings: Iterable[tuple[Any, Any]] | None = None,
        ros_arguments: Iterable[Any] | None = None,
        arguments: Iterable[Any] | None = None,
        output: Any = "log",
        respawn: Any = False,
        respawn_delay: float | None = None,
        **kwargs: Any,
    ) -> None:
        condition = kwargs.pop("condition", None)
        for ignored in (
            "emulate_tty",
            "additional_env",
            "env",
            "cwd",
            "prefix",
            "sigterm_timeout",
            "sigkill_timeout",
            "on_exit",
            "node_name",
            "node_namespace",
        ):
            kwargs.pop(ignored, None)
        if kwargs:
            raise LaunchFileError(f"Node() got unexpected arguments: {', '.join(sorted(kwargs))}")
        super().__init__(condition=condition)
        if package is None:
            raise LaunchFileError(f"{self.where}: Node needs a package (actors runs packages' executables)")
        self.package = normalize_to_list_of_substitutions(package)
        self.executable = normalize_to_list_of_substitutions(executable)
        self.node_name = None if name is None else normalize_to_list_of_substitutions(name)
        self.node_namespace = None if namespace is None else normalize_to_list_of_substitutions(namespace)
        self.exec_name = None if exec_name is None else normalize_to_list_of_substitutions(exec_name)
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.ros_arguments = list(ros_arguments or [])
        self.arguments = list(arguments or [])
        self.output = output
        self.respawn = respawn
        self.respawn_delay = respawn_delay

    def execute(self, context: LaunchContext) -> None:
        package = perform_substitutions(context, self.package)
        executable = perform_substitutions(context, self.executable)
        try:
            found, where = context.service.executable(package, executable)
        except PackageError as exc:
            raise LaunchFileError(f"{self.where}: {exc}") from None
        argv = [perform_substitutions(context, word) for word in self.arguments]
        argv.append("--ros-args")
        name = perform_substitutions(context, self.node_name) if self.node_name else None
        if name:
            argv += ["-r", f"__node:={name}"]
        pushed = context.launch_configurations.get(NAMESPACE, "")
        inner = perform_substitutions(context, self.node_namespace) if self.node_namespace else ""
        namespace = _join_namespace(pushed, inner)
        if namespace:
            argv += ["-r", f"__ns:={namespace}"]
        rules: list[dict[str, Any] | str] = []
        pushed_parameters = dict(context.launch_configurations.get(PARAMETERS, ()))
        if pushed_parameters:
            rules.append(pushed_parameters)
        for entry in self.parameters:
            if isinstance(entry, dict):
                flat: dict[str, Any] = {}
                _flatten("", {perform_substitutions(context, k): _value(context, v) for k, v in entry.items()}, flat)
                rules.append(flat)
            else:
                path = str(entry) if isinstance(entry, Path) else perform_substitutions(context, entry)
                rules.append(path)
        for rule in rules:
            if isinstance(rule, str):
                argv += ["--params-file", rule]
            else:
                argv += ["--params-file", context.service.params_file(rule)]
        for source, target in (*context.launch_configurations.get(REMAPS, ()), *self.remappings):
            argv += ["-r", f"{perform_substitutions(context, source)}:={perform_substitutions(context, target)}"]
        argv += [perform_substitutions(context, word) for word in self.ros_arguments]
        respawn = self.respawn
        if not isinstance(respawn, bool):
            respawn = perform_substitutions(context, respawn).strip().lower() in ("true", "1")
        label = perform_substitutions(context, self.exec_name) if self.exec_name else executable
        context.service.start_node(self, found, where, argv, label, respawn, float(self.respawn_delay or 0.0))


PushROSNamespace = PushRosNamespace
"""The name launch_ros gives it since Jazzy (the older one stays)."""
