"""``rclpy.parameter``: actors' Parameter, and rclpy's helpers for parameter values and files."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from actors.codec import load_yaml
from actors.params import PARAMETER_SEPARATOR_STRING, Parameter, ParameterType, value_from_msg, value_to_msg
from actors.rosargs import load_params_file
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

parameter_value_to_python = value_from_msg


def get_parameter_value(string_value: str) -> ParameterValue:
    """A ParameterValue from text, read as YAML (``"2"`` is an int); text that is not YAML stays text."""
    try:
        value = load_yaml(string_value)
        return value_to_msg(value)
    except ValueError:
        return value_to_msg(string_value)


def parameter_dict_from_yaml_file(
    parameter_file: str | Path,
    use_wildcard: bool = False,
    target_nodes: Sequence[str] | None = None,
    namespace: str = "",
) -> dict[str, ParameterMsg]:
    """The parameters of a ROS parameter file, as ``{name: rcl_interfaces/msg/Parameter}``.

    All nodes' parameters unless ``target_nodes`` names some (the ``/**`` ones
    too with ``use_wildcard``); names get ``namespace.`` in front.  Raises
    RuntimeError for a named node the file lacks or a file without parameters,
    and RosArgsError for a malformed file.
    """
    rules = load_params_file(parameter_file)
    wanted = None if target_nodes is None else {_key(name) for name in target_nodes}
    if wanted is not None:
        missing = sorted(wanted - {rule.node_key for rule in rules})
        if missing:
            raise RuntimeError(
                f"Param file does not contain parameters for {missing}, only for nodes: "
                f"{sorted({rule.node_key for rule in rules})}"
            )
    values: dict[str, Any] = {}
    for rule in rules:
        if wanted is None or rule.node_key in wanted or (use_wildcard and rule.node_key == "/**"):
            values.update(rule.values)
    if not values:
        raise RuntimeError("Param file does not contain any valid parameters")
    prefix = f"{namespace}{PARAMETER_SEPARATOR_STRING}" if namespace else ""
    return {prefix + name: Parameter(prefix + name, value=value).to_parameter_msg() for name, value in values.items()}


def _key(node: str) -> str:
    return node if node.startswith("/") else "/" + node
