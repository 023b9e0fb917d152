"""TOML files decoded into msgspec Structs, with errors that name the file and the key path."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any, TypeVar

import msgspec

from actors.errors import ActorsError

__all__ = ["load_toml", "key_path_error"]

T = TypeVar("T")

# msgspec says e.g. "Object contains unknown field `foo` - at `$.nodes[0]`".
_AT = re.compile(r"^(?P<problem>.*?)(?: - at `\$(?P<path>[^`]*)`)?$", re.S)
_FIELD = re.compile(r"^Object (?P<what>contains unknown|missing required) field `(?P<key>[^`]+)`$")
_LENGTH = re.compile(r"^Expected `array` of length (?P<want>\d+), got (?P<got>\d+)$")
# msgspec's type names in the words a TOML file uses.
_TYPE_NAMES = {
    "float": "a number",
    "int": "an integer",
    "str": "a string",
    "bool": "a boolean",
    "array": "an array",
    "object": "a table",
    "null": "nothing",
}


def key_path_error(exc: msgspec.ValidationError) -> tuple[str, str]:
    """Split a msgspec validation error into ``(key path, problem)`` in TOML's words.

    ``"Object missing required field `use` - at `$.nodes[0]`"`` gives
    ``("nodes[0].use", "missing required key")``.
    """
    match = _AT.match(str(exc))
    assert match is not None  # the pattern matches any text
    problem, path = match["problem"], (match["path"] or "").lstrip(".")
    if field := _FIELD.match(problem):
        path = f"{path}.{field['key']}" if path else field["key"]
        problem = "unknown key" if field["what"] == "contains unknown" else "missing required key"
    elif length := _LENGTH.match(problem):
        problem = f"expected an array of {length['want']} numbers, got {length['got']} items"
    else:
        problem = re.sub(r"`(\w+)`", lambda m: _TYPE_NAMES.get(m[1], m[1]), problem)
    return path or "(top level)", problem[:1].lower() + problem[1:]


def load_toml(path: str | Path, type_: type[T], error: type[ActorsError]) -> T:
    """Read ``path`` as TOML and decode it into ``type_``.

    Raises ``error`` with one line, ``<path>: <key path>: <problem>``, for a
    missing file, a TOML syntax error, an unknown or missing key, or a value of
    the wrong type or out of range.
    """
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise error(f"{path}: cannot read: {exc.strerror or exc}") from None
    try:
        data: Any = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: TOML syntax error: {exc}") from None
    try:
        return msgspec.convert(data, type_, strict=True)
    except msgspec.ValidationError as exc:
        key, problem = key_path_error(exc)
        raise error(f"{path}: {key}: {problem}") from None
