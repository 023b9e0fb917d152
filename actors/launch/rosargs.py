"""ROS command-line arguments (``--ros-args ...``) and parameter files, as rcl reads them.

::

    prog a b --ros-args -p speed:=0.5 -r chatter:=talk -r __node:=speaker \\
        --params-file params.yaml --log-level debug -- c

:func:`parse` splits ``argv`` into the program's own arguments (``prog a b c``)
and :class:`RosArgs`; :func:`remove_ros_args` keeps only the former, as
``rclpy.utilities.remove_ros_args`` does.  Rules take an optional node prefix
(``-p talker:speed:=0.5``, ``-r talker:chatter:=talk``) that limits them to the
node of that name; ``__node`` (or ``__name``) and ``__ns`` rename a node or move
it.  Values after ``:=`` of ``-p`` are YAML, as in rcl: ``-p 'ids:=[1, 2]'``.

A parameter file holds, per node, ``ros__parameters`` (nested names joined
with ``.``)::

    /**:                       # every node
      ros__parameters: {use_sim_time: false}
    talker:                    # the node /talker
      ros__parameters: {speed: 0.5, limits: {max: 2.0}}
    /robot1:                   # namespaces as nested keys or in the key: /robot1/driver
      driver:
        ros__parameters: {wheel_radius: 0.033}

A node key matches a node's full name as rclpy matches it: a missing leading
``/`` is added, ``/*`` stands for one name part and ``/**`` for any number.
Later rules win over earlier ones (argument order, then file order).  Every
problem raises :class:`~actors.errors.RosArgsError` naming the argument or the
file and key.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from actors.codec import load_yaml
from actors.errors import InvalidNameError, RosArgsError
from actors.ros.log import LEVELS
from actors.ros.names import expand, normalize_namespace, validate_node_name

__all__ = [
    "ROS_ARGS",
    "Remap",
    "ParamRule",
    "RosArgs",
    "NodeArgs",
    "parse",
    "remove_ros_args",
    "load_params_file",
    "parameters_for",
    "values_for",
    "node_key_matches",
]

ROS_ARGS = "--ros-args"
_END = "--"
_LOG_LEVELS = {**LEVELS, "unset": 0}
_ENCLAVE = ("-e", "--enclave")
_IGNORED_WITH_VALUE = ("--log-file-name", "--log-config-file")
_FLAGS = {f"--{state}-{what}-logs" for state in ("enable", "disable") for what in ("stdout", "rosout", "external-lib")}


@dataclass(frozen=True)
class Remap:
    """``[node:]source:=target``: a name remapping, limited to one node when ``node`` is set."""

    source: str
    target: str
    node: str | None = None


@dataclass(frozen=True)
class ParamRule:
    """Parameter values for the nodes whose full name matches ``node_key`` (``/**``: all)."""

    node_key: str
    values: Mapping[str, Any]


@dataclass(frozen=True)
class NodeArgs:
    """What the ROS arguments make of one node: its name, namespace, remappings and parameters."""

    name: str
    namespace: str
    remap: dict[str, str]
    params: dict[str, Any]


@dataclass(frozen=True)
class RosArgs:
    """The ROS arguments of a command line, in the order given."""

    remaps: tuple[Remap, ...] = ()
    params: tuple[ParamRule, ...] = ()
    log_levels: dict[str, int] = field(default_factory=dict)  # "" is the default level
    enclave: str | None = None
    log_outputs: dict[str, bool] = field(default_factory=dict)  # --enable/--disable-<what>-logs: what -> on

    def logs_to(self, what: str) -> bool:
        """Whether logs go to ``what`` (``stdout``, ``rosout``, ``external-lib``): on unless disabled."""
        return self.log_outputs.get(what, True)

    @property
    def log_level(self) -> int | None:
        """The default logging level set by ``--log-level LEVEL``, if any."""
        return self.log_levels.get("")

    def __add__(self, other: RosArgs) -> RosArgs:
        """These rules followed by ``other``'s (which win where they overlap)."""
        return RosArgs(
            self.remaps + other.remaps,
            self.params + other.params,
            {**self.log_levels, **other.log_levels},
            other.enclave or self.enclave,
            {**self.log_outputs, **other.log_outputs},
        )

    def for_node(self, name: str, namespace: str | None) -> NodeArgs:
        """Name, namespace, remappings and parameters of the node created as ``name`` in ``namespace``.

        ``__node``/``__ns`` rules rename and move it; remappings apply when global
        or prefixed with the node's (original) name, the first matching rule of a
        name winning; parameters are matched against the final full name.
        """
        remap: dict[str, str] = {}
        for rule in self.remaps:
            if rule.node is None or rule.node == name:
                # As in rcl, the first rule that matches a name is the one applied.
                source = "__node" if rule.source == "__name" else rule.source
                remap.setdefault(source, rule.target)
        final_name = remap.pop("__node", name)
        ns = normalize_namespace(remap.pop("__ns", namespace))
        fqn = f"/{final_name}" if ns == "/" else f"{ns}/{final_name}"
        return NodeArgs(final_name, ns, remap, values_for(self.params, fqn))


def parse(argv: Sequence[str]) -> tuple[RosArgs, list[str]]:
    """Split ``argv`` into its ROS arguments and the rest (the program's own, in order).

    Raises RosArgsError for a flag without its value, a malformed rule, an
    unreadable parameter file, or an unknown flag inside ``--ros-args``.
    """
    remaps: list[Remap] = []
    params: list[ParamRule] = []
    levels: dict[str, int] = {}
    enclave: str | None = None
    outputs: dict[str, bool] = {}
    rest: list[str] = []
    unknown: list[str] = []
    in_ros = False
    args = list(argv)
    i = 0
    while i < len(args):
        arg = args[i]
        i += 1
        if not in_ros:
            if arg == ROS_ARGS:
                in_ros = True
            else:
                rest.append(arg)
            continue
        if arg == ROS_ARGS:
            continue
        if arg == _END:
            in_ros = False
            continue
        if arg in _FLAGS:
            state, what = arg[2:-5].split("-", 1)  # --enable-rosout-logs -> enable, rosout
            outputs[what] = state == "enable"
            continue
        takes_value = arg in ("-p", "--param", "-r", "--remap", "--params-file", "--log-level")
        if not (takes_value or arg in _ENCLAVE or arg in _IGNORED_WITH_VALUE):
            unknown.append(arg)
            continue
        if i >= len(args):
            raise RosArgsError(f"--ros-args: {arg} needs a value, got nothing after it")
        value = args[i]
        i += 1
        if arg in ("-p", "--param"):
            params.append(_param_rule(arg, value))
        elif arg in ("-r", "--remap"):
            remaps.append(_remap_rule(arg, value))
        elif arg == "--params-file":
            params.extend(load_params_file(value))
        elif arg == "--log-level":
            logger, level = _log_level(value)
            levels[logger] = level
        elif arg in _ENCLAVE:
            enclave = value
    if unknown:
        raise RosArgsError(f"--ros-args: unknown ROS arguments {unknown}")
    return RosArgs(tuple(remaps), tuple(params), levels, enclave, outputs), rest


def remove_ros_args(argv: Sequence[str]) -> list[str]:
    """``argv`` without its ``--ros-args ... [--]`` sections; RosArgsError if those are malformed."""
    return parse(argv)[1]


def _split_rule(flag: str, text: str) -> tuple[str | None, str, str]:
    head, sep, value = text.partition(":=")
    if not sep or not head:
        raise RosArgsError(f"--ros-args: {flag} {text!r}: expected [node:]name:=value")
    node, colon, name = head.rpartition(":")
    if not colon:
        return None, name, value
    if not name:
        raise RosArgsError(f"--ros-args: {flag} {text!r}: expected [node:]name:=value")
    try:
        validate_node_name(node)
    except InvalidNameError as exc:
        raise RosArgsError(f"--ros-args: {flag} {text!r}: {exc}") from None
    return node, name, value


def _param_rule(flag: str, text: str) -> ParamRule:
    node, name, raw = _split_rule(flag, text)
    try:
        value = load_yaml(raw) if raw.strip() else ""
        value = _param_value(value, name)
    except ValueError as exc:
        raise RosArgsError(f"--ros-args: {flag} {text!r}: {exc}") from None
    return ParamRule(f"/{node}" if node else "/**", {name: value})


def _remap_rule(flag: str, text: str) -> Remap:
    node, source, target = _split_rule(flag, text)
    try:
        if source in ("__node", "__name"):
            validate_node_name(target)
        elif source == "__ns":
            target = normalize_namespace(target)
        else:
            expand(source, "/", "node", what="remap source")
            expand(target, "/", "node", what="remap target")
    except InvalidNameError as exc:
        raise RosArgsError(f"--ros-args: {flag} {text!r}: {exc}") from None
    return Remap(source, target, node)


def _log_level(text: str) -> tuple[str, int]:
    logger, sep, level = text.rpartition(":=")
    if not sep:
        logger, level = "", text
    number = _LOG_LEVELS.get(level.lower())
    if number is None:
        raise RosArgsError(
            f"--ros-args: --log-level {text!r}: unknown level {level!r} (one of {', '.join(sorted(_LOG_LEVELS))})"
        )
    return logger, number


def _param_value(value: Any, where: str) -> Any:
    """A YAML value as a parameter holds it; ValueError for one no parameter can hold."""
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list):
        if not value:
            raise ValueError(f"{where}: an empty list has no type a parameter could take")
        kinds = {bool if isinstance(v, bool) else type(v) for v in value}
        if len(kinds) == 1 and kinds <= {bool, int, float, str}:
            return value
        raise ValueError(f"{where}: a list parameter holds one type (bool, int, float or str), got {value!r}")
    raise ValueError(f"{where}: a parameter holds bool, int, float, str or a list of one of them, got {value!r}")


# -- parameter files ---------------------------------------------------------------


def load_params_file(path: str | Path) -> list[ParamRule]:
    """The rules of a ROS parameter file, in file order.

    Raises RosArgsError naming the file and the key path for a file that
    cannot be read, is not YAML, or is not shaped as ROS expects.
    """
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise RosArgsError(f"{path}: cannot read the parameter file: {exc.strerror or exc}") from None
    try:
        data = load_yaml(text, merge_repeated_keys=True)
    except ValueError as exc:
        raise RosArgsError(f"{path}: not valid YAML: {exc}") from None
    if data is None:
        return []
    if not isinstance(data, dict):
        raise RosArgsError(f"{path}: expected node names as keys at the top, got {type(data).__name__}")
    rules: list[ParamRule] = []
    _collect(path, data, [], rules)
    return rules


def _collect(path: str | Path, table: dict[Any, Any], keys: list[str], rules: list[ParamRule]) -> None:
    for key, value in table.items():
        here = [*keys, str(key)]
        where = "/".join(here)
        if key == "ros__parameters":
            if not keys:
                raise RosArgsError(f"{path}: ros__parameters: needs a node name above it")
            if not isinstance(value, dict):
                raise RosArgsError(f"{path}: {where}: expected a table of parameters")
            rules.append(ParamRule(_node_key(path, keys), _flatten(path, where, value, "")))
        elif isinstance(value, dict):
            _collect(path, value, here, rules)
        else:
            raise RosArgsError(
                f"{path}: {where}: expected a namespace or a node holding ros__parameters, got {value!r}"
            )


def _node_key(path: str | Path, keys: list[str]) -> str:
    key = "/".join(k.strip("/") for k in keys)
    key = "/" + key
    for part in key[1:].split("/"):
        if part in ("*", "**"):
            continue
        try:
            validate_node_name(part)
        except InvalidNameError:
            raise RosArgsError(f"{path}: {'/'.join(keys)}: {part!r} is not a valid node name or namespace") from None
    return key


def _flatten(path: str | Path, where: str, table: dict[Any, Any], prefix: str) -> dict[str, Any]:
    values: dict[str, Any] = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            values.update(_flatten(path, f"{where}/{key}", value, f"{name}."))
            continue
        try:
            values[name] = _param_value(value, name)
        except ValueError as exc:
            raise RosArgsError(f"{path}: {where}: {exc}") from None
    return values


_REGEX_CACHE: dict[str, re.Pattern[str]] = {}


def node_key_matches(node_key: str, node_fqn: str) -> bool:
    """Whether a parameter file's node key (``talker``, ``/ns/*``, ``/**``) names the node ``node_fqn``."""
    pattern = _REGEX_CACHE.get(node_key)
    if pattern is None:
        key = node_key if node_key.startswith("/") else "/" + node_key
        parts = re.split(r"(/\*\*|/\*)", key)
        regex = "".join(r"(/\w+)*" if p == "/**" else r"(/\w+)" if p == "/*" else re.escape(p) for p in parts)
        pattern = _REGEX_CACHE[node_key] = re.compile(regex)
    return pattern.fullmatch(node_fqn) is not None


def parameters_for(path: str | Path, node_fqn: str) -> dict[str, Any]:
    """The parameters a ROS parameter file gives the node ``node_fqn`` (later keys win)."""
    return values_for(load_params_file(path), node_fqn)


def values_for(rules: Iterable[ParamRule], node_fqn: str) -> dict[str, Any]:
    """The values ``rules`` give the node ``node_fqn``, later rules winning."""
    values: dict[str, Any] = {}
    for rule in rules:
        if node_key_matches(rule.node_key, node_fqn):
            values.update(rule.values)
    return values
