"""Reading a launch file of any front end into a description.

A Python launch file is executed (it is a program: that is the front end) and
its ``generate_launch_description()`` called; an XML or YAML file is read by
:mod:`actors.compat.launch.frontend`.  Any error while reading is a
LaunchFileError naming the launch file and line.
"""

from __future__ import annotations

import os
import traceback
from typing import Any

from actors.compat.launch.entities import LaunchDescription
from actors.compat.launch.frontend import load_xml, load_yaml
from actors.compat.launch.substitutions import reading
from actors.errors import ActorsError, LaunchFileError

__all__ = ["load_launch_file"]


def load_launch_file(path: str, where: str | None = None) -> LaunchDescription:
    """The description in the launch file ``path`` (front end by its extension)."""
    if not os.path.isfile(path):
        raise LaunchFileError(f"{where + ': ' if where else ''}no such launch file: {path}")
    name = os.path.basename(path)
    if name.endswith(".py"):
        return _load_python(path)
    if name.endswith((".xml", ".launch")):
        return load_xml(path)
    if name.endswith((".yaml", ".yml")):
        return load_yaml(path)
    raise LaunchFileError(f"{path}: not a launch file: expected .launch.py, .launch.xml or .launch.yaml")


def _load_python(path: str) -> LaunchDescription:
    try:
        with open(path, "rb") as file:
            code = compile(file.read(), path, "exec")
    except SyntaxError as exc:
        raise LaunchFileError(f"{path}:{exc.lineno}: SyntaxError: {exc.msg}") from None
    namespace: dict[str, Any] = {"__name__": "__launch_file__", "__file__": path}
    try:
        with reading(path):
            exec(code, namespace)
            generate = namespace.get("generate_launch_description")
            if not callable(generate):
                raise LaunchFileError(f"{path}: no generate_launch_description() function")
            description = generate()
    except LaunchFileError:
        raise
    except Exception as exc:
        raise LaunchFileError(f"{_line_in(exc, path)}: {_one_line(exc)}") from None
    if not isinstance(description, LaunchDescription):
        raise LaunchFileError(
            f"{path}: generate_launch_description() returned {type(description).__name__}, not a LaunchDescription"
        )
    return description


def _line_in(exc: BaseException, path: str) -> str:
    """``path:line`` of the deepest frame of ``exc`` in the launch file."""
    line = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if os.path.abspath(frame.f_code.co_filename) == os.path.abspath(path):
            line = lineno
    return f"{path}:{line}" if line is not None else path


def _one_line(exc: BaseException) -> str:
    if isinstance(exc, ActorsError):
        return str(exc)
    return f"{type(exc).__name__}: {exc}"
