"""Numeric sequences held as rclpy holds them: an ``array.array`` of the ROS type's typecode, however made."""

from __future__ import annotations

from array import array

import numpy as np
import pytest

from actors import codec
from actors.errors import MessageValidationError
from actors.messages._copy import snapshot
from actors.messages.arrays import held
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import Int32MultiArray
from interfaces.test_msgs.msg import Arrays, BoundedSequences, UnboundedSequences

# What rclpy (Kilted) holds in test_msgs' sequences, read from its own messages: array.array of
# these typecodes.  uint8[] and byte[] are bytes here (rclpy: array('B') and a list of bytes), bool[]
# and string[] lists as in rclpy.
RCLPY_TYPECODES = {
    "char_values": "B",
    "float32_values": "f",
    "float64_values": "d",
    "int8_values": "b",
    "int16_values": "h",
    "uint16_values": "H",
    "int32_values": "i",
    "uint32_values": "I",
    "int64_values": "q",
    "uint64_values": "Q",
}
VALUES = {name: [1, 2, 3] if code not in "fd" else [0.5, 1.5, 2.5] for name, code in RCLPY_TYPECODES.items()}


def _held(msg: object) -> dict[str, str]:
    """Each numeric field's type and typecode, ``array.f`` for an ``array('f')``."""
    return {
        name: f"{type(getattr(msg, name)).__name__}.{getattr(getattr(msg, name), 'typecode', '')}"
        for name in RCLPY_TYPECODES
    }


EXPECTED = {name: f"array.{code}" for name, code in RCLPY_TYPECODES.items()}


@pytest.mark.parametrize("cls", [UnboundedSequences, BoundedSequences, Arrays])
def test_every_numeric_sequence_is_an_array_of_rclpys_typecode_however_the_message_was_made(cls):
    made = cls(**VALUES)
    plain = codec.to_builtins(made)
    ways = {
        "default": cls(),
        "constructor, from lists": made,
        "constructor, from numpy": cls(**{name: np.array(v) for name, v in VALUES.items()}),
        "CDR": codec.decode_cdr(codec.encode_cdr(made), cls),
        "msgpack": codec.decode(codec.encode(made), cls),
        "JSON": codec.decode_json(codec.encode_json(made), cls),
        "plain data": codec.convert(plain, cls),
        "snapshot": snapshot(made),
    }
    assert {way: _held(msg) for way, msg in ways.items()} == dict.fromkeys(ways, EXPECTED)
    assert all(msg == made for way, msg in ways.items() if way != "default")
    assert plain["int32_values"] == [1, 2, 3] and type(plain["int32_values"]) is list
    assert (type(made.uint8_values), type(made.bool_values), type(made.string_values)) == (bytes, list, list)


def test_a_list_assigned_after_construction_is_an_array_in_what_subscribers_receive():
    scan = LaserScan()
    scan.ranges = [1.0, 2.0]  # a struct has no setter: the field holds the list until publish()
    received = snapshot(scan)
    assert received.ranges == array("f", [1.0, 2.0]) and received.ranges.typecode == "f"


@pytest.mark.parametrize(
    ("msg", "error"),
    [
        (LaserScan(ranges=[1.0, 1e39]), r"field 'ranges\[1\]' of sensor_msgs/msg/LaserScan: 1e\+39 is out of range"),
        (LaserScan(ranges=[True]), r"field 'ranges\[0\]' .*: expected a float, got the bool True"),
        (LaserScan(ranges=["1"]), r"field 'ranges\[0\]' .*: expected a float, got the str '1'"),
        (Int32MultiArray(data=[2**31]), r"field 'data\[0\]' .*: 2147483648 is out of range for int32"),
    ],
)
def test_what_does_not_fit_stays_as_given_and_publish_names_it(msg, error):
    assert type(msg.ranges if isinstance(msg, LaserScan) else msg.data) is list  # not made into inf or 0
    with pytest.raises(MessageValidationError, match=error):
        snapshot(msg)


def test_held_converts_only_what_fits_exactly():
    assert held([1.0, float("inf")], "f") == array("f", [1.0, float("inf")])
    assert held(np.array([1, 2], dtype=np.int64), "i") == array("i", [1, 2])
    assert held([True, 2], "i") == array("i", [1, 2])  # rclpy takes a bool for an int
    for value, code in ([1e39], "f"), ([1.0], "i"), (b"\x00\x00\x80?", "f"), (np.array([True]), "d"), ([256], "B"):
        assert held(value, code) is value
    for code in "fi":  # an iterator is read once, whole; what is no sequence stays for publish() to name
        assert held((x for x in [1, 2]), code) == array(code, [1, 2]) and held(range(2), code) == array(code, [0, 1])
        assert held(None, code) is None and held(5.0, code) == 5.0


def test_a_field_prints_as_rclpys_does_and_compares_as_its_arrays_do():
    msg = Int32MultiArray(data=[0, 1, 1])
    assert repr(msg.data) == "array('i', [0, 1, 1])" == f"{msg.data!r}"  # what an rclpy action client logs
    assert (
        msg == Int32MultiArray(data=array("i", [0, 1, 1])) == codec.decode_cdr(codec.encode_cdr(msg), Int32MultiArray)
    )
    assert msg.data != [0, 1, 1] and list(msg.data) == [0, 1, 1]  # as in rclpy: an array is no list
    assert codec.to_yaml(msg).endswith("data:\n- 0\n- 1\n- 1\n")
