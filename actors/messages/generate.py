"""The interface generator: roots of .msg/.srv/.action packages to msgspec Struct modules.

:func:`generate` turns a *root* (a folder of packages ``<root>/<pkg>/msg/*.msg``,
``<root>/<pkg>/srv/*.srv``, ``<root>/<pkg>/action/*.action``) into one module
per package and kind, written beside the sources: ``<root>/<pkg>/msg/__init__.py``
holds every message of ``pkg``, ``<root>/<pkg>/srv/__init__.py`` every service,
``<root>/<pkg>/action/__init__.py`` every action.  An action's module holds,
as rosidl's Python modules do, a class per action with ``Goal``, ``Result``,
``Feedback`` and ``Impl`` (``SendGoalService``, ``GetResultService``,
``FeedbackMessage``, ``CancelGoalService``, ``GoalStatusMessage``), beside the
structs themselves (``Fibonacci_Goal``, ``Fibonacci_SendGoal_Request``...).  The root folder's name is the top-level
Python package: the shipped root is ``interfaces``, so its types import as
``interfaces.std_msgs.msg``; a user's root ``/some/dir/my_root`` imports as
``my_root.my_pkg.msg`` once ``/some/dir`` is on ``sys.path``.  ``__init__.py``
files missing in the root and its packages are written too.  A package
referenced but not found in the given roots comes from the shipped root.

A generated class body is evaluated eagerly (no ``from __future__ import
annotations``): annotations resolve once at import, and defaults that name
another struct (``default_factory=Point``) need that struct defined first, so
structs of one module are emitted dependencies first.  Integer ranges are
module-level ``Annotated`` aliases (``_uint8``) so msgspec checks them on
decode; uint64 is checked for ``>= 0`` only (msgspec's bounds stop at int64).
"""

from __future__ import annotations

import json
import keyword
import math
from array import array
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any, TypeGuard, TypeVar, cast

from actors.errors import IdlError, InterfaceError
from actors.messages.arrays import typecode
from actors.messages.idl import (
    FLOATS,
    INTEGER_RANGES,
    OCTETS,
    PACKAGE_NAME,
    STRINGS,
    TYPE_NAME,
    ActionSpec,
    FieldType,
    MessageSpec,
    ServiceSpec,
    parse_action,
    parse_message,
    parse_service,
    shipped_root,
)

__all__ = ["generate", "render", "render_module", "render_kind", "module_map"]

# byte and char share uint8's alias: one range, one name.
_ALIAS = {name: f"_{name}" for name in INTEGER_RANGES} | {"byte": "_uint8", "char": "_uint8"}
_ZERO: dict[str, Any] = (
    {"bool": False, "string": "", "wstring": ""} | dict.fromkeys(FLOATS, 0.0) | dict.fromkeys(INTEGER_RANGES, 0)
)
_PYTHON_TYPE = (
    {"bool": "bool", "string": "str", "wstring": "str"}
    | dict.fromkeys(FLOATS, "float")
    | dict.fromkeys(INTEGER_RANGES, "int")
)


_S = TypeVar("_S")


def _every(specs: Sequence[object], kind: type[_S]) -> TypeGuard[Sequence[_S]]:
    return all(isinstance(spec, kind) for spec in specs)


def render_module(
    specs: Sequence[MessageSpec | ServiceSpec | ActionSpec],
    *,
    modules: Mapping[str, str],
    sources: str,
) -> str:
    """The source of one module holding ``specs`` (all messages, all services, or all actions).

    ``modules`` maps every known message and service (``pkg/msg/Name``,
    ``pkg/srv/Name``) to the module defining it; ``sources`` names the source
    files in the docstring.  Raises IdlError for a message that (indirectly)
    contains itself.
    """
    if _every(specs, MessageSpec):
        local = {spec.ros_type: spec for spec in specs}
        writer = _Writer(modules, {spec.name for spec in specs})
        for spec in _dependencies_first(local):
            writer.struct(spec)
    elif _every(specs, ServiceSpec):
        suffixes = ("", "_Request", "_Response", "_Event")
        writer = _Writer(modules, {spec.name + suffix for spec in specs for suffix in suffixes})
        for service in specs:
            writer.service(service)
    else:
        writer = _Writer(modules, {name for spec in specs for name in _action_names(spec)})
        for action in cast("Sequence[ActionSpec]", specs):  # neither messages nor services: actions
            writer.action(action)
    return writer.source(sources)


def _action_names(spec: Any) -> list[str]:
    """Every Python name an action's module defines for ``spec``."""
    services = (spec.send_goal, spec.get_result)
    messages = (spec.goal, spec.result, spec.feedback, spec.feedback_message)
    return [
        spec.name,
        *(m.name for m in messages),
        *(s.name + x for s in services for x in ("", "_Request", "_Response", "_Event")),
    ]


def _dependencies_first(local: Mapping[str, MessageSpec]) -> list[MessageSpec]:
    ordered: dict[str, MessageSpec] = {}
    visiting: set[str] = set()

    def visit(spec: MessageSpec) -> None:
        if spec.ros_type in ordered:
            return
        visiting.add(spec.ros_type)
        for field in spec.fields:
            target = local.get(field.type.ros_type)
            if target is None:
                continue
            if target.ros_type in visiting:
                raise IdlError(spec.path, field.line, f"{target.ros_type} contains itself")
            visit(target)
        visiting.discard(spec.ros_type)
        ordered[spec.ros_type] = spec

    for name in sorted(local):
        visit(local[name])
    return list(ordered.values())


class _Writer:
    """Accumulates class bodies, the names they import and the aliases they use."""

    def __init__(self, modules: Mapping[str, str], defined: set[str]) -> None:
        self.modules = modules
        self.taken = set(defined)  # every Python name defined or imported so far
        self.classes: list[str] = []
        self.exports: list[str] = []
        self.imports: dict[str, dict[str, str]] = {}  # module -> {name: local alias}
        self.local_names: dict[str, str] = {}  # ROS type -> Python name in this module
        self.aliases: set[str] = set()
        self.annotated = False
        self.numeric = False  # a field holds an array.array: the module imports array and held

    def struct(self, spec: MessageSpec) -> None:
        name = self._declare(spec.ros_type, spec.name)
        body = [
            f"class {name}(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):",
            f'    """``{spec.ros_type}``."""',
            "",
            f"    __ros_type__: ClassVar[str] = {_literal(spec.ros_type)}",
            f"    __ros_definition__: ClassVar[str] = {_text_literal(spec.text)}",
        ]
        body += [f"    {c.name}: ClassVar[{_PYTHON_TYPE[c.type.base]}] = {_literal(c.value)}" for c in spec.constants]
        if spec.fields:
            body.append("")
        body += [f"    {f.name}: {self._annotation(f.type)} = {self._default(f.type, f.default)}" for f in spec.fields]
        body += _held(spec)
        self.classes.append("\n".join(body))

    def service(self, spec: ServiceSpec) -> None:
        self.struct(spec.request)
        self.struct(spec.response)
        event = spec.event
        self.struct(event)
        name = self._declare(spec.ros_type, spec.name)
        self.classes.append(
            "\n".join(
                [
                    f"class {name}:",
                    f'    """``{spec.ros_type}``: its ``Request`` and ``Response`` messages, and ``Event``."""',
                    "",
                    f"    __ros_type__: ClassVar[str] = {_literal(spec.ros_type)}",
                    f"    __ros_definition__: ClassVar[str] = {_text_literal(spec.text)}",
                    f"    Request = {self.local_names[spec.request.ros_type]}",
                    f"    Response = {self.local_names[spec.response.ros_type]}",
                    f"    Event = {self.local_names[event.ros_type]}",
                ]
            )
        )

    def action(self, spec: ActionSpec) -> None:
        for part in (spec.goal, spec.result, spec.feedback):
            self.struct(part)
        self.service(spec.send_goal)
        self.service(spec.get_result)
        self.struct(spec.feedback_message)
        name = self._declare(spec.ros_type, spec.name)
        local = self.local_names
        cancel = self._imported("action_msgs/srv/CancelGoal", "CancelGoal")
        status = self._imported("action_msgs/msg/GoalStatusArray", "GoalStatusArray")
        self.classes.append(
            "\n".join(
                [
                    f"class {name}:",
                    f'    """``{spec.ros_type}``: ``Goal``, ``Result``, ``Feedback``.',
                    "",
                    "    ``Impl`` holds the types its wire protocol uses.",
                    '    """',
                    "",
                    f"    __ros_type__: ClassVar[str] = {_literal(spec.ros_type)}",
                    f"    __ros_definition__: ClassVar[str] = {_text_literal(spec.text)}",
                    f"    Goal = {local[spec.goal.ros_type]}",
                    f"    Result = {local[spec.result.ros_type]}",
                    f"    Feedback = {local[spec.feedback.ros_type]}",
                    "",
                    "    class Impl:",
                    '        """The services and topic types of the action\'s wire protocol."""',
                    "",
                    f"        SendGoalService = {local[spec.send_goal.ros_type]}",
                    f"        GetResultService = {local[spec.get_result.ros_type]}",
                    f"        FeedbackMessage = {local[spec.feedback_message.ros_type]}",
                    f"        CancelGoalService = {cancel}",
                    f"        GoalStatusMessage = {status}",
                ]
            )
        )

    def source(self, sources: str) -> str:
        ranges = {_ALIAS[base]: bounds for base, bounds in INTEGER_RANGES.items()}
        aliases = [
            f"{alias} = Annotated[int, msgspec.Meta({_bounds(low, high)})]"
            for alias, (low, high) in ranges.items()
            if alias in self.aliases
        ]
        typing_names = "Annotated, ClassVar" if self.annotated or aliases else "ClassVar"
        if self.numeric:
            self.imports.setdefault("actors.messages.arrays", {})["held"] = "held"
        imports = [
            _import(module, sorted(n if n == a else f"{n} as {a}" for n, a in names.items()))
            for module, names in sorted(self.imports.items())
        ]
        standard = f"from typing import {typing_names}"
        if self.numeric:
            standard = "from array import array\nfrom collections.abc import MutableSequence\n" + standard
        sections = [
            f'"""Generated from {sources} by `python -m actors interface generate`; do not edit."""',
            f"{standard}\n\nimport msgspec",
            "\n".join(imports),
            "\n".join(["__all__ = [", *(f"    {_literal(n)}," for n in sorted(self.exports)), "]"]),
            "\n".join(aliases),
        ]
        head = "\n\n".join(section for section in sections if section)
        return head + "\n\n\n" + "\n\n\n".join(self.classes) + "\n"

    def _declare(self, ros_type: str, name: str) -> str:
        self.local_names[ros_type] = name
        self.exports.append(name)
        return name

    def _type_name(self, type_: FieldType) -> str:
        if type_.ros_type in self.local_names:
            return self.local_names[type_.ros_type]
        return self._imported(type_.ros_type, type_.base)

    def _imported(self, ros_type: str, base: str) -> str:
        """The local name of ``base`` imported from the module defining ``ros_type``."""
        imported = self.imports.setdefault(self.modules[ros_type], {})
        if base not in imported:
            clash = base in self.taken
            imported[base] = f"{ros_type.split('/')[0]}_{base}" if clash else base
            self.taken.add(imported[base])
        return imported[base]

    def _annotation(self, type_: FieldType) -> str:
        if type_.array and type_.base in OCTETS:
            return self._sized("bytes", type_)
        if type_.is_nested:
            element = self._type_name(type_)
        elif type_.base in INTEGER_RANGES:
            element = _ALIAS[type_.base]
            self.aliases.add(element)
        elif type_.base in STRINGS and type_.string_bound is not None:
            self.annotated = True
            element = f"Annotated[str, msgspec.Meta(max_length={type_.string_bound})]"
        else:
            element = _PYTHON_TYPE[type_.base]
        if not type_.array:
            return element
        # An array.array (see actors.messages.arrays) is a mutable sequence, not a list.
        return self._sized(f"{'MutableSequence' if typecode(type_) else 'list'}[{element}]", type_)

    def _sized(self, annotation: str, type_: FieldType) -> str:
        if type_.array == "unbounded":
            return annotation
        self.annotated = True
        low = f"min_length={type_.size}, " if type_.array == "fixed" else ""
        return f"Annotated[{annotation}, msgspec.Meta({low}max_length={type_.size})]"

    def _default(self, type_: FieldType, value: Any) -> str:
        fixed = type_.array == "fixed"
        if type_.array and type_.base in OCTETS:
            return _literal(value) if value is not None else f"bytes({type_.size})" if fixed else 'b""'
        code = typecode(type_)
        if code is not None:
            self.numeric = True
            if value is not None:
                return f"msgspec.field(default_factory=lambda: array({_literal(code)}, {_literal(value)}))"
            zeros = f", bytes({(type_.size or 0) * array(code).itemsize})" if fixed else ""
            return f"msgspec.field(default_factory=lambda: array({_literal(code)}{zeros}))"
        if type_.array:
            if value is not None:
                factory = f"lambda: {_literal(value)}"
            elif fixed and type_.is_nested:
                factory = f"lambda: [{self._type_name(type_)}() for _ in range({type_.size})]"
            elif fixed:
                factory = f"lambda: [{_literal(_ZERO[type_.base])}] * {type_.size}"
            else:
                factory = "list"
            return f"msgspec.field(default_factory={factory})"
        if type_.is_nested:
            return f"msgspec.field(default_factory={self._type_name(type_)})"
        return _literal(_ZERO[type_.base] if value is None else value)


def _held(spec: MessageSpec) -> list[str]:
    """A ``__post_init__`` that makes the numeric arrays given to the constructor ``array.array``s, as rclpy does."""
    lines = []
    for field in spec.fields:
        code = typecode(field.type)
        if code is not None:
            value = f"self.{field.name}"
            lines.append(f"        if type({value}) is not array or {value}.typecode != {_literal(code)}:")
            lines.append(f"            {value} = held({value}, {_literal(code)})")
    return ["", "    def __post_init__(self) -> None:", *lines] if lines else []


def _bounds(low: int, high: int) -> str:
    # msgspec cannot check bounds beyond int64; msgpack itself refuses ints
    # above uint64's maximum, so only JSON and plain data can exceed it.
    return f"ge={low}, le={high}" if high < 2**63 else f"ge={low}"


def _literal(value: Any) -> str:
    """A Python literal for a parsed default or constant."""
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, float) and not math.isfinite(value):
        return f'float("{value}")'
    if isinstance(value, list):
        return "[" + ", ".join(_literal(item) for item in value) + "]"
    return repr(value)


def _text_literal(text: str) -> str:
    """A multi-line string literal, one source line per definition line."""
    if not text:
        return '""'
    lines = text.splitlines(keepends=True)
    return "(\n" + "".join(f"        {_literal(line)}\n" for line in lines) + "    )"


def _import(module: str, names: list[str]) -> str:
    line = f"from {module} import {', '.join(names)}"
    if len(line) <= 99:
        return line
    return f"from {module} import (\n" + "".join(f"    {name},\n" for name in names) + ")"


def generate(roots: Sequence[str | Path] = ()) -> list[Path]:
    """Generate the modules of every package under ``roots`` (default: the shipped root).

    Writes only files whose text changed and returns their paths.  Raises
    IdlError for a malformed source or an unknown referenced type, and
    InterfaceError for a root or package that cannot be a Python package.
    """
    written = []
    for path, text in render(roots).items():
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            written.append(path)
    return written


def render(roots: Sequence[str | Path] = ()) -> dict[Path, str]:
    """What :func:`generate` would write, path to text; reads sources and writes nothing.

    Raises as :func:`generate` does.
    """
    given = [Path(root).resolve() for root in roots] or [shipped_root()]
    packages = _find_packages([*given, shipped_root()])
    modules = module_map((pkg, root.name, kinds) for pkg, (root, kinds) in packages.items())
    out: dict[Path, str] = {}
    for pkg, (root, kinds) in packages.items():
        if root not in given:
            continue
        for kind, sources in kinds.items():
            out[root / pkg / kind / "__init__.py"] = render_kind(pkg, kind, sources, modules)
        doc = f"The {pkg} interface package: ``{root.name}.{pkg}.msg``, ``.srv`` and ``.action``."
        _where_missing(out, root / pkg / "__init__.py", doc)
    for root in given:
        _where_missing(out, root / "__init__.py", "Interface packages made by ``actors interface generate``.")
    return out


def module_map(packages: Iterable[tuple[str, str, Mapping[str, Sequence[Path]]]]) -> dict[str, str]:
    """Where every message and service of ``packages`` is defined: ``pkg/msg/Name`` to its module.

    Each package is its name, its top-level module (``interfaces``, a root's
    name) and its source files by kind.
    """
    return {
        f"{pkg}/{kind}/{source.stem}": f"{top}.{pkg}.{kind}"
        for pkg, top, kinds in packages
        for kind in ("msg", "srv")
        for source in kinds.get(kind, ())
    }


def render_kind(pkg: str, kind: str, sources: Sequence[Path], modules: dict[str, str]) -> str:
    """The module of one package's sources of one kind: parsed, its references checked, rendered.

    Raises IdlError or InterfaceError naming the source (and line) that is wrong.
    """
    specs = [_parse_file(source, pkg, kind) for source in sources]
    _check_references(specs, modules)
    return render_module(specs, modules=modules, sources=f"{pkg}/{kind}/*.{kind}")


def _find_packages(roots: Iterable[Path]) -> dict[str, tuple[Path, dict[str, list[Path]]]]:
    """Package name to its root and sources by kind; the first root holding a package wins."""
    packages: dict[str, tuple[Path, dict[str, list[Path]]]] = {}
    tops: dict[str, Path] = {}
    for root in roots:
        if not root.is_dir():
            raise InterfaceError(f"{root}: no such interface root folder")
        if not root.name.isidentifier() or keyword.iskeyword(root.name):
            raise InterfaceError(f"{root}: a root's name must be a Python identifier")
        if tops.setdefault(root.name, root) != root:
            raise InterfaceError(f"{root}: another root is already named {root.name!r}")
        found: dict[str, dict[str, list[Path]]] = {}
        for kind in ("msg", "srv", "action"):
            for source in sorted(root.glob(f"*/{kind}/*.{kind}")):
                found.setdefault(source.parent.parent.name, {}).setdefault(kind, []).append(source)
            for other in ("msg", "srv", "action"):
                misplaced = next(iter(sorted(root.glob(f"*/{other}/*.{kind}"))), None) if other != kind else None
                if misplaced is not None:
                    raise InterfaceError(f"{misplaced}: a .{kind} file belongs in {kind}/, not {other}/")
        for pkg, kinds in found.items():
            if not PACKAGE_NAME.fullmatch(pkg) or keyword.iskeyword(pkg):
                raise InterfaceError(f"{root / pkg}: invalid package name {pkg!r}")
            packages.setdefault(pkg, (root, kinds))
    return packages


_PARSERS = {"msg": parse_message, "srv": parse_service, "action": parse_action}


def _parse_file(path: Path, pkg: str, kind: str) -> MessageSpec | ServiceSpec | ActionSpec:
    if not TYPE_NAME.fullmatch(path.stem):
        raise InterfaceError(f"{path}: a type name must be CamelCase letters and digits")
    # A class of that name cannot be written (None, True, False) or would hide what the
    # generated module imports from typing.
    if keyword.iskeyword(path.stem) or path.stem in ("Annotated", "ClassVar"):
        raise InterfaceError(f"{path}: the type name {path.stem!r} is reserved in Python")
    if not path.is_file():
        raise InterfaceError(f"{path}: not a file (an interface is a .{kind} file)")
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise InterfaceError(f"{path}:{line}: not UTF-8 text (byte {data[error.start]:#04x})") from None
    parse: Any = _PARSERS[kind]
    return parse(text, path=path, pkg=pkg, name=path.stem)


def _parts(spec: MessageSpec | ServiceSpec | ActionSpec) -> tuple[MessageSpec, ...]:
    """The messages of a spec whose fields its module defines."""
    if isinstance(spec, ServiceSpec):
        return (spec.request, spec.response)
    if isinstance(spec, ActionSpec):
        return (spec.goal, spec.result, spec.feedback)
    return (spec,)


def _check_references(specs: Iterable[MessageSpec | ServiceSpec | ActionSpec], modules: dict[str, str]) -> None:
    for spec in specs:
        if isinstance(spec, ActionSpec):
            missing = [t for t in _ACTION_NEEDS if t not in modules]
            if missing:
                raise IdlError(spec.path, 1, f"an action needs {', '.join(missing)}")
        for part in _parts(spec):
            for field in part.fields:
                if field.type.is_nested and field.type.ros_type not in modules:
                    raise IdlError(part.path, field.line, f"unknown type {field.type.ros_type!r}")


# What every action's module uses beside its own parts.
_ACTION_NEEDS = (
    "unique_identifier_msgs/msg/UUID",
    "builtin_interfaces/msg/Time",
    "action_msgs/srv/CancelGoal",
    "action_msgs/msg/GoalStatusArray",
)


def _where_missing(out: dict[Path, str], path: Path, doc: str) -> None:
    if not path.exists():
        out[path] = f'"""{doc}"""\n'
