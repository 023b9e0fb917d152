"""msgspec's validation errors in our words: the key path, what was expected, what was given, did you mean.

msgspec says ``Expected `bool`, got `str` - at `$.data``` or ``Object
contains unknown field `lineer```.  :func:`explain` turns that into a key path
and a problem a user can act on: ``("data", "expected a bool, got the string
'maybe'")``, ``("lineer", "unknown field (did you mean 'linear'?)")``, an
invalid choice with the valid ones listed.  It reads the value given and the
type expected at the error's path from the data and the type themselves, so
it never guesses.  Callers frame the pair (a file and its key path, a message
type and its field).
"""

from __future__ import annotations

import difflib
import enum
import re
from collections.abc import Iterable, Mapping
from typing import Any, NamedTuple

import msgspec
import msgspec.inspect as mi

__all__ = ["Words", "MESSAGE_WORDS", "FILE_WORDS", "Explained", "explain", "did_you_mean", "closest", "shown"]


class Words(msgspec.Struct, frozen=True, kw_only=True):
    """How a kind of input names its parts: ``key`` or ``field``, ``table`` or ``mapping``..."""

    key: str
    mapping: str
    array: str


MESSAGE_WORDS = Words(key="field", mapping="a mapping", array="a list")
"""For messages and requests (YAML, JSON, msgpack)."""

FILE_WORDS = Words(key="key", mapping="a table", array="an array")
"""For TOML files."""

_AT = re.compile(r"^(?P<problem>.*?)(?: - at `\$(?P<path>[^`]*)`)?$", re.S)
_FIELD = re.compile(r"^Object (?P<what>contains unknown|missing required) field `(?P<key>[^`]+)`$")
_GOT = re.compile(r"^Expected `(?P<want>\w+)`, got `(?P<got>\w+)`$")
_BOUND = re.compile(r"^Expected `(?P<want>\w+)` (?P<op>[<>]=?) (?P<limit>\S+)$")
_LENGTH = re.compile(r"^Expected `(?P<want>\w+)` of length (?P<op>[<>]=? )?(?P<n>\d+)(?:, got (?P<got>\d+))?$")
_CHOICE = re.compile(r"^Invalid (?:enum )?value (?P<value>.+)$")
_STEP = re.compile(r"\.([^.\[]+)|\[(\d+|\.\.\.)\]")
_OPS = {">": "greater than", ">=": "at least", "<": "less than", "<=": "at most"}


class Explained(NamedTuple):
    """Where the problem is (``nodes[0].use``, ``linear.x``; empty for the top level) and what it is.

    ``unknown`` is true when the path names a key the type does not have.
    """

    path: str
    problem: str
    unknown: bool = False


def explain(exc: msgspec.MsgspecError, type_: Any, data: Any, words: Words = MESSAGE_WORDS) -> Explained:
    """What ``exc`` (raised converting or decoding ``data`` as ``type_``) means, in our words.

    ``data`` is the plain value that was converted (for bytes, their untyped
    decoding).  Never raises.
    """
    match = _AT.match(str(exc))
    assert match is not None  # the pattern matches any text
    text, raw_path = match["problem"], match["path"] or ""
    steps = _steps(raw_path)
    value, info = data, _unwrap(mi.type_info(type_), data)
    for i, step in enumerate(steps):
        if step == "...":  # msgspec does not name dict keys: find the one that fails
            step = _failing_key(value, info)
            steps[i] = step
        value, info = _child(value, info, step)
    path = _join(steps)
    if field := _FIELD.match(text):
        key = field["key"]
        path = f"{path}.{key}" if path else key
        if field["what"] == "missing required":
            return Explained(path, f"missing required {words.key}")
        return Explained(path, f"unknown {words.key}" + did_you_mean(key, _field_names(info)), True)
    if got := _GOT.match(text):
        return Explained(path, f"expected {_a(got['want'], words)}, got {shown(value, words)}")
    if bound := _BOUND.match(text):
        limit = bound["limit"]
        return Explained(path, f"expected {_a(bound['want'], words)} {bound['op']} {limit}, got {shown(value, words)}")
    if length := _LENGTH.match(text):
        return Explained(path, _length_problem(length, value, words))
    if _CHOICE.match(text):
        return Explained(path, _choice_problem(value, info))
    problem = re.sub(r"`(\w+)`", lambda m: _a(m[1], words), text)
    return Explained(path, problem[:1].lower() + problem[1:])


def did_you_mean(given: str, known: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``known`` to ``given``, or nothing."""
    close = closest(given, known)
    return f" (did you mean '{close}'?)" if close is not None else ""


def closest(given: str, known: Iterable[str]) -> str | None:
    """The one of ``known`` closest to ``given``, if any is close enough to be a typo of it."""
    close = difflib.get_close_matches(given, list(known), n=1, cutoff=0.6)
    return close[0] if close else None


def shown(value: Any, words: Words = MESSAGE_WORDS) -> str:
    """A value as an error text shows it: ``the string 'maybe'``, ``the integer 300``, ``a list``."""
    if value is None:
        return "nothing"
    if isinstance(value, bool):
        return f"the bool {str(value).lower()}"
    if isinstance(value, str):
        text = repr(value if len(value) <= 40 else value[:37] + "...")
        return f"the string {text}"
    if isinstance(value, int):
        return f"the integer {value}"
    if isinstance(value, float):
        return f"the number {value!r}"
    if isinstance(value, (list, tuple)):
        return words.array
    if isinstance(value, Mapping):
        return words.mapping
    return f"a {type(value).__name__}"


# --------------------------------------------------------------------------- helpers


def _a(name: str, words: Words) -> str:
    return {
        "bool": "a bool",
        "int": "an integer",
        "float": "a number",
        "str": "a string",
        "bytes": "bytes (a list of integers from 0 to 255)",
        "array": words.array,
        "object": words.mapping,
        "null": "nothing",
    }.get(name, name)


def _steps(path: str) -> list[str | int]:
    return [key if key else (int(index) if index.isdigit() else index) for key, index in _STEP.findall(path)]


def _join(steps: list[str | int]) -> str:
    out = ""
    for step in steps:
        out += f"[{step}]" if isinstance(step, int) else (f".{step}" if out else str(step))
    return out


def _unwrap(info: mi.Type, value: Any) -> mi.Type:
    """The member of a union (Optional, a tagged union) that ``value`` is meant for."""
    while isinstance(info, mi.UnionType):
        members = [t for t in info.types if not isinstance(t, mi.NoneType)]
        tagged = [t for t in members if isinstance(t, mi.StructType) and t.tag_field]
        if tagged and isinstance(value, Mapping):
            tag = value.get(tagged[0].tag_field)
            members = [t for t in tagged if t.tag == tag] or members
        if len(members) != 1:
            return info
        info = members[0]
    return info


def _child(value: Any, info: mi.Type, step: str | int) -> tuple[Any, mi.Type]:
    child: Any = None
    if isinstance(value, Mapping):
        child = value.get(step)
    elif isinstance(value, (list, tuple)) and isinstance(step, int) and step < len(value):
        child = value[step]
    if isinstance(info, mi.UnionType):  # a tagged union whose tag matched none of its members
        return child, info if any(getattr(t, "tag_field", None) == step for t in info.types) else mi.AnyType()
    if isinstance(info, mi.StructType):
        fields = {f.encode_name: f.type for f in info.fields}
        if info.tag_field == step:
            return child, mi.LiteralType(values=(info.tag,))
        return child, _unwrap(fields.get(str(step), mi.AnyType()), child)
    if isinstance(info, (mi.ListType, mi.SetType, mi.FrozenSetType, mi.VarTupleType)):
        return child, _unwrap(info.item_type, child)
    if isinstance(info, mi.TupleType) and isinstance(step, int) and step < len(info.item_types):
        return child, _unwrap(info.item_types[step], child)
    if isinstance(info, mi.DictType):
        return child, _unwrap(info.value_type, child)
    return child, mi.AnyType()


def _failing_key(value: Any, info: mi.Type) -> str:
    if isinstance(value, Mapping) and isinstance(info, mi.DictType):
        for key, item in value.items():
            try:
                msgspec.convert(item, _python_type(info.value_type))
            except (msgspec.ValidationError, TypeError):
                return str(key)
    return "..."


def _python_type(info: mi.Type) -> Any:
    if isinstance(info, mi.StructType):
        return info.cls
    return Any


def _field_names(info: mi.Type) -> list[str]:
    if isinstance(info, mi.StructType):
        return [f.encode_name for f in info.fields]
    return []


def _choices(info: mi.Type) -> list[str]:
    if isinstance(info, mi.EnumType):
        return [str(member.value) for member in info.cls]
    if isinstance(info, mi.LiteralType):
        return [str(value) for value in info.values]
    if isinstance(info, mi.UnionType):  # a tagged union's tags
        return [str(t.tag) for t in info.types if isinstance(t, mi.StructType) and t.tag is not None]
    return []


def _choice_problem(value: Any, info: mi.Type) -> str:
    choices = _choices(info)
    given = value.value if isinstance(value, enum.Enum) else value
    if not choices:
        return f"{given!r} is not a valid value"
    return f"{given!r} is not one of {', '.join(choices)}" + did_you_mean(str(given), choices)


def _length_problem(length: re.Match[str], value: Any, words: Words) -> str:
    op = (length["op"] or "").strip()
    n = int(length["n"])
    what = ("character" if length["want"] == "str" else "item") + ("" if n == 1 else "s")
    size = len(value) if isinstance(value, (str, list, tuple, Mapping)) else None
    got = f", got {size}" if size is not None else ""
    if not op:
        return f"expected {words.array} of {n} {what}{got}"
    return f"expected {_OPS[op]} {n} {what}{got}"
