"""test_msgs' message fixtures: ``get_test_msg(name)`` gives sample messages of a test_msgs type.

ROS ships such a module beside its test_msgs package for tests that round-trip
every kind of field (rclpy's serialization tests import it).  These samples
are made from each type's own definition: the defaults, then every field at
the low end of its range, then at the high end (longest strings and arrays
the bounds allow, non-ASCII text, nested messages likewise), so each type
covers its field kinds without a hand-written list to keep in step.
"""

from __future__ import annotations

from typing import Any

from actors.messages._copy import FLOAT32_MAX
from actors.messages._fields import FieldLayout, MessageLayout, layout
from actors.messages.idl import FieldType, INTEGER_RANGES, OCTETS
from interfaces.test_msgs import msg

__all__ = ["get_test_msg"]

_TEXT = {False: "", True: "Grüße, ロボット!"}
_FLOAT_ENDS = {"float32": FLOAT32_MAX, "float64": 1.7976931348623157e308}
_UNBOUNDED_LENGTH = 4  # elements of a T[] sample at the high end


def get_test_msg(name: str) -> list[Any]:
    """The samples of ``test_msgs/msg/<name>``: its default, its low-end and its high-end message.

    A type without fields has one sample.  KeyError names an unknown type.
    """
    cls = getattr(msg, name, None)
    if not isinstance(cls, type) or name not in msg.__all__:
        raise KeyError(f"test_msgs has no message {name!r}")
    shape = layout(cls)
    if shape.placeholder:  # the only field is the wire's placeholder byte
        return [cls()]
    return [cls(), _sample(shape, high=False), _sample(shape, high=True)]


def _sample(shape: MessageLayout, *, high: bool) -> Any:
    if shape.placeholder:
        return shape.cls()
    return shape.cls(**{field.name: _field(field, high) for field in shape.fields})


def _field(field: FieldLayout, high: bool) -> Any:
    kind = field.type
    if kind.array is None:
        return _element(field, high)
    count = kind.size if kind.array == "fixed" else (kind.size if kind.array == "bounded" else _UNBOUNDED_LENGTH)
    count = count if high or kind.array == "fixed" else 0
    items = [_element(field, high) for _ in range(count or 0)]
    return bytes(items) if kind.base in OCTETS else items


def _element(field: FieldLayout, high: bool) -> Any:
    kind: FieldType = field.type
    if field.nested is not None:
        return _sample(field.nested, high=high)
    if kind.base == "bool":
        return high
    if kind.base in INTEGER_RANGES:
        return INTEGER_RANGES[kind.base][high]
    if kind.base in _FLOAT_ENDS:
        return _FLOAT_ENDS[kind.base] if high else -_FLOAT_ENDS[kind.base]
    text = _TEXT[high] if kind.base == "wstring" else ("the high end" if high else "")
    return text[: kind.string_bound] if kind.string_bound is not None else text
