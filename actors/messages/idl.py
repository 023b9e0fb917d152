"""The ``.msg``/``.srv``/``.action`` parser: ROS 2 interface text to small frozen specs.

A ``.msg`` file holds one declaration a line, ``#`` starting a comment:

    TYPE NAME [DEFAULT]        a field; DEFAULT as in ROS (``int64 a 5``,
                               ``string s "hi"``, ``float64[] v [1.0, 2.0]``)
    TYPE NAME=VALUE            a constant (primitive, non-array types only)

TYPE is a primitive (``bool byte char float32 float64 int8 .. uint64 string
wstring``), a bounded string (``string<=N``) or a message (``Name``,
``pkg/Name``, ``pkg/msg/Name``; a bare ``Name`` is the same package's message,
in ``.srv`` and ``.action`` files too), optionally an array: ``T[]``, ``T[N]``
or ``T[<=N]``.  A ``.srv`` file is a request and a response separated by a
``---`` line; an ``.action`` file is a goal, a result and a feedback separated
by two.  An action also implies the types ROS derives from it (rosidl's
``Action`` definition): the ``Name_SendGoal`` and ``Name_GetResult`` services
and the ``Name_FeedbackMessage`` topic type, all of kind ``action``; their
definitions name the action's own parts as ``pkg/action/Name_Goal``.

Every problem raises :class:`actors.errors.IdlError` naming ``path:line``.
Generating modules from parsed files is :mod:`actors.messages.generate`'s job.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from actors.errors import IdlError

__all__ = [
    "Constant",
    "Field",
    "FieldType",
    "MessageSpec",
    "ServiceSpec",
    "ActionSpec",
    "FLOATS",
    "INTEGER_RANGES",
    "OCTETS",
    "PRIMITIVES",
    "STRINGS",
    "PACKAGE_NAME",
    "TYPE_NAME",
    "parse_message",
    "parse_service",
    "parse_action",
    "shipped_root",
    "strip_comment",
]

#: Inclusive value range of every integer primitive (``byte`` and ``char`` are uint8).
INTEGER_RANGES: dict[str, tuple[int, int]] = {
    "byte": (0, 255),
    "char": (0, 255),
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
#: The other primitives, by kind.
FLOATS = frozenset({"float32", "float64"})
STRINGS = frozenset({"string", "wstring"})
PRIMITIVES = frozenset({"bool", *INTEGER_RANGES, *FLOATS, *STRINGS})
#: Element types whose arrays are Python ``bytes``.
OCTETS = frozenset({"byte", "uint8"})

_TYPE = re.compile(
    r"(?P<base>[A-Za-z][A-Za-z0-9_/]*?)"
    r"(?:<=(?P<string_bound>\d+))?"
    r"(?:\[(?P<upper><=)?(?P<size>\d*)\])?"
)
#: What a package name and a type name may be.
PACKAGE_NAME = re.compile(r"[a-z][a-z0-9_]*")
#: The largest array size or string bound: CDR carries lengths as uint32.
_MAX_BOUND = 2**32 - 1
TYPE_NAME = re.compile(r"[A-Z][A-Za-z0-9]*")
# The parts of an action other definitions may name: ``pkg/action/Name_Goal``, and its services'
# requests and responses (``pkg/action/Name_SendGoal_Request``), as a service's event names them.
_ACTION_PART = re.compile(r"[A-Z][A-Za-z0-9]*_(?:Goal|Result|Feedback|(?:SendGoal|GetResult)_(?:Request|Response))")
# The parts of a service its event names: ``pkg/srv/Name_Request``, ``pkg/srv/Name_Response``.
_SERVICE_PART = re.compile(r"[A-Z][A-Za-z0-9]*_(?:Request|Response)")
_FIELD_NAME = re.compile(r"(?!.*__)(?!.*_$)[a-z][a-z0-9_]*")
_CONSTANT_NAME = re.compile(r"[A-Z][A-Z0-9_]*")
_CONSTANT = re.compile(r"(?P<name>[A-Za-z_][A-Za-z0-9_]*)\s*=\s*(?P<value>.*)")
# Names that generated class bodies evaluate; a field with one of them would
# shadow it for the fields after it.
_RESERVED = frozenset({"bool", "bytes", "float", "int", "list", "str", "msgspec"})


@dataclass(frozen=True, slots=True)
class FieldType:
    """A field's type: ``base`` is a primitive name or a message name (then ``pkg`` is set).

    ``array`` is None for a scalar, else ``"unbounded"`` (``T[]``),
    ``"bounded"`` (``T[<=size]``) or ``"fixed"`` (``T[size]``).  ``kind`` is
    ``msg``, ``srv`` for a service's request or response (its event names
    them), or ``action`` for an action's parts.
    """

    base: str
    pkg: str | None = None
    string_bound: int | None = None
    array: str | None = None
    size: int | None = None
    kind: str = "msg"

    @property
    def is_nested(self) -> bool:
        """True for a message type, False for a primitive."""
        return self.pkg is not None

    @property
    def ros_type(self) -> str:
        """The element's ROS name: ``pkg/msg/Name``, or the primitive's name."""
        return f"{self.pkg}/{self.kind}/{self.base}" if self.pkg else self.base


@dataclass(frozen=True, slots=True)
class Field:
    """One field; ``default`` is None when the ROS zero value applies."""

    name: str
    type: FieldType
    default: Any
    line: int


@dataclass(frozen=True, slots=True)
class Constant:
    """One constant: a primitive, non-array ``type`` and its ``value``."""

    name: str
    type: FieldType
    value: Any
    line: int


@dataclass(frozen=True, slots=True)
class MessageSpec:
    """A parsed message, a service's request or response (``kind="srv"``), or an action's part.

    ``text`` is its raw definition, comments included.
    """

    pkg: str
    name: str
    fields: tuple[Field, ...]
    constants: tuple[Constant, ...]
    text: str
    path: str
    kind: str = "msg"

    @property
    def ros_type(self) -> str:
        """``pkg/msg/Name`` (``pkg/srv/Name_Request`` for a request)."""
        return f"{self.pkg}/{self.kind}/{self.name}"


@dataclass(frozen=True, slots=True)
class ServiceSpec:
    """A parsed service: its request and response messages and its raw text.

    ``kind`` is ``action`` for the services an action implies.
    """

    pkg: str
    name: str
    request: MessageSpec
    response: MessageSpec
    text: str
    path: str
    kind: str = "srv"

    @property
    def ros_type(self) -> str:
        """``pkg/srv/Name`` (``pkg/action/Name_SendGoal`` for an action's)."""
        return f"{self.pkg}/{self.kind}/{self.name}"

    @property
    def event(self) -> MessageSpec:
        """``Name_Event``, what service introspection publishes: rosidl's ServiceEventInfo and at most
        one request and one response."""
        own = self.ros_type
        definition = f"service_msgs/ServiceEventInfo info\n{own}_Request[<=1] request\n{own}_Response[<=1] response\n"
        return parse_message(definition, path=f"{own}_Event", pkg=self.pkg, name=f"{self.name}_Event", kind=self.kind)


@dataclass(frozen=True, slots=True)
class ActionSpec:
    """A parsed action: its goal, result and feedback, and the wire types ROS derives from them.

    ``send_goal`` (request: ``goal_id`` and ``goal``; response: ``accepted``
    and ``stamp``), ``get_result`` (request: ``goal_id``; response: ``status``
    and ``result``) and ``feedback_message`` (``goal_id`` and ``feedback``) are
    named and shaped exactly as rosidl makes them, so their type hashes and
    wire form match ROS's.
    """

    pkg: str
    name: str
    goal: MessageSpec
    result: MessageSpec
    feedback: MessageSpec
    send_goal: ServiceSpec
    get_result: ServiceSpec
    feedback_message: MessageSpec
    text: str
    path: str

    @property
    def ros_type(self) -> str:
        """``pkg/action/Name``."""
        return f"{self.pkg}/action/{self.name}"


def parse_message(text: str, *, path: str | Path = "<string>", pkg: str, name: str, kind: str = "msg") -> MessageSpec:
    """Parse the text of a ``.msg`` file of package ``pkg``.

    ``path`` only names the source in errors; ``kind`` is the ROS name's
    middle part (``msg``, or ``srv``/``action`` for the parts of those).
    Raises IdlError at the first malformed line, duplicate name or
    out-of-range value.
    """
    return _parse_lines(_lines(text), 0, path=str(path), pkg=pkg, name=name, kind=kind)


def parse_service(text: str, *, path: str | Path = "<string>", pkg: str, name: str) -> ServiceSpec:
    """Parse the text of a ``.srv`` file: request, a ``---`` line, response.

    The parts become messages ``Name_Request`` and ``Name_Response`` of kind
    ``srv``.  Raises IdlError unless there is exactly one separator, or as
    :func:`parse_message` does.
    """
    lines = _lines(text)
    common = {"path": str(path), "pkg": pkg, "kind": "srv"}
    (request, offset_r), (response, offset_s) = _sections(lines, 2, str(path), "a service")
    request_spec = _parse_lines(request, offset_r, name=f"{name}_Request", **common)
    response_spec = _parse_lines(response, offset_s, name=f"{name}_Response", **common)
    return ServiceSpec(pkg, name, request_spec, response_spec, "\n".join(lines) + "\n", str(path))


def parse_action(text: str, *, path: str | Path = "<string>", pkg: str, name: str) -> ActionSpec:
    """Parse the text of an ``.action`` file: goal, ``---``, result, ``---``, feedback.

    The parts become messages ``Name_Goal``, ``Name_Result`` and
    ``Name_Feedback`` of kind ``action``, and the derived ``Name_SendGoal``,
    ``Name_GetResult`` and ``Name_FeedbackMessage`` types are built around
    them.  Raises IdlError unless there are exactly two separators, or as
    :func:`parse_message` does.
    """
    lines = _lines(text)
    where = {"path": str(path), "pkg": pkg, "kind": "action"}
    parts = [
        _parse_lines(section, offset, name=f"{name}_{part}", **where)
        for part, (section, offset) in zip(("Goal", "Result", "Feedback"), _sections(lines, 3, str(path), "an action"))
    ]
    goal, result, feedback = parts
    uuid = "unique_identifier_msgs/UUID goal_id"
    own = f"{pkg}/action/{name}"

    def derived(part: str, definition: str) -> MessageSpec:
        return parse_message(definition, path=f"{own}_{part}", pkg=pkg, name=f"{name}_{part}", kind="action")

    def service(part: str, request: str, response: str) -> ServiceSpec:
        return ServiceSpec(
            pkg,
            f"{name}_{part}",
            derived(f"{part}_Request", request),
            derived(f"{part}_Response", response),
            f"{request}---\n{response}",
            f"{own}_{part}",
            "action",
        )

    return ActionSpec(
        pkg,
        name,
        goal,
        result,
        feedback,
        service("SendGoal", f"{uuid}\n{own}_Goal goal\n", "bool accepted\nbuiltin_interfaces/Time stamp\n"),
        service("GetResult", f"{uuid}\n", f"int8 status\n{own}_Result result\n"),
        derived("FeedbackMessage", f"{uuid}\n{own}_Feedback feedback\n"),
        "\n".join(lines) + "\n",
        str(path),
    )


def _sections(lines: list[str], count: int, path: str, what: str) -> list[tuple[list[str], int]]:
    """``lines`` cut at its ``---`` lines into ``count`` sections, each with its line offset."""
    separators = [i for i, line in enumerate(lines) if strip_comment(line).strip() == "---"]
    if len(separators) != count - 1:
        line = separators[count - 1] + 1 if len(separators) >= count else len(lines)
        expected = "exactly one '---' line" if count == 2 else f"exactly {count - 1} '---' lines"
        raise IdlError(path, line, f"{what} needs {expected}")
    starts = [0, *(i + 1 for i in separators)]
    ends = [*separators, len(lines)]
    return [(lines[start:end], start) for start, end in zip(starts, ends)]


def strip_comment(line: str) -> str:
    """``line`` without its comment: from the first ``#`` outside quotes."""
    quote = None
    escaped = False
    for i, char in enumerate(line):
        if escaped:
            escaped = False
        elif char == "\\" and quote:
            escaped = True
        elif char in "\"'" and quote in (None, char):
            quote = None if quote else char
        elif char == "#" and not quote:
            return line[:i]
    return line


def _lines(text: str) -> list[str]:
    return text.replace("\r\n", "\n").rstrip("\n").split("\n") if text.strip() else []


def _parse_lines(lines: list[str], offset: int, *, path: str, pkg: str, name: str, kind: str) -> MessageSpec:
    fields: list[Field] = []
    constants: list[Constant] = []
    seen: set[str] = set()
    for number, raw in enumerate(lines, offset + 1):
        content = strip_comment(raw).strip()
        if not content:
            continue
        where = (path, number)
        type_text, rest = _first_word(content)
        if not rest:
            raise IdlError(*where, f"expected 'TYPE NAME', got {content!r}")
        type_ = _parse_type(type_text, pkg, where)
        constant = _CONSTANT.fullmatch(rest)
        if constant:
            item: Field | Constant = _parse_constant(type_, constant, number, where)
        else:
            item = _parse_field(type_, *_first_word(rest), number, where)
        if item.name in seen:
            raise IdlError(*where, f"duplicate name {item.name!r}")
        seen.add(item.name)
        if isinstance(item, Constant):
            constants.append(item)
        else:
            fields.append(item)
    text = "\n".join(lines) + "\n" if lines else ""
    return MessageSpec(pkg, name, tuple(fields), tuple(constants), text, path, kind)


def _first_word(text: str) -> tuple[str, str]:
    """``text``'s first whitespace-separated word and the stripped rest."""
    first, *rest = text.split(None, 1)
    return first, rest[0].strip() if rest else ""


def _parse_type(text: str, pkg: str, where: tuple[str, int]) -> FieldType:
    match = _TYPE.fullmatch(text)
    if not match:
        raise IdlError(*where, f"malformed type {text!r}")
    base, string_bound, upper, size = match.group("base", "string_bound", "upper", "size")
    if string_bound is not None and base not in STRINGS:
        raise IdlError(*where, f"only strings take a bound '<=N', not {base!r}")
    if upper and not size:
        raise IdlError(*where, f"a bounded array needs a size: {text!r}")
    array = None if size is None else "bounded" if upper else "fixed" if size else "unbounded"
    for bound, what in ((string_bound, "a string's bound"), (size, "an array's size")):
        # ROS refuses 0; CDR writes lengths as uint32, so nothing larger can cross the wire.
        if bound and not 0 < int(bound) <= _MAX_BOUND:
            raise IdlError(*where, f"{what} must be from 1 to {_MAX_BOUND}, got {int(bound)} in {text!r}")
    bound = int(string_bound) if string_bound else None
    count = int(size) if size else None
    if base in PRIMITIVES:
        return FieldType(base, string_bound=bound, array=array, size=count)
    parts = base.split("/")
    kind = "msg"
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        kind = parts[1]
        parts = [parts[0], parts[2]]
    if len(parts) == 1:
        parts = [pkg, parts[0]]
    name_form = {"action": _ACTION_PART, "srv": _SERVICE_PART}.get(kind, TYPE_NAME)
    if len(parts) != 2 or not PACKAGE_NAME.fullmatch(parts[0]) or not name_form.fullmatch(parts[1]):
        raise IdlError(*where, f"unknown type {text!r}")
    return FieldType(parts[1], pkg=parts[0], kind=kind, string_bound=bound, array=array, size=count)


def _parse_field(type_: FieldType, name: str, default: str, number: int, where: tuple[str, int]) -> Field:
    if not _FIELD_NAME.fullmatch(name):
        raise IdlError(*where, f"invalid field name {name!r} (lowercase, digits, single '_')")
    if keyword.iskeyword(name) or name in _RESERVED:
        raise IdlError(*where, f"field name {name!r} is reserved in Python")
    if default and type_.is_nested:
        raise IdlError(*where, "a message-typed field cannot have a default value")
    value = _parse_value(type_, default, where) if default else None
    return Field(name, type_, value, number)


def _parse_constant(type_: FieldType, match: re.Match[str], number: int, where: tuple[str, int]) -> Constant:
    name, value = match.group("name", "value")
    if not _CONSTANT_NAME.fullmatch(name):
        raise IdlError(*where, f"invalid constant name {name!r} (uppercase, digits, '_')")
    if type_.is_nested or type_.array:
        raise IdlError(*where, "a constant must have a primitive, non-array type")
    if not value.strip():
        raise IdlError(*where, f"constant {name!r} has no value")
    return Constant(name, type_, _parse_value(type_, value.strip(), where), number)


def _parse_value(type_: FieldType, text: str, where: tuple[str, int]) -> Any:
    if not type_.array:
        return _parse_scalar(type_, text, where)
    if not (text.startswith("[") and text.endswith("]")):
        raise IdlError(*where, f"an array default must look like [a, b], got {text!r}")
    items = [_parse_scalar(type_, item, where) for item in _split_items(text[1:-1], where)]
    if type_.array == "fixed" and len(items) != type_.size:
        raise IdlError(*where, f"expected {type_.size} values, got {len(items)}")
    if type_.array == "bounded" and type_.size is not None and len(items) > type_.size:
        raise IdlError(*where, f"expected at most {type_.size} values, got {len(items)}")
    return bytes(items) if type_.base in OCTETS else items


def _split_items(text: str, where: tuple[str, int]) -> list[str]:
    items, quote, start = [], None, 0
    for i, char in enumerate(text):
        if char in "\"'" and quote in (None, char) and text[i - 1 : i] != "\\":
            quote = None if quote else char
        elif char == "," and not quote:
            items.append(text[start:i])
            start = i + 1
    if quote:
        raise IdlError(*where, f"unterminated string in {text!r}")
    items.append(text[start:])
    items = [item.strip() for item in items]
    return [] if items == [""] else items


def _parse_scalar(type_: FieldType, text: str, where: tuple[str, int]) -> Any:
    base = type_.base
    if base == "bool":
        lowered = text.lower()
        if lowered not in ("true", "false", "1", "0"):
            raise IdlError(*where, f"expected true or false, got {text!r}")
        return lowered in ("true", "1")
    if base in STRINGS:
        value = _unquote(text)
        if type_.string_bound is not None and len(value) > type_.string_bound:
            raise IdlError(*where, f"string longer than its bound {type_.string_bound}: {text!r}")
        return value
    number: float
    try:
        number = float(text) if base in FLOATS else int(text)
    except ValueError:
        raise IdlError(*where, f"expected a {base} value, got {text!r}") from None
    low, high = INTEGER_RANGES.get(base, (number, number))
    if not low <= number <= high:
        raise IdlError(*where, f"{number} is out of range for {base} [{low}, {high}]")
    return number


def _unquote(text: str) -> str:
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "\"'":
        quote = text[0]
        return text[1:-1].replace("\\" + quote, quote).replace("\\\\", "\\")
    return text


def shipped_root() -> Path:
    """The ``interfaces`` folder installed with actors (found from the package, not the cwd)."""
    import interfaces

    return Path(interfaces.__file__).resolve().parent
