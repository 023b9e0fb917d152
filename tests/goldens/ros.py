"""Our messages as real rclpy messages (where rclpy is installed), and how to compare CDR with rclpy's.

rclpy's ``serialize_message`` (rmw_fastrtps) writes the same CDR as
``encode_cdr`` but leaves the alignment padding as its buffer held it and
returns as many bytes as its size estimate says (see :mod:`actors.messages.cdr`).
:func:`same_wire` therefore compares every byte that is not padding (found
by encoding twice with different padding bytes) and checks rclpy's length
against :func:`fastrtps_length`, a model of that estimate.
"""

from __future__ import annotations

import importlib
from typing import Any

from actors.messages import cdr
from actors.messages._fields import MessageLayout, layout
from actors.messages.idl import OCTETS, STRINGS

__all__ = ["rclpy_class", "to_rclpy", "same_wire", "padding_positions", "fastrtps_length"]


def rclpy_class(ros_type: str) -> type:
    """The rclpy class of ``ros_type``, services' parts and actions' wire types included.

    Raises ImportError (ModuleNotFoundError) when its package is not installed.
    """
    pkg, kind, name = ros_type.split("/")
    module = importlib.import_module(f"{pkg}.{kind}")
    if hasattr(module, name):
        return getattr(module, name)
    for suffix, path in _PARTS:
        if name.endswith(suffix):
            found: Any = getattr(module, name.removesuffix(suffix))
            for attribute in path:
                found = getattr(found, attribute)
            return found
    raise ImportError(f"{pkg}.{kind} has no {name}")


_PARTS = (
    ("_SendGoal_Request", ("Impl", "SendGoalService", "Request")),
    ("_SendGoal_Response", ("Impl", "SendGoalService", "Response")),
    ("_GetResult_Request", ("Impl", "GetResultService", "Request")),
    ("_GetResult_Response", ("Impl", "GetResultService", "Response")),
    ("_FeedbackMessage", ("Impl", "FeedbackMessage")),
    ("_Request", ("Request",)),
    ("_Response", ("Response",)),
    ("_Goal", ("Goal",)),
    ("_Result", ("Result",)),
    ("_Feedback", ("Feedback",)),
)


def to_rclpy(msg: Any) -> Any:
    """The rclpy message equal to our ``msg``."""
    out = rclpy_class(msg.__ros_type__)()
    lay = layout(type(msg))
    if lay.placeholder:
        return out
    for field in lay.fields:
        value, type_ = getattr(msg, field.name), field.type
        if field.nested is not None:
            value = [to_rclpy(e) for e in value] if type_.array else to_rclpy(value)
        elif type_.base == "byte":  # rclpy's byte is a bytes object of length 1
            value = [bytes([b]) for b in value] if type_.array else bytes([value])
        elif type_.array and type_.base in OCTETS:
            value = list(value)
        setattr(out, field.name, value)
    return out


def padding_positions(msg: Any) -> set[int]:
    """The offsets of ``encode_cdr(msg)`` that are alignment padding."""
    zero, marked = cdr.encode(msg), cdr.encode(msg, padding=0xA5)
    return {i for i, (a, b) in enumerate(zip(zero, marked)) if a != b}


def same_wire(msg: Any, theirs: bytes) -> str | None:
    """Why ``theirs`` (rclpy's bytes) is not ``msg``'s CDR, or None when it is."""
    ours = cdr.encode(msg)
    if len(theirs) != fastrtps_length(msg) or len(theirs) < len(ours):
        return f"rclpy wrote {len(theirs)} bytes, we wrote {len(ours)}, its estimate is {fastrtps_length(msg)}"
    padding = padding_positions(msg)
    for i, byte in enumerate(ours):
        if i not in padding and theirs[i] != byte:
            return f"byte {i} differs: rclpy {theirs[i]:02x}, ours {byte:02x}\nrclpy {theirs.hex()}\nours  {ours.hex()}"
    return None


# ----- rmw_fastrtps' buffer size (rosidl_typesupport_fastrtps_c's size functions, in our words)

_SIZES = {
    "bool": 1,
    "byte": 1,
    "char": 1,
    "uint8": 1,
    "int8": 1,
    "int16": 2,
    "uint16": 2,
    "int32": 4,
    "uint32": 4,
    "float32": 4,
    "int64": 8,
    "uint64": 8,
    "float64": 8,
}


def _align(offset: int, size: int) -> int:
    return -offset % size


def fastrtps_length(msg: Any) -> int:
    """How many bytes rclpy's serialize_message returns for ``msg`` (rmw_fastrtps' estimate).

    A fixed-size type whose CDR matches its C struct's memory layout is
    "plain": its length is the header and its size, rounded up to 4.  Any
    other type's is the header plus a size computed as the C typesupport
    does, which aligns the elements of a sequence even when it is empty and
    counts one character more per wstring.
    """
    lay = layout(type(msg))
    size, plain = _fixed(lay, 0)
    if plain:
        return (4 + size + 3) & ~3
    return 4 + _estimate(lay, msg, 0)


def _estimate(lay: MessageLayout, msg: Any, offset: int) -> int:
    start = offset
    for field in lay.fields:
        value, type_ = (0 if lay.placeholder else getattr(msg, field.name)), field.type
        items = value if type_.array else [value]
        if type_.array in ("bounded", "unbounded"):
            offset += 4 + _align(offset, 4)
        if field.nested is not None:
            for item in items:
                offset += _estimate(field.nested, item, offset)
        elif type_.base in STRINGS:
            unit = 1 if type_.base == "string" else 4
            for item in items:
                count = len(item.encode()) if unit == 1 else len(item.encode("utf-16-le")) // 2
                offset += 4 + _align(offset, 4) + unit * (count + 1)
        else:
            size = _SIZES[type_.base]
            offset += len(items) * size + _align(offset, size)
    return offset - start


def _fixed(lay: MessageLayout, offset: int) -> tuple[int, bool]:
    """The CDR size of a fixed-size ``lay`` from ``offset``, and whether it is "plain"."""
    start, plain, last = offset, True, 0
    for field in lay.fields:
        type_ = field.type
        if type_.array in ("bounded", "unbounded") or type_.base in STRINGS:
            return 0, False
        count = type_.size if type_.array == "fixed" else 1
        if field.nested is not None:
            last = 0
            for _ in range(count):
                size, inner = _fixed(field.nested, offset)
                plain &= inner
                offset += size
                last += size
        else:
            size = _SIZES[type_.base]
            offset += _align(offset, size) + count * size
            last = count * size
    # Plain only if the C struct's last member ends where the CDR does.
    return offset - start, plain and _c_offset_of_last(lay) + last == offset - start


def _c_layout(lay: MessageLayout) -> tuple[int, int]:
    """sizeof and alignof of ``lay``'s C struct (fixed-size fields only)."""
    offset, widest = 0, 1
    for field in lay.fields:
        size, align = _c_member(field)
        offset += _align(offset, align) + size
        widest = max(widest, align)
    return offset + _align(offset, widest), widest


def _c_member(field: Any) -> tuple[int, int]:
    count = field.type.size if field.type.array == "fixed" else 1
    if field.nested is not None:
        size, align = _c_layout(field.nested)
    else:
        size = align = _SIZES[field.type.base]
    return count * size, align


def _c_offset_of_last(lay: MessageLayout) -> int:
    offset = 0
    for field in lay.fields:
        size, align = _c_member(field)
        offset += _align(offset, align)
        if field is lay.fields[-1]:
            return offset
        offset += size
    return 0
