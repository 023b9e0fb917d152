"""How the command line prints messages: rclpy's repr, and YAML as ``ros2 topic echo`` does."""

from __future__ import annotations

import functools
from array import array
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from actors.errors import ControlError

if TYPE_CHECKING:
    from actors.messages._fields import FieldLayout, MessageLayout

__all__ = ["ros_repr", "yaml_text", "csv_text", "parse_yaml", "field"]


def ros_repr(value: Any) -> str:
    """``value`` as rclpy's repr prints it: ``std_msgs.msg.Bool(data=True)``, nested alike."""
    name = getattr(type(value), "__ros_type__", None)
    if name is not None:
        fields = ", ".join(f"{f}={ros_repr(getattr(value, f))}" for f in value.__struct_fields__)
        return f"{name.replace('/', '.')}({fields})"
    if isinstance(value, (list, array)):  # a message's repr shows its array fields as lists
        return "[" + ", ".join(ros_repr(item) for item in value) + "]"
    return repr(value)


def yaml_text(
    value: Any,
    *,
    no_arr: bool = False,
    no_str: bool = False,
    truncate_length: int | None = None,
    flow_style: bool = False,
) -> str:
    """``value`` as YAML, block style unless ``flow_style``: a message as ``codec.to_yaml`` writes it.

    In a message, ``no_arr`` puts ``ros2 topic echo --no-arr``'s summary
    (``<sequence type: float, length: 360>``) in place of each array, and
    ``no_str`` its ``<string length: <N>>`` in place of each string; arrays and
    strings longer than ``truncate_length`` end in ``...`` after so many elements,
    as rosidl_runtime_py's ``message_to_yaml`` cuts them.
    """
    from actors import codec
    from actors.messages._fields import layout

    if hasattr(type(value), "__ros_type__"):
        if not (no_arr or no_str or truncate_length is not None or flow_style):
            return codec.to_yaml(value)
        data = _abridged(codec.to_builtins(value), layout(type(value)), no_arr, no_str, truncate_length)
    else:
        data = _cut(_plain(value), truncate_length)
    text = codec.dump_yaml(data, flow_style=flow_style)
    if isinstance(data, (dict, list)):
        return text
    return text.removesuffix("...\n")  # the end-of-document mark PyYAML adds after a bare scalar


def csv_text(value: Any, *, no_arr: bool = False, no_str: bool = False, truncate_length: int | None = None) -> str:
    """``value``'s fields, nested ones too, on one line separated by commas, as ``ros2 topic echo --csv``
    prints them (an array's elements beyond ``truncate_length`` become one ``...``)."""
    from actors import codec
    from actors.messages._fields import layout

    if hasattr(type(value), "__ros_type__"):
        value = _abridged(codec.to_builtins(value), layout(type(value)), no_arr, no_str, None)
    else:
        value = _plain(value)

    def one(item: Any) -> str:
        if isinstance(item, dict):
            return ",".join(one(v) for v in item.values())
        if isinstance(item, list):
            cut = item if truncate_length is None else item[:truncate_length]
            return ",".join([*(one(v) for v in cut), *(["..."] if len(cut) < len(item) else [])])
        if isinstance(item, str) and truncate_length is not None and len(item) > truncate_length:
            return item[:truncate_length] + "..."
        return str(item)

    return one(value)


# rosidl's names of the .msg primitives (what --no-arr prints), where they differ.
_IDL_NAMES = {"bool": "boolean", "byte": "octet", "char": "uint8", "float32": "float", "float64": "double"}


def _abridged(
    data: dict[str, Any], message: MessageLayout, no_arr: bool, no_str: bool, truncate_length: int | None
) -> dict[str, Any]:
    """``data`` (a message's builtins) with arrays and strings summarised or cut, nested messages too."""
    from actors.messages.idl import STRINGS

    def one(value: Any, field: FieldLayout) -> Any:
        if field.nested is not None:
            return _abridged(value, field.nested, no_arr, no_str, truncate_length)
        if no_str and field.type.base in STRINGS:
            return f"<string length: <{len(value)}>>"
        return _cut(value, truncate_length)

    for field in message.fields:
        if field.name not in data:
            continue  # rosidl's placeholder in a message without fields
        kind, value = field.type.array, data[field.name]
        if kind and no_arr:
            element = field.type.ros_type if field.type.is_nested else field.type.base
            element = _IDL_NAMES.get(element, element)
            data[field.name] = (
                f"<array type: {element}[{field.type.size}]>"
                if kind == "fixed"
                else f"<sequence type: {element}[{field.type.size}], length: {len(value)}>"
                if kind == "bounded"
                else f"<sequence type: {element}, length: {len(value)}>"
            )
        elif kind:
            data[field.name] = _cut_list(value, truncate_length, functools.partial(one, field=field))
        else:
            data[field.name] = one(value, field)
    return data


def _cut(value: Any, truncate_length: int | None) -> Any:
    """A string or list longer than ``truncate_length`` cut to it, with ``...`` after (lists: each item too)."""
    if truncate_length is None:
        return value
    if isinstance(value, str):
        return value[:truncate_length] + "..." if len(value) > truncate_length else value
    if isinstance(value, list):
        return _cut_list(value, truncate_length, lambda item: _cut(item, truncate_length))
    return value


def _cut_list(items: list[Any], truncate_length: int | None, each: Callable[[Any], Any]) -> list[Any]:
    if truncate_length is None or len(items) <= truncate_length:
        return [each(item) for item in items]
    return [*(each(item) for item in items[:truncate_length]), "..."]


def _plain(value: Any) -> Any:
    from actors import codec

    if hasattr(type(value), "__ros_type__"):
        return codec.to_builtins(value)
    if isinstance(value, (list, tuple, array)):
        return [_plain(item) for item in value]
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    return value


def parse_yaml(text: str, what: str) -> Any:
    """The value of a YAML ``text``; ControlError naming ``what`` when it is not YAML."""
    from actors import codec

    try:
        return codec.load_yaml(text)
    except ValueError as exc:
        raise ControlError(f"{what} {text!r} is not valid YAML: {exc}") from None


def field(msg: Any, path: str) -> Any:
    """The field ``a.b`` of ``msg``; ControlError when the message has no such field."""
    value = msg
    for part in path.split("."):
        if part not in getattr(type(value), "__struct_fields__", ()):
            raise ControlError(f"{type(msg).__ros_type__} has no field {path!r}")
        value = getattr(value, part)
    return value
