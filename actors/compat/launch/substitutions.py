"""``launch.substitutions``: text known when the launch runs (arguments, paths, expressions, environment)."""

from __future__ import annotations

import math
import os
import shutil
from collections.abc import Iterable
from typing import Any

from actors.compat.launch.entities import (
    LaunchContext,
    Substitution,
    TextSubstitution,
    caller_location,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from actors.errors import LaunchFileError

__all__ = [
    "TextSubstitution",
    "LaunchConfiguration",
    "PathJoinSubstitution",
    "PythonExpression",
    "EnvironmentVariable",
    "FindExecutable",
    "LocalSubstitution",
    "ThisLaunchFileDir",
    "ThisLaunchFile",
    "NotSubstitution",
    "AndSubstitution",
    "OrSubstitution",
    "reading",
]

# The launch file being read: ThisLaunchFile(Dir) made while it is read refer to it.
_reading: list[str] = []


class reading:
    """``with reading(path):`` while a launch file is read (its ThisLaunchFileDir is that file's folder)."""

    def __init__(self, path: str) -> None:
        self.path = os.path.abspath(path)

    def __enter__(self) -> None:
        _reading.append(self.path)

    def __exit__(self, *exc: object) -> None:
        _reading.pop()


class LaunchConfiguration(Substitution):
    """The value of a launch argument or configuration; ``default`` when it has none."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        self.default = None if default is None else normalize_to_list_of_substitutions(default)
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.variable_name)
        if name in context.launch_configurations:
            return str(context.launch_configurations[name])
        if self.default is not None:
            return perform_substitutions(context, self.default)
        raise LaunchFileError(f"{self.where or 'launch'}: launch configuration {name!r} does not exist")

    def describe(self) -> str:
        return f"LaunchConfiguration({''.join(s.describe() for s in self.variable_name)})"


class PathJoinSubstitution(Substitution):
    """Parts joined with the path separator."""

    def __init__(self, substitutions: Iterable[Any]) -> None:
        self.substitutions = [normalize_to_list_of_substitutions(part) for part in substitutions]

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform_substitutions(context, part) for part in self.substitutions))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([*self.substitutions, other])


class PythonExpression(Substitution):
    """A Python expression, evaluated with the ``math`` module's names at hand; its result as text."""

    def __init__(self, expression: Any, python_modules: Any = ("math",)) -> None:
        self.expression = normalize_to_list_of_substitutions(expression)
        self.modules = [normalize_to_list_of_substitutions(m) for m in python_modules]
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        text = perform_substitutions(context, self.expression)
        names: dict[str, Any] = {}
        for module in self.modules:
            name = perform_substitutions(context, module)
            imported = __import__(name)
            names[name] = imported
            if name == "math":
                names.update({k: v for k, v in vars(math).items() if not k.startswith("_")})
        try:
            return str(eval(text, names))  # what PythonExpression is for: the launch file's own expression
        except Exception as exc:
            raise LaunchFileError(
                f"{self.where or 'launch'}: PythonExpression {text!r}: {type(exc).__name__}: {exc}"
            ) from None


class EnvironmentVariable(Substitution):
    """An environment variable's value; ``default_value`` when unset (an error when there is none)."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        if name in context.environment:
            return context.environment[name]
        if self.default_value is not None:
            return perform_substitutions(context, self.default_value)
        raise LaunchFileError(f"{self.where or 'launch'}: environment variable {name!r} does not exist")


ROS2 = "ros2"
"""The command the launcher runs as actors' own when no ``ros2`` is on the PATH (see the service)."""


class FindExecutable(Substitution):
    """The path of an executable on the PATH; a missing ``ros2`` stands as the bare word ``ros2``."""

    def __init__(self, *, name: Any) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        found = shutil.which(name, path=context.environment.get("PATH"))
        if found is not None:
            return found
        if name == ROS2:  # the launcher translates ros2 commands onto actors' command line
            return name
        raise LaunchFileError(f"{self.where or 'launch'}: executable {name!r} not found on the PATH")


class LocalSubstitution(Substitution):
    """A context local by expression (``event.reason`` in an event handler's entities)."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        self.expression = expression
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        try:
            # The launch file's own expression over the context's locals, as ROS's launch evaluates it.
            return str(eval(self.expression, {}, context.get_locals_as_dict()))
        except Exception as exc:
            raise LaunchFileError(
                f"{self.where or 'launch'}: LocalSubstitution {self.expression!r}: {type(exc).__name__}: {exc}"
            ) from None


class ThisLaunchFile(Substitution):
    """The path of the launch file that made this substitution."""

    def __init__(self) -> None:
        self.path = _reading[-1] if _reading else None

    def perform(self, context: LaunchContext) -> str:
        if self.path is None:
            raise LaunchFileError("ThisLaunchFile used outside a launch file")
        return self.path


class ThisLaunchFileDir(ThisLaunchFile):
    """The folder of the launch file that made this substitution."""

    def perform(self, context: LaunchContext) -> str:
        return os.path.dirname(super().perform(context))


def _truth(context: LaunchContext, value: list[Substitution], where: str | None) -> bool:
    text = perform_substitutions(context, value).strip().lower()
    if text in ("true", "1"):
        return True
    if text in ("false", "0"):
        return False
    raise LaunchFileError(f"{where or 'launch'}: {text!r} is not a condition: expected true, false, 1 or 0")


class NotSubstitution(Substitution):
    """``true`` when its value is false, and the reverse."""

    def __init__(self, value: Any) -> None:
        self.value = normalize_to_list_of_substitutions(value)
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        return str(not _truth(context, self.value, self.where)).lower()


class AndSubstitution(Substitution):
    """``true`` when both values are."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize_to_list_of_substitutions(left), normalize_to_list_of_substitutions(right)
        self.where = caller_location()

    def perform(self, context: LaunchContext) -> str:
        return str(_truth(context, self.left, self.where) and _truth(context, self.right, self.where)).lower()


class OrSubstitution(AndSubstitution):
    """``true`` when either value is."""

    def perform(self, context: LaunchContext) -> str:
        return str(_truth(context, self.left, self.where) or _truth(context, self.right, self.where)).lower()
