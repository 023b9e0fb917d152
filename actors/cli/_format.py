"""How the command line prints messages: rclpy's repr, and YAML as ``ros2 topic echo`` does."""

from __future__ import annotations

from typing import Any

from actors.errors import ControlError

__all__ = ["ros_repr", "yaml_text", "parse_yaml", "field"]


def ros_repr(value: Any) -> str:
    """``value`` as rclpy's repr prints it: ``std_msgs.msg.Bool(data=True)``, nested alike."""
    name = getattr(type(value), "__ros_type__", None)
    if name is not None:
        fields = ", ".join(f"{f}={ros_repr(getattr(value, f))}" for f in value.__struct_fields__)
        return f"{name.replace('/', '.')}({fields})"
    if isinstance(value, list):
        return "[" + ", ".join(ros_repr(item) for item in value) + "]"
    return repr(value)


def yaml_text(value: Any) -> str:
    """``value`` as block YAML: a message as ``codec.to_yaml`` writes it, anything else likewise."""
    from actors import codec

    if hasattr(type(value), "__ros_type__"):
        return codec.to_yaml(value)
    text = codec.dump_yaml(_plain(value))
    return text.removesuffix("...\n")  # the end-of-document mark PyYAML adds after a bare scalar


def _plain(value: Any) -> Any:
    from actors import codec

    if hasattr(type(value), "__ros_type__"):
        return codec.to_builtins(value)
    if isinstance(value, (list, tuple)):
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
