"""``rclpy.parameter``: actors' Parameter, and rclpy's helpers for parameter values and files."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from actors.codec import load_yaml
from actors.ros.parameter import TYPES
from actors.ros.parameter_store import (
    PARAMETER_SEPARATOR_STRING,
    Parameter,
    ParameterType,
    value_from_msg,
    value_to_msg,
)
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.msg import ParameterValue

__all__ = [
    "Parameter",
    "ParameterType",
    "PARAMETER_SEPARATOR_STRING",
    "get_parameter_value",
    "parameter_value_to_python",
    "parameter_dict_from_yaml_file",
]

# A list read from text is typed by what all its items are, checked in this order (an empty list
# passes the first check, so "[]" is a BOOL_ARRAY, as rclpy reads it).
_LIST_TYPES = (
    (bool, ParameterType.BOOL_ARRAY),
    (int, ParameterType.INTEGER_ARRAY),
    (float, ParameterType.DOUBLE_ARRAY),
    (str, ParameterType.STRING_ARRAY),
)


def get_parameter_value(string_value: str) -> ParameterValue:
    """A ParameterValue guessed from text read as YAML, as rclpy guesses it.

    ``"2"`` is an INTEGER, ``"[1, 2]"`` an INTEGER_ARRAY, ``"[]"`` an empty
    BOOL_ARRAY.  Everything else stays the text itself, a STRING: text YAML
    cannot read, text YAML reads as nothing (``""``, ``" "``, ``"null"``), a
    list of mixed items, a mapping.
    """
    try:
        value = load_yaml(string_value)
    except ValueError:
        value = string_value
    if isinstance(value, (bool, int, float)):
        return value_to_msg(value)
    if isinstance(value, list):
        for item_type, list_type in _LIST_TYPES:
            if all(isinstance(item, item_type) for item in value):
                return value_to_msg(value, list_type)
    return value_to_msg(value if isinstance(value, str) else string_value, ParameterType.STRING)


def parameter_value_to_python(parameter_value: ParameterValue) -> Any:
    """The Python value a ParameterValue holds, arrays as lists (a BYTE_ARRAY's items one-byte bytes).

    None for NOT_SET; RuntimeError for a ``type`` that is no parameter type.
    """
    if parameter_value.type not in TYPES:
        raise RuntimeError(f"unexpected parameter type {parameter_value.type}")
    value = value_from_msg(parameter_value)
    if isinstance(value, (bytes, bytearray)):  # rclpy's byte[] items are one-byte bytes
        return [value[i : i + 1] for i in range(len(value))]
    return list(value) if parameter_value.type >= ParameterType.BYTE_ARRAY else value


def parameter_dict_from_yaml_file(
    parameter_file: str | Path,
    use_wildcard: bool = False,
    target_nodes: Sequence[str] | None = None,
    namespace: str = "",
) -> dict[str, ParameterMsg]:
    """The parameters a ROS parameter file holds for ``target_nodes``, as ``{name: Parameter msg}``.

    As rclpy's: ``/**`` comes first with ``use_wildcard``; a target node is
    looked up by its absolute name, by its bare name (in the root namespace) and
    under a namespace key; nested names are joined with ``.`` and prefixed with
    ``namespace`` as given.  Raises RuntimeError when nothing matched (rclpy
    reads no node at all when ``target_nodes`` is empty) or a node's entry has
    no ``ros__parameters``, and OSError or ValueError for a file that cannot be
    read or is not YAML.
    """
    data = load_yaml(Path(parameter_file).read_text(encoding="utf-8")) or {}
    found: dict[str, Any] = {}
    if use_wildcard and "/**" in data:
        found.update(_node_parameters(data["/**"], "wildcard(/**)"))
    for node in target_nodes or ():
        if not node:
            continue
        absolute = node if node.startswith("/") else "/" + node
        namespace_key, _, base = absolute.rpartition("/")
        if absolute in data:
            found.update(_node_parameters(data[absolute], f"node {absolute}"))
        if not namespace_key and base in data:
            found.update(_node_parameters(data[base], f"node {base}"))
        elif namespace_key in data and base in data[namespace_key]:
            found.update(_node_parameters(data[namespace_key][base], f"namespace {namespace_key} node {base}"))
    if not found:
        raise RuntimeError("Param file does not contain any valid parameters")
    return _unpacked(namespace, found)


def _node_parameters(entry: Any, what: str) -> dict[str, Any]:
    if not isinstance(entry, dict) or "ros__parameters" not in entry:
        raise RuntimeError(f"YAML file is not a valid ROS parameter file for {what}")
    return dict(entry["ros__parameters"])


def _unpacked(prefix: str, values: dict[str, Any]) -> dict[str, ParameterMsg]:
    params: dict[str, ParameterMsg] = {}
    for name, value in values.items():
        full = prefix + name
        if isinstance(value, dict):
            params.update(_unpacked(full + PARAMETER_SEPARATOR_STRING, value))
        else:
            params[full] = ParameterMsg(name=full, value=get_parameter_value(str(value)))
    return params
