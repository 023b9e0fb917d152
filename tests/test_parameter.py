"""A parameter's value and type: agreement checks, rclpy's inference, messages both ways."""

from __future__ import annotations

import pytest

from actors.ros.parameter import Parameter, value_from_msg, value_to_msg


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
    for value in [True, 3, 2.5, "s", b"\x01\x02", [True, False], [1, 2], [1.5, 2.0], ["x"]]:
        assert value_from_msg(value_to_msg(value)) == value
    assert value_to_msg([b"\x01", b"\x02"]).byte_array_value == b"\x01\x02"  # rclpy's list of bytes
    with pytest.raises(TypeError):
        value_to_msg([1, "mixed"])
