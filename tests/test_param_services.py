"""A node's parameter services: what the command line and parameter clients talk to."""

from __future__ import annotations

import pytest

from actors import Node, Runtime
from actors.params import ParameterType, value_from_msg, value_to_msg
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.srv import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    SetParameters,
    SetParametersAtomically,
)
from test_params import Bare, Tuned

pytestmark = pytest.mark.virtual_time


async def test_the_parameter_services():
    class Asker(Node):
        def __init__(self) -> None:
            super().__init__("asker")

    async with Runtime() as rt:
        rt.spawn(Tuned)
        asker = rt.spawn(Asker)
        core = asker._core
        listed = await core.create_client(ListParameters, "/tuned/list_parameters").call(
            ListParameters.Request(), timeout=1)
        # Declaration order, as rclpy answers: use_sim_time first (the node's own), then the class's.
        assert listed.result.names == ["use_sim_time", "speed", "count", "model", "names", "flag"]
        got = await core.create_client(GetParameters, "/tuned/get_parameters").call(
            GetParameters.Request(names=["speed", "names", "ghost"]), timeout=1)
        assert [value_from_msg(v) for v in got.values] == [0.5, ["a", "b"], None]
        types = await core.create_client(GetParameterTypes, "/tuned/get_parameter_types").call(
            GetParameterTypes.Request(names=["speed", "ghost"]), timeout=1)
        assert list(types.types) == [ParameterType.DOUBLE, ParameterType.NOT_SET]  # uint8[]: bytes
        setter = core.create_client(SetParameters, "/tuned/set_parameters")
        response = await setter.call(SetParameters.Request(parameters=[
            ParameterMsg(name="speed", value=value_to_msg(0.25)),
            ParameterMsg(name="model", value=value_to_msg("x")),
            ParameterMsg(name="ghost", value=value_to_msg(1))]), timeout=1)
        assert [r.successful for r in response.results] == [True, False, False]
        assert "not declared" in response.results[2].reason  # an answer, not an exception
        atomic = await core.create_client(SetParametersAtomically, "/tuned/set_parameters_atomically").call(
            SetParametersAtomically.Request(parameters=[
                ParameterMsg(name="count", value=value_to_msg(5)),
                ParameterMsg(name="count", value=value_to_msg(70))]), timeout=1)
        assert not atomic.result.successful and rt.node("tuned").get_parameter("count").value == 3
        described = await core.create_client(DescribeParameters, "/tuned/describe_parameters").call(
            DescribeParameters.Request(names=["count"]), timeout=1)
        assert described.descriptors[0].integer_range[0].to_value == 10
        assert rt.node("tuned").get_parameter("speed").value == 0.25


async def test_a_node_can_do_without_parameter_services():
    async with Runtime() as rt:
        rt.spawn(Bare, start_parameter_services=False)
        assert not [name for name in rt.services.servers if name.startswith("/bare/")]
