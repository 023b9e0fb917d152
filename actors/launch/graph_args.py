"""A graph file's launch arguments: ``[args]``, ``$(var name)`` in its values, and their listing.

An argument is declared with its default (``speed = 0.2``), or as a table
(``speed = { default = 0.2, description = "...", choices = [0.1, 0.2] }``;
no ``default`` makes it required).  A value that is ``$(var name)`` and
nothing else takes the argument's value with its type: the default's TOML
type, or a command line's ``name:=value`` read as YAML, as launch_ros reads
parameter values.  Inside a longer string it is text, as launch substitutes it.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import msgspec

from actors.codec import load_yaml
from actors.core.explain import did_you_mean
from actors.errors import GraphFileError

__all__ = ["Argument", "declared_arguments", "argument_values", "substitute", "format_arguments"]

_VAR = re.compile(r"\$\((\w+)\s+([^()\s]+)\s*\)")
_ANY = re.compile(r"\$\((\S*)")


class Argument(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """One declared argument: its default (None: required), what it is for, the values it may take."""

    default: Any = None
    description: str = "no description given"
    choices: list[Any] | None = None

    def default_text(self) -> str | None:
        """The default as ``--show-args`` shows it (text, quoted, as launch describes text)."""
        return None if self.default is None else repr(_text(self.default))


def declared_arguments(table: Any, where: str) -> dict[str, Argument]:
    """The ``[args]`` table as arguments; GraphFileError naming the key for a bad one."""
    if not isinstance(table, dict):
        raise GraphFileError(f"{where}: args: expected a table of name = default, got {type(table).__name__}")
    declared = {}
    for name, spec in table.items():
        if not re.fullmatch(r"[A-Za-z_]\w*", name):
            raise GraphFileError(f"{where}: args.{name}: an argument's name is letters, digits and _")
        try:
            arg = msgspec.convert(spec, Argument) if isinstance(spec, dict) else Argument(default=spec)
        except msgspec.ValidationError as exc:
            raise GraphFileError(f"{where}: args.{name}: {exc}") from None
        if arg.choices is not None and arg.default is not None and arg.default not in arg.choices:
            raise GraphFileError(f"{where}: args.{name}: the default {arg.default!r} is not one of {arg.choices}")
        declared[name] = arg
    return declared


def argument_values(declared: Mapping[str, Argument], given: Mapping[str, Any], where: str) -> dict[str, Any]:
    """Every declared argument's value: ``given``'s (text from a command line is read as YAML), else
    its default.  GraphFileError for an argument not declared, one required and not given, or a
    value not among the choices."""
    for name in given:
        if name not in declared:
            known = ", ".join(declared) or "none"
            raise GraphFileError(f"{where}: no argument {name!r}{did_you_mean(name, declared)} (declared: {known})")
    values = {}
    for name, arg in declared.items():
        if name in given:
            value = given[name]
            if isinstance(value, str):
                value = _typed(value)
        elif arg.default is None:
            raise GraphFileError(f"{where}: argument {name!r} is required: give it as {name}:=VALUE")
        else:
            value = arg.default
        if arg.choices is not None and value not in arg.choices:
            raise GraphFileError(f"{where}: argument {name}: {value!r} is not one of {arg.choices}")
        values[name] = value
    return values


def _typed(text: str) -> Any:
    # As launch_ros reads a parameter's value; text YAML cannot read stays text.
    try:
        value = load_yaml(text)
    except ValueError:
        return text
    return text if value is None or isinstance(value, (dict, list)) else value


def substitute(data: Any, values: Mapping[str, Any], where: str, key: str = "") -> Any:
    """``data`` with every ``$(var name)`` in its strings replaced; GraphFileError naming the key of
    an unknown argument or of a substitution other than ``var``."""
    if isinstance(data, dict):
        return {k: substitute(v, values, where, f"{key}.{k}" if key else k) for k, v in data.items()}
    if isinstance(data, list):
        return [substitute(v, values, where, f"{key}[{i}]") for i, v in enumerate(data)]
    if not isinstance(data, str) or "$(" not in data:
        return data

    def value_of(match: re.Match[str]) -> Any:
        kind, name = match[1], match[2]
        if kind != "var":
            raise GraphFileError(f"{where}: {key}: $({kind} ...): a graph file substitutes $(var name) only")
        if name not in values:
            known = ", ".join(values) or "none: declare it in [args]"
            raise GraphFileError(
                f"{where}: {key}: no argument {name!r}{did_you_mean(name, values)} (declared: {known})"
            )
        return values[name]

    whole = _VAR.fullmatch(data)
    if whole is not None:
        return value_of(whole)
    text = _VAR.sub(lambda m: _text(value_of(m)), data)
    if (stray := _ANY.search(text)) is not None:
        raise GraphFileError(f"{where}: {key}: $({stray[1]}: expected $(var name)")
    return text


def _text(value: Any) -> str:
    return str(value).lower() if isinstance(value, bool) else str(value)  # as TOML and YAML spell them


def format_arguments(arguments: Iterable[tuple[str, str, str | None, Sequence[Any] | None]]) -> str:
    """``ros2 launch --show-args``'s listing of (name, description, default text or None, choices)."""
    lines = ["Arguments (pass arguments as '<name>:=<value>'):"]
    rows = list(arguments)
    if not rows:
        lines += ["", "  No arguments."]
    for name, description, default, choices in rows:
        lines += ["", f"    '{name}':", f"        {description}"]
        if choices:
            lines.append(f"        Valid choices are: {list(choices)}")
        lines.append(f"        (default: {default})" if default is not None else "        (required)")
    return "\n".join(lines)
