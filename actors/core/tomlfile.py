"""TOML files decoded into msgspec Structs, with errors that name the file and the key path."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, TypeVar

import msgspec

from actors.core.explain import FILE_WORDS, explain
from actors.errors import ActorsError

__all__ = ["MAX_SECONDS", "load_toml", "read_toml", "convert_toml"]

T = TypeVar("T")

MAX_SECONDS = 1e9
"""The longest duration, period or delay a file may give, in seconds (about 31 years).

Beyond it the clock's float loses the precision timers need (and ``inf`` or
``1e308`` would make a virtual clock stand still): such a value is a typo.
"""


def load_toml(path: str | Path, type_: type[T], error: type[ActorsError]) -> T:
    """Read ``path`` as TOML and decode it into ``type_``.

    Raises ``error`` with one line, ``<path>: <key path>: <problem>``, for a
    missing file, text that is not UTF-8, a TOML syntax error, values nested
    too deeply to read, an unknown or missing key (with the nearest known one),
    a value of the wrong type, out of range or not among the valid choices (listed).
    """
    return convert_toml(read_toml(path, error), type_, path, error)


def read_toml(path: str | Path, error: type[ActorsError]) -> dict[str, Any]:
    """Read ``path`` as TOML into plain values (the first half of :func:`load_toml`)."""
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise error(f"{path}: cannot read: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise error(
            f"{path}: not UTF-8 text (byte {exc.start} is {raw[exc.start]:#04x}); TOML files are UTF-8"
        ) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: TOML syntax error: {exc}") from None
    except RecursionError:
        raise error(f"{path}: values nested too deeply to read") from None


def convert_toml(data: Any, type_: type[T], path: str | Path, error: type[ActorsError]) -> T:
    """Decode plain values read from ``path`` into ``type_`` (the second half of :func:`load_toml`)."""
    try:
        return msgspec.convert(data, type_, strict=True)
    except msgspec.ValidationError as exc:
        key, problem, _ = explain(exc, type_, data, FILE_WORDS)
        raise error(f"{path}: {key or '(top level)'}: {problem}") from None
