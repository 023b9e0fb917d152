"""Numeric sequences as rclpy holds them: an ``array.array`` of the ROS type's typecode.

rclpy keeps a ``float32[]`` as ``array('f')``, an ``int32[<=5]`` as
``array('i')``, and so on for every number type but ``uint8``/``byte``
(actors keeps those as ``bytes``) and ``bool`` (a list, as in rclpy).  A
generated message holds the same: its defaults are arrays, its constructor
turns what it is given into one (:func:`held`, the class's
``__post_init__``), CDR fills one with a single copy of the bytes, and
``publish()``'s snapshot converts a list assigned to the field later.

rclpy keeps fixed-size arrays (``float64[36]``) as numpy arrays; actors keeps
them as ``array.array`` too, so that comparing two messages gives a bool
(a numpy field would make ``==`` between messages raise) and every field of
a number type behaves one way.
"""

from __future__ import annotations

import math
import struct
from array import array
from typing import Any

from actors.messages.idl import FieldType

__all__ = ["TYPECODES", "typecode", "held"]

#: The array typecode of each ROS number type a sequence of is an ``array.array`` (as rclpy's).
TYPECODES: dict[str, str] = {
    "char": "B",
    "int8": "b",
    "int16": "h",
    "uint16": "H",
    "int32": "i",
    "uint32": "I",
    "int64": "q",
    "uint64": "Q",
    "float32": "f",
    "float64": "d",
}
assert all(array(code).itemsize == struct.calcsize(code) for code in TYPECODES.values())

# float32's infinities as this machine stores them: where a conversion may have made one.
_INFINITIES = tuple(struct.pack("=f", sign * math.inf) for sign in (1, -1))


def typecode(type_: FieldType) -> str | None:
    """The typecode of an array field held as ``array.array``, or None for any other field."""
    return TYPECODES.get(type_.base) if type_.array else None


def held(value: Any, code: str) -> Any:
    """``value`` as an ``array(code)`` when every item fits; otherwise ``value`` as it was.

    What does not fit (a str or a bool in a float array, 300 in an ``int8[]``,
    1e39 in a ``float32[]``) stays as it was given, so that ``publish()`` refuses it by
    field name, as it refuses a wrong value assigned later.
    """
    if type(value) is array and value.typecode == code:
        return value
    if isinstance(value, (str, bytes, bytearray, memoryview)):
        return value  # array() would read the bytes as machine numbers
    if not isinstance(value, (list, tuple, array)) and not hasattr(value, "dtype"):
        try:
            value = list(value)  # an iterator is read once: by the checks below, then lost to array()
        except TypeError:
            return value  # not a sequence at all: publish() names it
    if code in "fd" and (getattr(getattr(value, "dtype", None), "kind", "") == "b" or bool in map(type, value)):
        return value  # array('f') takes True as 1.0 (a numpy bool too); publish() refuses a bool for a float
    try:
        converted = array(code, value)
    except (TypeError, ValueError, OverflowError):
        return value
    if code == "f" and _overflowed(converted, value):
        return value
    return converted


def _overflowed(converted: array[Any], value: Any) -> bool:
    # A finite float beyond float32's range becomes an infinity in array('f'): look for
    # infinities in the raw bytes first (in C), then compare with the source only if any.
    raw = converted.tobytes()
    if not any(infinity in raw for infinity in _INFINITIES):
        return False
    return any(math.isinf(made) and not math.isinf(given) for made, given in zip(converted, value))
