"""An ament_python package's ``setup.py`` and ``setup.cfg``, read without running them.

``ros2 run`` finds a package's executables among its installed console
scripts, which setuptools made from ``entry_points`` when colcon built it, and
its shared files where ``data_files`` put them.  Nothing is built here, so both
are read from the sources:

- ``setup.py`` is parsed with :mod:`ast`, never executed: the arguments of its
  ``setup(...)`` call are evaluated from what a package's setup file is made of
  (literals, module-level names assigned once, ``+`` on strings and lists,
  f-strings, ``os.path.join``, ``glob``/``glob.glob`` relative to the package,
  ``str``, ``pathlib.Path`` and ``/``).  Anything else (a function of its own,
  a loop) is a :class:`~actors.errors.PackageError` naming file, line and
  expression: running arbitrary setup code to list executables is what we
  chose not to do.
- ``setup.cfg`` is read with :mod:`configparser`: ``[metadata] name``,
  ``[options.entry_points] console_scripts`` and ``[options.data_files]``.

Both may be there (setuptools merges them; ``setup.py``'s arguments win).
"""

from __future__ import annotations

import ast
import configparser
import glob
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

from actors.errors import PackageError

__all__ = ["SetupInfo", "read_setup", "parse_entry_point"]


@dataclass(frozen=True)
class SetupInfo:
    """What a package's setup files declare: its console scripts and its data files."""

    name: str | None = None
    console_scripts: dict[str, str] = field(default_factory=dict)  # executable -> "module:attr"
    data_files: list[tuple[str, list[str]]] = field(default_factory=list)  # (destination, sources)


def read_setup(folder: Path) -> SetupInfo:
    """The setup information of the package in ``folder`` (empty if it has no setup files).

    Raises PackageError naming the file (and line) that cannot be read.
    """
    info = SetupInfo()
    cfg = folder / "setup.cfg"
    if cfg.is_file():
        info = _read_cfg(cfg)
    script = folder / "setup.py"
    if script.is_file():
        found = _read_py(script)
        info = SetupInfo(
            name=found.name or info.name,
            console_scripts={**info.console_scripts, **found.console_scripts},
            data_files=found.data_files or info.data_files,
        )
    return info


def parse_entry_point(text: str, where: str) -> tuple[str, str]:
    """``"exe = module.path:func"`` -> ``("exe", "module.path:func")``; PackageError if malformed."""
    name, sep, target = text.partition("=")
    name, target = name.strip(), target.strip().split("[")[0].strip()  # "[extras]" mean nothing here
    module, colon, attr = target.partition(":")
    if not sep or not name or not colon or not all(part.isidentifier() for part in module.split(".")):
        raise PackageError(f"{where}: not a console script 'name = module:function': {text!r}")
    if not all(part.isidentifier() for part in attr.split(".")):
        raise PackageError(f"{where}: not a console script 'name = module:function': {text!r}")
    return name, target


# --------------------------------------------------------------------------- setup.cfg


def _read_cfg(path: Path) -> SetupInfo:
    parser = configparser.ConfigParser(interpolation=None)
    try:
        parser.read(path, encoding="utf-8")
    except configparser.Error as exc:
        raise PackageError(f"{path}: {' '.join(str(exc).split())}") from None
    scripts: dict[str, str] = {}
    if parser.has_option("options.entry_points", "console_scripts"):
        for line in parser.get("options.entry_points", "console_scripts").splitlines():
            if line.strip():
                name, target = parse_entry_point(line, f"{path}: [options.entry_points] console_scripts")
                scripts[name] = target
    data: list[tuple[str, list[str]]] = []
    if parser.has_section("options.data_files"):
        for destination, sources in parser.items("options.data_files"):
            files = [line.strip() for line in sources.replace(",", "\n").splitlines() if line.strip()]
            data.append((destination, _expand_globs(path.parent, files)))
    return SetupInfo(name=parser.get("metadata", "name", fallback="") or None, console_scripts=scripts, data_files=data)


def _expand_globs(folder: Path, patterns: list[str]) -> list[str]:
    out: list[str] = []
    for pattern in patterns:
        if glob.has_magic(pattern):
            out += sorted(str(Path(p).relative_to(folder)) for p in glob.glob(str(folder / pattern)))
        else:
            out.append(pattern)
    return out


# --------------------------------------------------------------------------- setup.py


def _read_py(path: Path) -> SetupInfo:
    text = path.read_text(encoding="utf-8")
    try:
        tree = ast.parse(text, str(path))
    except SyntaxError as exc:
        raise PackageError(f"{path}:{exc.lineno}: {exc.msg}") from None
    evaluator = _Evaluator(path, text, tree)
    call = next(
        (
            node
            for node in ast.walk(tree)
            if isinstance(node, ast.Call) and _callee(node.func) in ("setup", "setuptools.setup")
        ),
        None,
    )
    if call is None:
        return SetupInfo()
    arguments = {keyword.arg: keyword.value for keyword in call.keywords if keyword.arg}
    name = evaluator.value(arguments["name"]) if "name" in arguments else None
    scripts: dict[str, str] = {}
    if "entry_points" in arguments:
        points = evaluator.value(arguments["entry_points"])
        lines = points.get("console_scripts", []) if isinstance(points, dict) else []
        if isinstance(lines, str):
            lines = lines.splitlines()
        for line in lines:
            if str(line).strip():
                where = f"{path}:{arguments['entry_points'].lineno}: entry_points"
                exe, target = parse_entry_point(str(line), where)
                scripts[exe] = target
    data: list[tuple[str, list[str]]] = []
    if "data_files" in arguments:
        for item in evaluator.value(arguments["data_files"]) or []:
            if not (isinstance(item, list | tuple) and len(item) == 2 and isinstance(item[1], list | tuple)):
                raise PackageError(
                    f"{path}:{arguments['data_files'].lineno}: data_files: expected (destination, [files]) "
                    f"pairs, got {item!r}"
                )
            data.append((str(item[0]), [str(source) for source in item[1]]))
    return SetupInfo(name=str(name) if name is not None else None, console_scripts=scripts, data_files=data)


def _callee(func: ast.expr) -> str:
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return f"{_callee(func.value)}.{func.attr}"
    return ""


class _Evaluator:
    """Evaluates the expressions a setup file is made of, and nothing else."""

    def __init__(self, path: Path, text: str, tree: ast.Module) -> None:
        self.path = path
        self.text = text
        self.folder = path.parent
        self.names: dict[str, ast.expr] = {}
        for statement in tree.body:
            if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
                target = statement.targets[0]
                if isinstance(target, ast.Name):
                    self.names[target.id] = statement.value
        self._calls: Mapping[str, Callable[..., Any]] = {
            "os.path.join": os.path.join,
            "path.join": os.path.join,
            "join": os.path.join,
            "glob": self._glob,
            "glob.glob": self._glob,
            "str": str,
            "Path": PurePosixPath,
            "pathlib.Path": PurePosixPath,
            "list": list,
            "sorted": sorted,
        }

    def value(self, node: ast.expr, depth: int = 0) -> Any:
        if depth > 50:
            self._refuse(node, "names refer to each other too deeply")
        evaluate = lambda n: self.value(n, depth + 1)  # noqa: E731 - one name for the recursion
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, ast.List | ast.Tuple):
            return [evaluate(item) for item in node.elts]
        if isinstance(node, ast.Dict):
            if any(key is None for key in node.keys):
                self._refuse(node, "a ** in a dict")
            return {evaluate(key): evaluate(val) for key, val in zip(node.keys, node.values) if key is not None}
        if isinstance(node, ast.Name):
            if node.id not in self.names:
                self._refuse(node, f"{node.id!r} is not assigned at the top of the file")
            return evaluate(self.names[node.id])
        if isinstance(node, ast.JoinedStr):
            parts = []
            for part in node.values:
                if isinstance(part, ast.FormattedValue):
                    parts.append(str(evaluate(part.value)))
                else:
                    parts.append(str(evaluate(part)))
            return "".join(parts)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Div):
            left, right = evaluate(node.left), evaluate(node.right)
            try:
                return left + right if isinstance(node.op, ast.Add) else left / right
            except TypeError:
                self._refuse(node, "these values do not add up")
        if isinstance(node, ast.Starred):
            return evaluate(node.value)
        if isinstance(node, ast.Call) and not node.keywords:
            function = self._calls.get(_callee(node.func))
            if function is not None:
                arguments = []
                for argument in node.args:
                    if isinstance(argument, ast.Starred):
                        arguments += list(evaluate(argument.value))
                    else:
                        arguments.append(evaluate(argument))
                result = function(*arguments)
                return str(result) if isinstance(result, PurePosixPath) else result
        self._refuse(node, "only literals, names, +, f-strings, os.path.join and glob are read")

    def _glob(self, pattern: Any) -> list[str]:
        found = glob.glob(str(self.folder / str(pattern)))
        return sorted(str(Path(p).relative_to(self.folder)) for p in found)

    def _refuse(self, node: ast.expr, why: str) -> Any:
        code = ast.get_source_segment(self.text, node) or ast.dump(node)
        raise PackageError(f"{self.path}:{node.lineno}: cannot read {code!r} without running setup.py: {why}")
