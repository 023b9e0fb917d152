"""CDR, ROS 2's wire format: an encoder and a decoder generated per message type, bit-exact with rmw's.

The format is plain CDR as the ROS 2 middlewares write it (XCDR1, "final"
structs): a 4-byte encapsulation header (``00 01 00 00`` little-endian,
``00 00 00 00`` big-endian), then the fields in definition order with no
framing, each primitive aligned to its own size (at most 8) counted from
*after* the header.  Nested messages are inlined; a sequence is a uint32
count then its elements; a string is a uint32 byte count including a
terminating NUL, then the UTF-8 bytes and the NUL; a wstring is a uint32
count of UTF-16 code units, then each unit as 4 bytes and no terminator (as
Fast CDR writes ``wchar_t``); a bool is one byte; an empty message carries
rosidl's one placeholder byte (see :mod:`actors.messages._fields`).  An empty sequence
of 8-byte elements adds no alignment after its count.

What :func:`encode` returns is exactly the message's CDR, as rmw_zenoh sends
it, padding bytes zero.  rclpy's ``serialize_message`` (rmw_fastrtps) returns
the same bytes followed by a few more: it sizes its buffer with an estimate
(rounded up to 4 bytes for fixed-size types, one alignment too many for an
empty ``float64[]``, one character too many per wstring) and leaves padding
and that tail as its allocator found them.  Readers ignore both.

Speed comes from generating Python source per type once, at first use: runs
of fixed-size fields (nested ones inlined, ``float64[9]`` included, as its raw
bytes) become one precompiled ``struct`` call; a numeric sequence, held as an
``array.array`` (see :mod:`actors.messages.arrays`), is one ``tobytes`` or one
``frombytes``; ``uint8[]`` a bytes slice.  Where a run starts at an offset known only at run
time (after a string), a table holds one ``Struct`` per possible alignment.

``decode(..., views=True)`` has its own generated decoders: there a numeric
array (``uint8[]`` included) is a ``numpy.frombuffer`` view of the input, in
its byte order, made after the same length check; a run steps over a
fixed-size one (struct's pad bytes) and views it at its offset, and fields
the class's ``__post_init__`` would copy into an ``array.array`` are set
after construction.  The encoders take such views
(and any 1-D numpy vector of the field's type) in C.

Decoding refuses anything malformed with :class:`CdrError` naming the type
and the field path: lengths are checked against the bytes left *before*
anything is allocated, so a forged length cannot make it allocate more than
the input's size.  The generated code keeps the index of the field it is at
in a local variable; on a failure the traceback's frames tell which field,
at no cost to the fast path.
"""

from __future__ import annotations

import functools
import struct
import sys
from array import array
from collections.abc import Callable
from types import FrameType
from typing import Any, TypeVar

from actors.errors import CdrError
from actors.messages._fields import MessageLayout, layout
from actors.messages.arrays import typecode
from actors.messages.idl import FLOATS, INTEGER_RANGES, OCTETS, STRINGS, FieldType

__all__ = ["HEADER", "Buffer", "encode", "encoder", "decode", "min_size"]

T = TypeVar("T")

#: The encapsulation header of little-endian plain CDR, as ROS writes it.
HEADER = b"\x00\x01\x00\x00"

# ROS primitive -> struct code (also the array typecode, bool aside), size in bytes.
_PRIMITIVES: dict[str, tuple[str, int]] = {
    "bool": ("?", 1),
    "byte": ("B", 1),
    "char": ("B", 1),
    "uint8": ("B", 1),
    "int8": ("b", 1),
    "int16": ("h", 2),
    "uint16": ("H", 2),
    "int32": ("i", 4),
    "uint32": ("I", 4),
    "int64": ("q", 8),
    "uint64": ("Q", 8),
    "float32": ("f", 4),
    "float64": ("d", 8),
}
assert all(array(code).itemsize == size for code, size in _PRIMITIVES.values() if code != "?")
# Array typecode -> numpy's name of the same type, byte order aside.
_NUMPY = {"b": "i1", "B": "u1", "h": "i2", "H": "u2", "i": "i4", "I": "u4", "q": "i8", "Q": "u8", "f": "f4", "d": "f8"}
_FLOAT32_MAX = 3.4028234663852886e38
_LITTLE_HOST = sys.byteorder == "little"


# --------------------------------------------------------------------------- public API


def encode(msg: Any, *, padding: int = 0) -> bytes:
    """``msg`` (a generated message, a service's Request/Response, an action's part) as CDR bytes.

    Little-endian, header included.  ``padding`` is the byte written where
    CDR aligns (ROS leaves it unspecified; tests set it to find the padding).
    Raises TypeError for an object that is not a generated message, and
    CdrError naming the field for a value its ROS type cannot carry (an
    ``int8`` of 300, a ``float64[9]`` of 8 items, a bounded sequence too long).
    """
    cls = type(msg)
    fill = _encoders.get((cls, padding)) or encoder(cls, padding)
    buf = Buffer(HEADER)
    try:
        fill(buf, msg)
    except Exception as exc:  # anything a bad value makes struct, array or str raise
        raise _encode_error(layout(cls), msg, exc) from None
    return buf.result()


def encoder(cls: type, padding: int = 0) -> Callable[[bytearray, Any], None]:
    """``cls``'s compiled encoder: ``fill(buf, msg)`` appends ``msg``'s CDR to ``buf``, a ``Buffer(HEADER)``.

    For a writer of many messages (a recorder's batch), which saves :func:`encode`'s
    per-call work and keeps the buffer as it is (``buf.result()`` only when
    ``buf.chunks``).  A bad value raises whatever struct, array or str raised:
    :func:`encode` of the same message names the field.  TypeError for a class
    that is not a generated message.
    """
    fill = _encoders.get((cls, padding))
    if fill is None:
        fill = _encoders[cls, padding] = _compile_encoder(layout(cls), padding, top=True)
    return fill


def decode(data: bytes | bytearray | memoryview, cls: type[T], *, views: bool = False) -> T:
    """A ``cls`` message from CDR ``data`` (little- or big-endian, header included).

    Bytes after the message are ignored (rmw_fastrtps leaves a few).  Raises
    CdrError naming the type and the field path for truncated or malformed
    data, an unknown encapsulation, an invalid string or an over-long bounded
    field; TypeError when ``cls`` is not a generated message.

    ``views=True``: every numeric sequence and fixed-size numeric array
    (``uint8[]``, ``byte[]`` and ``char[]`` included; ``bool`` aside) is a
    read-only ``numpy.frombuffer`` view of ``data`` instead of a copy, in
    the data's byte order (a big-endian message gives big-endian dtypes).
    The views keep ``data`` alive; a ``bytearray`` or writable
    ``memoryview`` given as ``data`` is aliased, not copied: its later
    changes show in the message (and a bytearray cannot be resized while
    the message lives).
    """
    cache = _view_decoders if views else _decoders
    decoders = cache.get(cls)
    if decoders is None:
        lay = layout(cls)
        decoders = cache[cls] = (
            _compile_decoder(lay, ">", top=True, views=views),
            _compile_decoder(lay, "<", top=True, views=views),
        )
    if views and type(data) is not bytes:
        data = memoryview(data).toreadonly()  # numpy would make writable views of a bytearray
    if len(data) < 4 or data[0] != 0 or data[1] > 1:
        head = bytes(data[:4]).hex(" ") or "nothing"
        raise CdrError(f"{layout(cls).ros_type}: not plain CDR (the header is {head}, expected 00 01 00 00)")
    try:
        return decoders[data[1]](data, 4)[0]  # header byte 1: 0 big-endian, 1 little-endian
    except Exception as exc:
        raise _decode_error(layout(cls), data, exc) from None


def min_size(lay: MessageLayout) -> int:
    """The fewest bytes a ``lay`` message can take in CDR, alignment aside (at least 1)."""
    total = 0
    for field in lay.fields:
        type_ = field.type
        if type_.array in ("unbounded", "bounded"):
            total += 4
            continue
        count = type_.size if type_.array == "fixed" else 1
        assert count is not None  # a fixed array has its size
        if type_.is_nested:
            assert field.nested is not None
            total += count * min_size(field.nested)
        elif type_.base in STRINGS:
            total += count * 4
        else:
            total += count * _PRIMITIVES[type_.base][1]
    return total


class Buffer(bytearray):
    """The bytes being encoded; large arrays are kept aside as chunks instead of copied in.

    Growing a bytearray by a megabyte and copying it into ``bytes`` costs
    milliseconds (fresh pages each time); ``b"".join`` of the pieces costs
    one copy.  After a spill the buffer restarts with ``skip`` dummy bytes so
    that its length stays congruent to the true offset modulo 8, which is all
    alignment reads from it.

    Made as a plain bytearray is (``Buffer(HEADER)``, no ``__init__`` of its
    own): until a first spill, which most messages never make, ``chunks`` and
    ``skip`` are the class's.  A Python ``__init__`` cost a third of encoding
    a small message.
    """

    chunks: tuple[Any, ...] = ()
    skip = 0

    def spill(self, data: Any) -> None:
        """Append ``data`` (a large bytes-like object) without copying it into the buffer."""
        self.chunks += (bytes(self[self.skip :]), data)
        self.skip = (len(self) + len(data)) & 7
        self[:] = bytes(self.skip)

    def result(self) -> bytes:
        """Everything written, as one bytes object."""
        if not self.chunks:
            return bytes(self)
        return b"".join([*self.chunks, self[self.skip :]])


# The Struct of a sequence of n numbers ("<360f"): compiled once for the lengths that recur.
_sequence_struct = functools.lru_cache(maxsize=256)(struct.Struct)
_SPILL = 1 << 16  # arrays longer than this many bytes are spilled rather than copied into the buffer
_encoders: dict[tuple[type, int], Callable[[bytearray, Any], None]] = {}
_decoders: dict[type, tuple[Callable[..., Any], Callable[..., Any]]] = {}
_view_decoders: dict[type, tuple[Callable[..., Any], Callable[..., Any]]] = {}
_element_encoders: dict[tuple[type, int], Callable[[bytearray, Any], None]] = {}
_element_decoders: dict[tuple[type, str, bool], Callable[..., Any]] = {}


# --------------------------------------------------------------------------- code generation


class _Source:
    """Lines of one generated function, the constants they use, and what is known of alignment.

    ``phase`` is the current offset modulo 8 when the generator knows it
    (after the header, after fixed-size fields), else None.
    """

    def __init__(self, lay: MessageLayout, top: bool, pad: str, pad_to: str) -> None:
        self.lay = lay
        self.lines: list[str] = []
        self.namespace: dict[str, Any] = {"array": array, "_Bad": _Bad, "__name__": __name__}  # ours, in tracebacks
        self.phase: int | None = 0 if top else None
        self.run: list[tuple[str, int, int, str, str]] = []  # code, size, align, argument, path
        self.where: list[Any] = []  # per field index: a path, or a run's items
        self.pending: list[tuple[str, FieldType, int]] = []  # values waiting for their run: token, type, item
        self.values: dict[str, str] = {}  # token -> the expression that reads the value
        self.names = 0
        self.pad, self.pad_to = pad, pad_to  # code that pads by a count, or to a mask

    def name(self, prefix: str, value: Any = None) -> str:
        self.names += 1
        name = f"{prefix}{self.names}"
        if value is not None:
            self.namespace[name] = value
        return name

    def emit(self, line: str, depth: int = 1) -> None:
        self.lines.append("    " * depth + line)

    def mark(self, what: Any, depth: int = 1) -> None:
        """Record where the code is (a field path or a run) in the local ``w``."""
        self.where.append(what)
        self.emit(f"w = {len(self.where) - 1}", depth)

    def align(self, align: int, depth: int = 1) -> None:
        """Emit what moves to the next multiple of ``align``: ``pad`` bytes, or a run-time mask."""
        if align == 1:
            return
        if self.phase is not None:
            pad = -self.phase % align
            if pad:
                self.emit(self.pad.format(pad), depth)
            self.phase = (self.phase + pad) % 8
        else:
            self.emit(self.pad_to.format(align - 1), depth)

    def compile(self, signature: str, body_end: list[str], filename: str) -> Callable[..., Any]:
        self.namespace["_WHERE"] = tuple(self.where)
        source = "\n".join([f"def f({signature}):", "    w = -1", *self.lines, *body_end])
        exec(compile(source, filename, "exec"), self.namespace)
        return self.namespace["f"]


def _struct_format(items: list[tuple[str, int, int, str, str]], phase: int, endian: str) -> tuple[str, int]:
    """The struct format of a run of fixed-size items starting at ``phase``, and the phase after it."""
    parts = [endian]
    offset = phase
    for code, size, align, _, _ in items:
        pad = -offset % align
        if pad:
            parts.append(f"{pad}x")
        parts.append(code)
        offset += pad + size
    return "".join(parts), offset % 8


def _offsets(items: list[tuple[str, int, int, str, str]], phase: int) -> tuple[int, ...]:
    """Each item's start from the run's start, when the run starts at ``phase``."""
    return tuple(end - size for (_, size, _, _, _), (_, end) in zip(items, _run_items(items, phase)))


def _run_items(items: list[tuple[str, int, int, str, str]], phase: int) -> list[tuple[str, int]]:
    """Each item's path and its end offset from the run's start, when the run starts at ``phase``."""
    ends = []
    offset = phase
    for _, size, align, _, path in items:
        offset += -offset % align + size
        ends.append((path, offset - phase))
    return ends


def _scalar_item(type_: FieldType, argument: str, path: str, skip: bool = False) -> tuple[str, int, int, str, str]:
    """A run's item for a fixed-size field; ``skip``: a fixed array the run steps over (a decoder's view of it)."""
    code, size = _PRIMITIVES[type_.base]
    if type_.array == "fixed":
        assert type_.size is not None  # a fixed array has its size
        if skip:
            return f"{size * type_.size}x", size * type_.size, size, argument, path
        if type_.base in OCTETS:
            return f"{type_.size}s", type_.size, 1, argument, path
        if typecode(type_):  # an array.array: its bytes in the run, not a Python number per item
            return f"{size * type_.size}s", size * type_.size, size, f"RAW({argument}, {code!r}, {type_.size})", path
        return f"{type_.size}{code}", size * type_.size, size, f"*{argument}", path
    return code, size, size, argument, path


def _raw(value: Any, code: str, count: int) -> bytes:
    """The little-endian bytes of ``count`` numbers: an array's own, a numpy vector's, or packed from any sequence.

    A numpy vector of the field's very type (a view :func:`decode` made, in
    either byte order) is converted in C; anything else goes through struct,
    which refuses a sequence of another length or a value out of range.
    """
    if _LITTLE_HOST and type(value) is array and value.typecode == code and len(value) == count:
        return value.tobytes()
    dtype = getattr(value, "dtype", None)
    if dtype is not None and dtype.str[1:] == _NUMPY[code] and value.ndim == 1 and len(value) == count:
        return value.astype("<" + _NUMPY[code], copy=False).tobytes()
    return _sequence_struct(f"<{count}{code}").pack(*value)


def _octets(value: Any, fixed: bool = False) -> Any:
    """A ``uint8[]``/``byte[]`` value as the encoder appends it: bytes-like as is, a uint8 numpy vector's memory.

    ``fixed``: for struct's ``s`` in a run, which takes bytes and bytearray only.
    """
    if isinstance(value, (bytes, bytearray, memoryview)):
        return bytes(value) if fixed and type(value) is memoryview else value
    if getattr(getattr(value, "dtype", None), "str", None) == "|u1" and value.ndim == 1:
        return value.tobytes() if fixed or not value.flags.c_contiguous else memoryview(value)
    raise TypeError(f"expected bytes or a 1-D uint8 numpy array, got {type(value).__name__}")


def _fixed_size(type_: FieldType) -> bool:
    """True for a field that can join a run: a primitive other than a string, or a fixed array of one."""
    return not type_.is_nested and type_.base not in STRINGS and type_.array in (None, "fixed")


# ----- encoders


def _compile_encoder(lay: MessageLayout, padding: int, *, top: bool) -> Callable[[bytearray, Any], None]:
    src = _Source(lay, top, "buf += PAD[{}]", "buf += PAD[(4 - len(buf)) & {}]")
    src.namespace.update(
        PAD=tuple(bytes([padding]) * n for n in range(8)),
        RAW=_raw,
        OCTETS=_octets,
        U32=struct.Struct("<I").pack,
        ST=_sequence_struct,
        padding=padding,
    )
    _encode_fields(src, lay, "m", "$")
    _flush_encode(src)
    return src.compile("buf, m", [], f"<cdr encoder {lay.ros_type}>")


def _element_encoder(lay: MessageLayout, padding: int) -> Callable[[bytearray, Any], None]:
    key = (lay.cls, padding)
    if key not in _element_encoders:
        _element_encoders[key] = _compile_encoder(lay, padding, top=False)
    return _element_encoders[key]


def _encode_fields(src: _Source, lay: MessageLayout, expr: str, path: str) -> None:
    if lay.placeholder:
        src.run.append(("B", 1, 1, "0", path))
        return
    for field in lay.fields:
        type_, value, where = field.type, f"{expr}.{field.name}", f"{path}.{field.name}"
        if type_.array is None and type_.is_nested:
            assert field.nested is not None
            _encode_fields(src, field.nested, value, where)
        elif _fixed_size(type_):
            if type_.array == "fixed" and type_.base in OCTETS:
                _flush_encode(src)
                src.mark(where)
                local = src.name("o")  # the run's argument: struct's "s" takes bytes and bytearray only
                src.emit(f"{local} = {value}")
                src.emit(f"if type({local}) is not bytes: {local} = OCTETS({local}, True)")
                src.emit(f"if len({local}) != {type_.size}: raise _Bad")
                value = local
            src.run.append(_scalar_item(type_, value, where))
        else:
            _flush_encode(src)
            src.mark(where)
            _encode_array(src, field.type, value, field.nested)


def _flush_encode(src: _Source) -> None:
    items, src.run = src.run, []
    if not items:
        return
    if src.namespace["padding"] and len(items) > 1:
        # struct pads with zeros: to write another padding byte, each item goes alone after PAD
        for item in items:
            src.align(item[2])
            src.run = [item]
            _flush_encode(src)
        return
    if src.namespace["padding"]:
        src.align(items[0][2])
    src.mark(items)
    arguments = ", ".join(item[3] for item in items)
    widest = max(item[2] for item in items)
    if src.phase is not None:
        fmt, src.phase = _struct_format(items, src.phase, "<")
        src.emit(f"buf += {src.name('P', struct.Struct(fmt).pack)}({arguments})")
    elif widest == 1:
        src.emit(f"buf += {src.name('P', struct.Struct(_struct_format(items, 0, '<')[0]).pack)}({arguments})")
    else:
        table = tuple(struct.Struct(_struct_format(items, phase, "<")[0]).pack for phase in range(widest))
        src.emit(f"buf += {src.name('P', table)}[(len(buf) - 4) & {widest - 1}]({arguments})")
        src.phase = None


def _encode_string(src: _Source, type_: FieldType, value: str, depth: int) -> None:
    bound = type_.string_bound
    if bound is not None:
        src.emit(f"if len({value}) > {bound}: raise _Bad", depth)
    src.align(4, depth)
    if type_.base == "string":
        src.emit(f"s = {value}.encode()", depth)
        src.emit("buf += U32(len(s) + 1); buf += s; buf.append(0)", depth)
    else:  # UTF-16 code units, each widened to 4 bytes
        src.emit(f"s = array('H', {value}.encode('utf-16-le'))", depth)
        if not _LITTLE_HOST:
            src.emit("s.byteswap()", depth)
        src.emit(f"s = array('I', s){'' if _LITTLE_HOST else '; s.byteswap()'}", depth)
        src.emit("buf += U32(len(s)); buf += s.tobytes()", depth)
    src.phase = None


def _encode_array(src: _Source, type_: FieldType, value: str, nested: MessageLayout | None) -> None:
    if type_.array is None:  # a lone string
        _encode_string(src, type_, value, 1)
        return
    src.emit(f"v = {value}")
    if type_.array == "fixed":
        src.emit(f"if len(v) != {type_.size}: raise _Bad")
    else:
        if type_.array == "bounded":
            src.emit(f"if len(v) > {type_.size}: raise _Bad")
        src.align(4)
        src.emit("buf += U32(len(v))")
    if nested is not None:
        src.emit(f"for e in v: {src.name('E', _element_encoder(nested, src.namespace['padding']))}(buf, e)")
    elif type_.base in STRINGS:
        src.emit("for e in v:")
        src.phase = None  # each item moves it
        _encode_string(src, type_, "e", 2)
    elif type_.base in OCTETS:
        src.emit("if type(v) is not bytes: v = OCTETS(v)")
        src.emit(f"if len(v) > {_SPILL}: buf.spill(v)")
        src.emit("else: buf += v")
    elif type_.base == "bool":
        src.emit("buf += bytes(map(bool, v))")
    else:  # a sequence of numbers (fixed arrays of them are part of runs)
        code, size = _PRIMITIVES[type_.base]
        src.emit("if len(v):")  # a numpy vector has no truth value
        src.phase = None
        src.align(size, 2)
        if _LITTLE_HOST:  # an array of the field's own typecode is its CDR bytes already
            src.emit(f"if type(v) is array and v.typecode == {code!r}: a = v.tobytes()", 2)
            src.emit(f"else: a = RAW(v, {code!r}, len(v))", 2)
        else:
            src.emit(f"a = RAW(v, {code!r}, len(v))", 2)
        src.emit(f"if len(a) > {_SPILL}: buf.spill(a)", 2)
        src.emit("else: buf += a", 2)
    src.phase = None


# ----- decoders


def _compile_decoder(lay: MessageLayout, endian: str, *, top: bool, views: bool = False) -> Callable[..., Any]:
    src = _Source(lay, top, "pos += {}", "pos += (4 - pos) & {}")
    src.namespace.update(
        U32=struct.Struct(endian + "I").unpack_from,
        ST=_sequence_struct,
        endian=endian,
        swap=(endian == "<") != _LITTLE_HOST,
        SWAPPED=_swapped,
        views=views,
    )
    if views:
        import numpy  # a core dependency, imported by the first decoder that makes views

        src.namespace.update(VIEW=numpy.frombuffer)
    constructor = _decode_fields(src, lay, "$")
    _flush_decode(src)
    for token, value in src.values.items():
        constructor = constructor.replace(token, value)
    kind = "view decoder" if views else "decoder"
    return src.compile("d, pos", [f"    return {constructor}, pos"], f"<cdr {kind} {lay.ros_type}>")


def _element_decoder(lay: MessageLayout, endian: str, views: bool) -> Callable[..., Any]:
    key = (lay.cls, endian, views)
    if key not in _element_decoders:
        _element_decoders[key] = _compile_decoder(lay, endian, top=False, views=views)
    return _element_decoders[key]


def _viewed(type_: FieldType) -> bool:
    """True for a field that a decoder with views makes a numpy view: numbers in an array, bool aside."""
    return type_.array is not None and not type_.is_nested and type_.base not in STRINGS and type_.base != "bool"


def _decode_fields(src: _Source, lay: MessageLayout, path: str) -> str:
    """Emit the decoding of ``lay``'s fields; return the expression that builds the message."""
    if lay.placeholder:
        src.run.append(("B", 1, 1, "", path))
        return f"{src.name('C', lay.cls)}()"
    arguments, late = [], []
    views = src.namespace["views"]
    for field in lay.fields:
        type_, where = field.type, f"{path}.{field.name}"
        if type_.array is None and type_.is_nested:
            assert field.nested is not None
            arguments.append(f"{field.name}={_decode_fields(src, field.nested, where)}")
        elif _fixed_size(type_):
            viewed = views and _viewed(type_)
            src.run.append(_scalar_item(type_, "", where, skip=viewed))
            token = f"@{len(src.pending)}@{len(src.values)}@"  # replaced once the run is unpacked
            src.pending.append((token, type_, len(src.run) - 1))
            if viewed and typecode(type_):
                late.append((field.name, token))
            else:
                arguments.append(f"{field.name}={token}")
        else:
            _flush_decode(src)
            src.mark(where)
            value = src.name("v")
            _decode_array(src, type_, value, field.nested)
            if views and typecode(type_):
                late.append((field.name, value))
            else:
                arguments.append(f"{field.name}={value}")
    made = f"{src.name('C', lay.cls)}({', '.join(arguments)})"
    if late:  # set as they are after the constructor: its __post_init__ would copy a numpy view into an array
        made_as = src.name("m")
        sets = ", ".join(f"setattr({made_as}, {name!r}, {value})" for name, value in late)
        made = f"({made_as} := {made}, {sets})[0]"
    return made


def _flush_decode(src: _Source) -> None:
    items, src.run = src.run, []
    pending, src.pending = src.pending, []
    if not items:
        return
    src.mark(items)
    endian = src.namespace["endian"]
    widest = max(item[2] for item in items)
    values = src.name("t")
    # A view's place: the run's start (in a local, as the views are made in the return) plus its offset.
    skips = any(code.endswith("x") for code, *_ in items)
    origin = src.name("r") if skips else ""
    if skips:
        src.emit(f"{origin} = pos")
    if src.phase is not None:
        offsets: Any = _offsets(items, src.phase)
        fmt, src.phase = _struct_format(items, src.phase, endian)
        unpacker = struct.Struct(fmt)
        src.emit(f"{values} = {src.name('S', unpacker.unpack_from)}(d, pos); pos += {unpacker.size}")
    elif widest == 1:
        offsets = _offsets(items, 0)
        unpacker = struct.Struct(_struct_format(items, 0, endian)[0])
        src.emit(f"{values} = {src.name('S', unpacker.unpack_from)}(d, pos); pos += {unpacker.size}")
    else:
        table = tuple(struct.Struct(_struct_format(items, phase, endian)[0]) for phase in range(widest))
        if skips:  # the offsets depend on the phase too
            offsets = src.name("o")
            table_of_offsets = tuple(_offsets(items, phase) for phase in range(widest))
            src.emit(f"{offsets} = {src.name('O', table_of_offsets)}[(pos - 4) & {widest - 1}]")
        src.emit(f"s = {src.name('S', table)}[(pos - 4) & {widest - 1}]")
        src.emit(f"{values} = s.unpack_from(d, pos); pos += s.size")
    # Each item's position in the unpacked tuple: a fixed numeric array spans several, a skipped one none.
    starts, index = [], 0
    for code, _, _, _, _ in items:
        starts.append(index)
        index += 0 if code.endswith("x") else 1 if code.endswith("s") or len(code) == 1 else int(code[:-1])
    for token, type_, item in pending:
        if items[item][0].endswith("x"):
            at = f"{offsets}[{item}]" if isinstance(offsets, str) else offsets[item]
            dtype = src.name("T", _dtype(endian, type_))
            src.values[token] = f"VIEW(d, {dtype}, {type_.size}, {origin} + {at})"
            continue
        start = starts[item]
        if type_.array == "fixed" and type_.base not in OCTETS:
            assert type_.size is not None  # a fixed array has its size
            held = typecode(type_)
            if held is None:  # bool[N]: a list, each bool unpacked by the run
                src.values[token] = f"list({values}[{start}:{start + type_.size}])"
            else:  # the run unpacked the array's bytes: one copy into the array
                made = f"array({held!r}, {values}[{start}])"
                src.values[token] = f"SWAPPED({made})" if src.namespace["swap"] else made
        else:
            src.values[token] = f"{values}[{start}]"


def _decode_string(src: _Source, type_: FieldType, target: str, depth: int) -> None:
    src.align(4, depth)
    src.emit("n, = U32(d, pos); pos += 4", depth)
    if type_.base == "string":
        src.emit("end = pos + n", depth)
        src.emit("if end > len(d): raise _Bad(f'a string of {n} bytes, {len(d) - pos} left')", depth)
        src.emit("if n and d[end - 1]: raise _Bad('a string without its terminating NUL')", depth)
        src.emit(f"{target} = str(d[pos:end - 1], 'utf-8') if n else ''; pos = end", depth)
    else:
        src.emit("end = pos + 4 * n", depth)
        src.emit("if end > len(d): raise _Bad(f'a wstring of {n} characters, {len(d) - pos} bytes left')", depth)
        src.emit("a = array('I'); a.frombytes(d[pos:end])", depth)
        src.emit("if swap: a.byteswap()", depth)
        src.emit(
            f"{target} = array('H', a).tobytes().decode('utf-16-le' if {_LITTLE_HOST} else 'utf-16-be'); pos = end",
            depth,
        )
    if type_.string_bound is not None:
        src.emit(
            f"if len({target}) > {type_.string_bound}: raise _Bad('longer than its bound {type_.string_bound}')", depth
        )
    src.phase = None


def _decode_array(src: _Source, type_: FieldType, target: str, nested: MessageLayout | None) -> None:
    if type_.array is None:
        _decode_string(src, type_, target, 1)
        return
    if type_.array == "fixed":
        src.emit(f"n = {type_.size}")
    else:
        src.align(4)
        src.emit("n, = U32(d, pos); pos += 4")
        if type_.array == "bounded":
            src.emit(f"if n > {type_.size}: raise _Bad(f'{{n}} items, more than its bound {type_.size}')")
    if nested is not None or type_.base in STRINGS:
        least = min_size(nested) if nested is not None else 4
        src.emit(f"if n * {least} > len(d) - pos: raise _Bad(f'{{n}} items cannot fit in {{len(d) - pos}} bytes')")
        src.emit(f"{target} = []")
        src.emit("for i in range(n):")
        src.phase = None  # each item moves it
        if nested is not None:
            element = _element_decoder(nested, src.namespace["endian"], src.namespace["views"])
            src.emit(f"e, pos = {src.name('D', element)}(d, pos)", 2)
        else:
            _decode_string(src, type_, "e", 2)
        src.emit(f"{target}.append(e)", 2)
        src.emit("i = -1")  # out of the loop: errors after it are not in an item
        src.phase = None
        return
    # A sequence of primitives (fixed arrays of them are part of runs).
    code, size = _PRIMITIVES[type_.base]
    if src.namespace["views"] and _viewed(type_):
        _decode_view(src, type_, target, size)
        return
    src.emit("if n:")
    src.phase = None
    src.align(size, 2)
    src.emit(f"end = pos + {size} * n", 2)
    src.emit(f"if end > len(d): raise _Bad(f'{{n}} items of {size} bytes, {{len(d) - pos}} bytes left')", 2)
    if type_.base in OCTETS:
        src.emit(f"{target} = bytes(d[pos:end]); pos = end", 2)
    elif type_.base == "bool":
        src.emit(f"{target} = list(map(bool, d[pos:end])); pos = end", 2)
    else:
        src.emit(f"{target} = array({code!r}); {target}.frombytes(d[pos:end]); pos = end", 2)
        if src.namespace["swap"]:
            src.emit(f"{target}.byteswap()", 2)
    src.emit("else:")
    empty = {"bool": "[]", **dict.fromkeys(OCTETS, 'b""')}.get(type_.base, f"array({code!r})")
    src.emit(f"{target} = {empty}", 2)
    src.phase = None


def _dtype(endian: str, type_: FieldType) -> Any:
    """The numpy dtype of a view of ``type_``'s numbers in CDR of ``endian`` byte order."""
    import numpy

    return numpy.dtype(endian + _PRIMITIVES[type_.base][0])


def _decode_view(src: _Source, type_: FieldType, target: str, size: int) -> None:
    """Emit the making of a read-only numpy view of a sequence's ``n`` items, checked against the bytes left.

    Fixed-size arrays are viewed by the run that steps over them (:func:`_flush_decode`).
    """
    dtype = src.name("T", _dtype(src.namespace["endian"], type_))
    src.emit("if n:")
    src.phase = None
    src.align(size, 2)
    src.emit(f"end = pos + {size} * n", 2)
    src.emit(f"if end > len(d): raise _Bad(f'{{n}} items of {size} bytes, {{len(d) - pos}} bytes left')", 2)
    src.emit(f"{target} = VIEW(d, {dtype}, n, pos); pos = end", 2)
    src.emit("else:")
    src.emit(f"{target} = VIEW(d, {dtype}, 0, pos)", 2)  # empty, and cheaper than a view of b''
    src.phase = None


def _swapped(numbers: array[Any]) -> array[Any]:
    """``numbers`` with each item's bytes reversed (read in the other byte order)."""
    numbers.byteswap()
    return numbers


# --------------------------------------------------------------------------- errors


class _Bad(Exception):
    """Raised by generated code: the problem is in the text, the field in the frame's ``w``."""


def _frames(exc: BaseException) -> list[FrameType]:
    """The frames of generated coders the exception passed through, outermost first."""
    frames = []
    tb = exc.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename.startswith("<cdr "):
            frames.append(tb.tb_frame)
        tb = tb.tb_next
    return frames


def _path(exc: BaseException, size: int | None) -> str:
    """The field path where the generated code failed, from each frame's ``w`` (and ``i`` in loops)."""
    path = ""
    for frame in _frames(exc):
        where = frame.f_globals["_WHERE"]
        index = frame.f_locals.get("w", -1)
        if index < 0:
            continue
        here = where[index]
        if isinstance(here, list):  # a run of fixed-size fields: the first that did not fit
            pos = frame.f_locals.get("pos", 0)
            ends = _run_items(here, (pos - 4) % 8)
            here = ends[-1][0]
            if size is not None:
                here = next((item for item, end in ends if pos + end > size), here)
        elif frame.f_locals.get("i", -1) >= 0:  # in the loop over this field's items
            here = f"{here}[{frame.f_locals['i']}]"
        path += here if not path else here.removeprefix("$")
    return path or "$"


def _decode_error(lay: MessageLayout, data: Any, exc: Exception) -> CdrError:
    size = len(data)
    if isinstance(exc, _Bad):
        problem = str(exc)
    elif isinstance(exc, struct.error):
        problem = f"truncated: the data ends at byte {size}"
    elif isinstance(exc, UnicodeDecodeError):
        problem = f"a string that is not valid {exc.encoding.upper()}"
    else:
        problem = f"malformed ({type(exc).__name__}: {exc})"
    return CdrError(f"{lay.ros_type}: {problem} - at `{_path(exc, size)}`")


def _encode_error(lay: MessageLayout, msg: Any, exc: Exception) -> CdrError:
    found = _problem(lay, msg, "$")
    if found is None:  # the checker missed it: say what failed where the code was
        found = _path(exc, None), f"{type(exc).__name__}: {exc}"
    path, problem = found
    return CdrError(f"{lay.ros_type}: {problem} - at `{path}`")


def _problem(lay: MessageLayout, value: Any, path: str) -> tuple[str, str] | None:
    """The first field of ``value`` its ROS type cannot carry, with the problem, or None."""
    if not isinstance(value, lay.cls):
        return path, f"expected {lay.ros_type}, got {type(value).__name__}"
    if lay.placeholder:
        return None
    for field in lay.fields:
        item, where, type_ = getattr(value, field.name), f"{path}.{field.name}", field.type
        if type_.array is None:
            found = _item_problem(type_, field.nested, item, where)
        elif type_.base in OCTETS and not _is_octets(item):
            found = where, f"expected bytes, got {_kind(item)}"
        elif not hasattr(item, "__len__") or (isinstance(item, (str, bytes)) and type_.base not in OCTETS):
            found = where, f"expected a sequence, got {type(item).__name__}"
        elif type_.array == "fixed" and len(item) != type_.size:
            found = where, f"expected exactly {type_.size} items, got {len(item)}"
        elif type_.array == "bounded" and type_.size is not None and len(item) > type_.size:
            found = where, f"expected at most {type_.size} items, got {len(item)}"
        elif type_.base in OCTETS:
            found = None
        else:
            if hasattr(item, "dtype"):  # a numpy vector: its items as Python numbers, as the checks expect
                item = item.tolist()
            found = next(
                (p for i, e in enumerate(item) if (p := _item_problem(type_, field.nested, e, f"{where}[{i}]"))), None
            )
        if found:
            return found
    return None


def _is_octets(value: Any) -> bool:
    try:
        _octets(value)
    except TypeError:
        return False
    return True


def _kind(value: Any) -> str:
    """``value``'s type name, with its dtype for a numpy array."""
    dtype = getattr(value, "dtype", None)
    return f"{type(value).__name__} of {dtype}" if dtype is not None else type(value).__name__


def _item_problem(type_: FieldType, nested: MessageLayout | None, value: Any, path: str) -> tuple[str, str] | None:
    base = type_.base
    if nested is not None:
        return _problem(nested, value, path)
    if base in STRINGS:
        if not isinstance(value, str):
            return path, f"expected str, got {type(value).__name__}"
        if type_.string_bound is not None and len(value) > type_.string_bound:
            return path, f"expected at most {type_.string_bound} characters, got {len(value)}"
        try:
            value.encode("utf-8" if base == "string" else "utf-16-le")
        except UnicodeEncodeError as exc:
            return path, f"cannot be encoded: {exc.reason}"
        return None
    if base == "bool":
        return None if isinstance(value, (bool, int)) else (path, f"expected bool, got {type(value).__name__}")
    if base in FLOATS:
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            return path, f"expected float, got {type(value).__name__}"
        if base == "float32" and abs(value) > _FLOAT32_MAX and abs(value) != float("inf"):
            return path, f"{value} is out of range for float32"
        return None
    low, high = INTEGER_RANGES[base]
    if not isinstance(value, int) or isinstance(value, bool):
        return path, f"expected int, got {type(value).__name__}"
    if not low <= value <= high:
        return path, f"{value} is out of range for {base} [{low}, {high}]"
    return None
