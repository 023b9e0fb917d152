"""CDR decoding with ``views=True``: numeric arrays as read-only numpy views of the input, no copy, same bytes back."""

from __future__ import annotations

import functools
import json
import struct
import tracemalloc
from array import array
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import generated_package
from goldens.values import DrawPick, RandomPick, message, shipped_messages
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from actors import codec
from actors.errors import CdrError
from actors.messages import cdr
from actors.messages._fields import layout
from actors.messages.idl import STRINGS
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import Image, LaserScan
from interfaces.unique_identifier_msgs.msg import UUID

ENTRIES = json.loads((Path(__file__).parent / "goldens" / "cdr.json").read_text())["messages"]


def _arrays(msg: Any, path: str = "$") -> Iterator[tuple[str, Any, Any]]:
    """Every numeric array field of ``msg`` (nested ones too, ``bool`` aside): its path, type and value."""
    lay = layout(type(msg))
    if lay.placeholder:
        return
    for field in lay.fields:
        type_, value, where = field.type, getattr(msg, field.name), f"{path}.{field.name}"
        if type_.is_nested:
            for i, item in enumerate([value] if type_.array is None else value):
                yield from _arrays(item, where if type_.array is None else f"{where}[{i}]")
        elif type_.array is not None and type_.base not in STRINGS and type_.base != "bool":
            yield where, type_, value


def _check_views(msg: Any, data: Any, order: str) -> int:
    """Assert each numeric array of ``msg`` is a read-only view of ``data`` in byte ``order``; how many there are."""
    whole = np.frombuffer(data, np.uint8)
    found = 0
    for where, type_, value in _arrays(msg):
        assert type(value) is np.ndarray, where
        assert not value.flags.writeable, where
        assert value.dtype.str[0] in ("|", order), (where, value.dtype)
        if type_.array == "fixed":
            assert len(value) == type_.size, where
        if len(value):
            assert np.shares_memory(value, whole), where
            found += 1
    return found


def _same_values(views: Any, default: Any) -> None:
    assert codec.to_builtins(views) == codec.to_builtins(default)
    for (where, _, view), (_, _, held) in zip(_arrays(views), _arrays(default), strict=True):
        assert view.tolist() == list(held), where


@pytest.mark.parametrize("entry", ENTRIES, ids=lambda entry: entry["type"])
def test_every_golden_decodes_to_views_of_its_bytes_and_encodes_back(entry):
    data = bytes.fromhex(entry["cdr"])
    default = codec.decode_cdr(data, entry["type"])
    views = codec.decode_cdr(data, entry["type"], views=True)
    _check_views(views, data, "<")
    _same_values(views, default)
    assert codec.encode_cdr(views) == codec.encode_cdr(default)
    for _, _, held in _arrays(default):  # the default is what rclpy holds, unchanged
        assert isinstance(held, (array, bytes)), type(held)


def test_the_goldens_hold_views_of_every_kind():
    kinds = set()
    for entry in ENTRIES:
        data = bytes.fromhex(entry["cdr"])
        msg = codec.decode_cdr(data, entry["type"], views=True)
        kinds |= {(type_.base, type_.array) for _, type_, value in _arrays(msg) if len(value)}
    bases = {base for base, _ in kinds}
    assert {"uint8", "byte", "char", "int8", "int32", "uint64", "float32", "float64"} <= bases
    assert {"fixed", "unbounded", "bounded"} <= {shape for _, shape in kinds}


def test_a_view_is_the_input_itself_not_a_copy():
    scan = LaserScan(ranges=[1.0, 2.0, 3.0], intensities=[0.5])
    data = codec.encode_cdr(scan)
    msg = codec.decode_cdr(data, LaserScan, views=True)
    assert msg.ranges.base is data and msg.intensities.base is data
    empty = codec.encode_cdr(LaserScan())
    assert codec.decode_cdr(empty, LaserScan, views=True).ranges.base is empty  # an empty one too
    assert msg.ranges.dtype == np.dtype("<f4") and msg.ranges.tolist() == [1.0, 2.0, 3.0]
    image = codec.encode_cdr(Image(width=2, data=bytes(range(200)) * 500))
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        pixels = codec.decode_cdr(image, Image, views=True).data
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert pixels.base is image and pixels.dtype == np.uint8 and len(pixels) == 100_000
    assert grown < 10_000  # the 100 kB of pixels were not copied


def test_views_print_as_numpy_arrays_and_echo_as_lists():
    msg = codec.decode_cdr(codec.encode_cdr(LaserScan(ranges=[1.5, 2.5])), LaserScan, views=True)
    assert "ranges=array([1.5, 2.5], dtype=float32)" in repr(msg)
    assert "ranges:\n- 1.5\n- 2.5\n" in codec.to_yaml(msg)
    image = codec.decode_cdr(codec.encode_cdr(Image(data=b"\x01\x02")), Image, views=True)
    assert codec.to_builtins(image)["data"] == [1, 2]
    assert json.loads(codec.encode_json(image))["data"] == [1, 2]


def test_a_mutable_input_is_aliased_read_only_and_pinned():
    buffer = bytearray(codec.encode_cdr(LaserScan(ranges=[1.0, 2.0])))
    msg = codec.decode_cdr(buffer, LaserScan, views=True)
    assert np.shares_memory(msg.ranges, np.frombuffer(buffer, np.uint8))
    with pytest.raises(ValueError, match="read-only"):
        msg.ranges[0] = 9.0
    buffer[-8:-4] = struct.pack("<f", 7.0)  # ranges[1] (intensities' count follows): the message sees it
    assert msg.ranges.tolist() == [1.0, 7.0]
    with pytest.raises(BufferError):
        buffer.extend(b"more")  # pinned while the message's views live
    mv = codec.decode_cdr(memoryview(buffer), LaserScan, views=True).ranges
    assert not mv.flags.writeable


# --------------------------------------------------------------------------- big-endian input


@functools.cache
def _rosbags() -> Any:
    pytest.importorskip("rosbags", reason="big-endian CDR is written by rosbags (test extra)")
    from rosbags.typesys import Stores, get_typestore

    return get_typestore(Stores.ROS2_KILTED)


def _big_endian(data: bytes, ros_type: str) -> bytes | None:
    """``data`` (little-endian CDR) as big-endian CDR, written by rosbags; None for a type rosbags lacks."""
    store = _rosbags()
    if ros_type not in store.fielddefs:
        return None
    return bytes(store.serialize_cdr(store.deserialize_cdr(data, ros_type), ros_type, little_endian=False))


def test_big_endian_input_gives_big_endian_views_and_encodes_little_endian():
    done = 0
    for entry in ENTRIES:
        default = codec.decode_cdr(bytes.fromhex(entry["cdr"]), entry["type"])
        little = codec.encode_cdr(default)  # rclpy's goldens end in a tail rosbags refuses
        big = _big_endian(little, entry["type"])
        if big is None:
            continue
        assert big[:2] == b"\x00\x00"
        views = codec.decode_cdr(big, entry["type"], views=True)
        _check_views(views, big, ">")
        _same_values(views, default)
        assert codec.encode_cdr(views) == little
        done += any(value.dtype.itemsize > 1 and len(value) for _, _, value in _arrays(views))
    assert done >= 10  # LaserScan, Odometry, PointCloud2's neighbours...: multi-byte views were swapped in use


# --------------------------------------------------------------------------- every shape, random values

SHAPES_MSG = """\
string name
int32[3] fixed_ints
uint8[2] fixed_octets
char[] chars
byte[] raw
int16[<=3] bounded
float64[] after_a_string
uint64[2] wide
Inner[] inners
Inner[2] pair
bool[2] flags
float32 tail
"""
INNER_MSG = "string s\nint8[] small\nfloat32[<=2] v\n"


@pytest.fixture(scope="module")
def shapes(tmp_path_factory):
    generated_package(
        tmp_path_factory.mktemp("root") / "cdr_views_root", "cdr_views_pkg", {"Shapes": SHAPES_MSG, "Inner": INNER_MSG}
    )
    return codec.get_type("cdr_views_pkg/msg/Shapes")


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_every_shape_round_trips_through_views(shapes, data):
    msg = message(shapes, DrawPick(data))
    encoded = cdr.encode(msg)
    views = cdr.decode(encoded, shapes, views=True)
    _check_views(views, encoded, "<")
    _same_values(views, cdr.decode(encoded, shapes))
    assert cdr.encode(views) == encoded


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(shipped_messages()), seed=st.integers(0, 2**32))
def test_every_shipped_message_round_trips_through_views(name, seed):
    cls = codec.get_type(name)
    encoded = cdr.encode(message(cls, RandomPick(seed)))
    views = cdr.decode(encoded, cls, views=True)
    _check_views(views, encoded, "<")
    assert cdr.encode(views) == encoded


# --------------------------------------------------------------------------- bad input


def test_truncated_arrays_are_refused_naming_the_field():
    scan = codec.encode_cdr(LaserScan(ranges=[1.0] * 10))
    with pytest.raises(CdrError, match=r"10 items of 4 bytes, \d+ bytes left - at `\$.ranges`"):
        codec.decode_cdr(scan[:-12], LaserScan, views=True)
    odometry = codec.encode_cdr(Odometry())
    with pytest.raises(CdrError, match=r"nav_msgs/msg/Odometry: .* - at `\$.pose.covariance`"):
        codec.decode_cdr(odometry[:120], Odometry, views=True)
    with pytest.raises(CdrError, match=r"unique_identifier_msgs/msg/UUID: .* - at `\$.uuid`"):
        codec.decode_cdr(codec.encode_cdr(UUID())[:10], UUID, views=True)


def test_a_forged_length_is_refused_before_any_view_is_made():
    forged = bytearray(codec.encode_cdr(Image(encoding="rgb8")))
    forged[-4:] = struct.pack("<I", 2**31)  # data's count: two gigabytes, in a message of a few dozen bytes
    with pytest.raises(CdrError, match=r"2147483648 items of 1 bytes, 0 bytes left - at `\$.data`"):
        codec.decode_cdr(bytes(forged), Image, views=True)


@pytest.mark.parametrize("entry", ENTRIES[::5], ids=lambda entry: entry["type"])
def test_every_truncation_is_a_cdr_error_with_views(entry):
    data = cdr.encode(codec.decode_cdr(bytes.fromhex(entry["cdr"]), entry["type"]))
    for end in range(len(data)):
        with pytest.raises(CdrError, match=f"^{entry['type']}: "):
            codec.decode_cdr(data[:end], entry["type"], views=True)


# --------------------------------------------------------------------------- numpy arrays in messages to encode


def test_numpy_vectors_encode_as_their_values_and_bad_ones_are_named():
    assert cdr.encode(LaserScan(ranges=[0.5, 2.0])) == cdr.encode(
        _assigned(LaserScan(), ranges=np.array([0.5, 2.0]))  # float64 into float32[]: each value converted
    )
    assert cdr.encode(Image(data=b"\x01\x03")) == cdr.encode(
        _assigned(Image(), data=np.arange(4, dtype=np.uint8)[1::2])  # a strided slice: its items, in order
    )
    with pytest.raises(CdrError, match=r"1e\+39 is out of range for float32 - at `\$.ranges\[1\]`"):
        cdr.encode(_assigned(LaserScan(), ranges=np.array([1.0, 1e39])))
    with pytest.raises(CdrError, match=r"expected bytes, got ndarray of int16 - at `\$.data`"):
        cdr.encode(_assigned(Image(), data=np.arange(3, dtype=np.int16)))
    with pytest.raises(CdrError, match=r"expected exactly 16 items, got 15 - at `\$.uuid`"):
        cdr.encode(_assigned(UUID(), uuid=np.zeros(15, np.uint8)))


def _assigned(msg: Any, **fields: Any) -> Any:
    # Assigned after construction: the constructor would make an array.array of a numpy vector.
    for name, value in fields.items():
        setattr(msg, name, value)
    return msg


def test_a_published_view_message_is_snapshotted_into_what_rclpy_holds():
    from actors.messages._copy import snapshot

    big = _big_endian(codec.encode_cdr(LaserScan(ranges=[1.5, 2.5])), "sensor_msgs/msg/LaserScan")
    assert big is not None
    sent = snapshot(codec.decode_cdr(big, LaserScan, views=True))
    assert sent.ranges == array("f", [1.5, 2.5]) and sent == LaserScan(ranges=[1.5, 2.5])
    image = snapshot(codec.decode_cdr(codec.encode_cdr(Image(data=b"\x01\x02")), Image, views=True))
    assert image.data == b"\x01\x02" and type(image.data) is bytes
