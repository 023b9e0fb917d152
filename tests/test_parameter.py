"""A parameter's value and type: agreement checks, rclpy's inference, messages both ways."""

from __future__ import annotations

from array import array

import pytest

from actors.ros.parameter import Parameter, value_from_msg, value_to_msg
from interfaces.rcl_interfaces.msg import ParameterValue


def test_a_parameter_checks_its_value_against_its_type():
    with pytest.raises(ValueError):
        Parameter("p", Parameter.Type.INTEGER, "not a number")
    with pytest.raises(TypeError):
        Parameter("p", 2, 1)  # a plain number is not a Parameter.Type
    with pytest.raises(TypeError):
        Parameter("p", value=object())
    param = Parameter("p", value=[True, False])
    assert param.type_ is Parameter.Type.BOOL_ARRAY
    with pytest.raises(AttributeError):
        param.value = [False]  # type: ignore[misc]
    assert Parameter("p", value=[]).type_ is Parameter.Type.BYTE_ARRAY  # rclpy's reading of an empty list


def test_parameter_values_round_trip_through_messages():
    for value in [True, 3, 2.5, "s", b"\x01\x02", [True, False], ["x"]]:
        assert value_from_msg(value_to_msg(value)) == value
    # Number lists come back as the message holds them, an array, as in rclpy (where a decoded
    # message and one built from a list hold the same array, so the two compare equal).
    assert value_from_msg(value_to_msg([1, 2])) == array("q", [1, 2])
    assert value_from_msg(value_to_msg([1.5, 2])) == array("d", [1.5, 2.0])
    assert value_to_msg([1, 2]) == ParameterValue(type=7, integer_array_value=[1, 2])
    assert value_to_msg([b"\x01", b"\x02"]).byte_array_value == b"\x01\x02"  # rclpy's list of bytes
    with pytest.raises(TypeError):
        value_to_msg([1, "mixed"])
