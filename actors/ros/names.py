"""ROS 2 name rules: validating node names and namespaces, resolving topic and service names."""

from __future__ import annotations

import re
from collections.abc import Mapping

from actors.errors import (
    InvalidNameError,
    InvalidNamespaceException,
    InvalidNodeNameException,
    InvalidServiceNameException,
    InvalidTopicNameException,
)

__all__ = [
    "validate_node_name",
    "normalize_namespace",
    "fully_qualified",
    "expand",
    "is_hidden",
    "is_hidden_name",
    "Resolver",
]

_NODE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_ABSOLUTE = re.compile(r"(?:/[A-Za-z_][A-Za-z0-9_]*)+\Z")
# Names already found valid: with any valid namespace and node name they expand to a valid
# name, so the nodes of a large graph (which share their topic and service names) check
# each name once, not once per node.
_VALID_NAMES: set[str] = set()
# The error raised for each kind of name (rclpy's exception names); others get InvalidNameError.
_ERRORS: dict[str, type[InvalidNameError]] = {
    "namespace": InvalidNamespaceException,
    "topic name": InvalidTopicNameException,
    "service name": InvalidServiceNameException,
}


def _invalid(what: str, text: str) -> InvalidNameError:
    return _ERRORS.get(what, InvalidNameError)(text)


def validate_node_name(name: str) -> str:
    """Return ``name`` if it is a valid ROS node name, else raise InvalidNameError."""
    if not isinstance(name, str) or not _NODE_NAME.match(name):
        if not name:
            rule = "must not be empty"
        elif isinstance(name, str) and re.fullmatch(r"[A-Za-z0-9_]+", name):
            rule = "must not start with a number"
        else:
            rule = "must not contain characters other than alphanumerics or '_'"
        raise InvalidNodeNameException(f"invalid node name {name!r}: a node name {rule}")
    return name


def is_hidden(name: str) -> bool:
    """Whether a node name is hidden, as in ROS: its last part starts with ``_``."""
    return name.rsplit("/", 1)[-1].startswith("_")


def is_hidden_name(name: str) -> bool:
    """Whether a topic, service or action name is hidden, as ROS tools judge it: a part starts with ``_``.

    ``/fibonacci/_action/feedback`` is hidden: ``topic list`` leaves it out unless asked.
    """
    return any(part.startswith("_") for part in name.split("/"))


def _check_absolute(name: str, what: str) -> str:
    if name == "/" or _ABSOLUTE.match(name):
        return name  # one regex for the usual case; the loop below finds the culprit
    if not name.startswith("/"):
        raise _invalid(what, f"{what} {name!r} is invalid: it must be absolute (start with '/')")
    for token in name[1:].split("/"):
        if not _TOKEN.match(token):
            # rcl's words for each rule, which rclpy's users (and tests) match on
            if not token:
                rule = "must not contain repeated '/' or end with '/'"
            elif re.fullmatch(r"[A-Za-z0-9_]+", token):
                rule = "must not start with a number in any part"
            else:
                rule = "must not contain characters other than alphanumerics, '_' or '/'"
            raise _invalid(what, f"{what} {name!r} is invalid: a {what} {rule}")
    return name


def normalize_namespace(namespace: str | None) -> str:
    """``""``/``None`` -> ``"/"``; ``"robot1"`` -> ``"/robot1"``; validated, no trailing slash."""
    if not namespace:
        return "/"
    if not namespace.startswith("/"):
        namespace = "/" + namespace
    if len(namespace) > 1 and namespace.endswith("/"):
        namespace = namespace[:-1]
    return _check_absolute(namespace, "namespace")


def fully_qualified(namespace: str, name: str) -> str:
    """The node's full name: ``/ns/name``."""
    return f"/{name}" if namespace == "/" else f"{namespace}/{name}"


def expand(name: str, namespace: str, node_name: str, *, what: str = "topic name") -> str:
    """Expand a relative, absolute or ``~/private`` name to an absolute one, by ROS rules.

    ``namespace`` and ``node_name`` must be valid already (a node's are).
    """
    if name in _VALID_NAMES:
        return _joined(name, namespace, node_name)
    if not isinstance(name, str):
        raise TypeError(f"a {what} must be a str, got {name!r}")
    if not name:
        raise _invalid(what, f"{what} {name!r} is invalid: it must not be empty")
    if "{" in name:
        name = _substituted(name, namespace, node_name, what)
    full = _joined(name, namespace, node_name)
    if full != "/" and full.endswith("/"):
        raise _invalid(what, f"{what} {name!r} is invalid: it must not end with '/'")
    _check_absolute(full, what)
    if len(_VALID_NAMES) < 10_000:
        _VALID_NAMES.add(name)
    return full


def _substituted(name: str, namespace: str, node_name: str, what: str) -> str:
    # rcl's substitutions: {node} is the node's name, {ns} and {namespace} its namespace.
    values = {"node": node_name, "ns": namespace, "namespace": namespace}

    def value(match: re.Match[str]) -> str:
        if match.group(1) not in values:
            raise _invalid(what, f"{what} {name!r} is invalid: unknown substitution: {match.group(0)}")
        return values[match.group(1)]

    return re.sub(r"\{([^{}]*)\}", value, name).replace("//", "/")


def _joined(name: str, namespace: str, node_name: str) -> str:
    if name == "~" or name.startswith("~/"):
        return fully_qualified(namespace, node_name) + name[1:]
    if name.startswith("/"):
        return name
    return (namespace if namespace != "/" else "") + "/" + name


class Resolver:
    """Resolves one node's topic and service names: expansion, then remapping.

    ``remap`` maps names (relative, absolute or private, expanded like the names
    they match) to replacements, as ``--ros-args -r from:=to`` does.
    """

    __slots__ = ("namespace", "node_name", "_remap")

    def __init__(self, namespace: str, node_name: str, remap: Mapping[str, str] | None) -> None:
        self.namespace = namespace
        self.node_name = node_name
        self._remap = {
            expand(src, namespace, node_name, what="remap source"): expand(
                dst, namespace, node_name, what="remap target"
            )
            for src, dst in (remap or {}).items()
        }

    def resolve(self, name: str, *, what: str = "topic name") -> str:
        """The absolute, remapped name for ``name``."""
        full = expand(name, self.namespace, self.node_name, what=what)
        return self._remap.get(full, full)
