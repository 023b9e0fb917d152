"""Parameters: declaring, overrides, refused sets that keep the old value, events, services."""

from __future__ import annotations

import logging

import anyio
import pytest

from actors import Node, Parameter, ParameterError, Runtime
from actors.params import ParameterType, value_from_msg, value_to_msg
from interfaces.rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    ParameterEvent,
    SetParametersResult,
)
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters, SetParameters
from nodes.param_talker import MinimalParam

pytestmark = pytest.mark.virtual_time


class Tuned(Node):
    def __init__(self) -> None:
        super().__init__("tuned")
        self.declare_parameter("speed", 0.5, ParameterDescriptor(
            description="m/s", floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]))
        self.declare_parameter("count", 3, ParameterDescriptor(
            integer_range=[IntegerRange(from_value=0, to_value=10, step=1)]))
        self.declare_parameter("model", "burger", ParameterDescriptor(read_only=True))
        self.declare_parameter("names", ["a", "b"])
        self.declare_parameter("flag", False)
        self.add_on_set_parameters_callback(self.veto)

    def veto(self, params: list[Parameter]) -> SetParametersResult:
        for p in params:
            if p.name == "count" and p.value == 7:
                return SetParametersResult(successful=False, reason="7 is unlucky")
        return SetParametersResult(successful=True)


class EventLog(Node):
    def __init__(self) -> None:
        super().__init__("event_log")
        self.events: list[ParameterEvent] = []
        self.create_subscription(ParameterEvent, "/parameter_events", self.events.append, 100)


def changed(events: list[ParameterEvent]) -> list[tuple[str, object]]:
    return [(p.name, value_from_msg(p.value)) for e in events for p in e.changed_parameters]


async def test_declared_values_and_types():
    async with Runtime() as rt:
        node = rt.spawn(Tuned)
        assert node.get_parameter("speed").value == 0.5
        assert node.get_parameter("names").type_ is ParameterType.STRING_ARRAY
        assert node.get_parameter("flag").type_ is ParameterType.BOOL
        assert node.describe_parameter("speed").description == "m/s"
        with pytest.raises(ParameterError, match="not declared"):
            node.get_parameter("nope")
        with pytest.raises(ParameterError, match="already declared"):
            node.declare_parameter("speed", 1.0)


@pytest.mark.parametrize(
    ("param", "reason"),
    [
        (Parameter("model", value="waffle"), "read-only"),
        (Parameter("speed", value="fast"), "wrong type: expected DOUBLE, got STRING"),
        (Parameter("speed", value=1.5), "out of range [0.0, 1.0]"),
        (Parameter("count", value=11), "out of range [0, 10]"),
        (Parameter("count", value=7), "7 is unlucky"),
        (Parameter("ghost", value=1), "not declared"),
    ],
)
async def test_refused_sets_keep_the_old_value_and_say_why(param, reason):
    async with Runtime() as rt:
        node = rt.spawn(Tuned)
        log = rt.spawn(EventLog)
        before = {n: node.get_parameter(n).value for n in ("model", "speed", "count")}
        (result,) = node.set_parameters([param])
        assert not result.successful and reason in result.reason
        assert {n: node.get_parameter(n).value for n in before} == before
        await anyio.sleep(0.1)
        assert changed(log.events) == []


async def test_each_accepted_change_appears_once_on_parameter_events():
    async with Runtime() as rt:
        log = rt.spawn(EventLog)
        node = rt.spawn(Tuned)
        results = node.set_parameters([Parameter("speed", value=0.75), Parameter("count", value=7),
                                       Parameter("count", value=4), Parameter("speed", value=1)])
        assert [r.successful for r in results] == [True, False, True, True]
        assert node.get_parameter("speed").value == 1.0  # an int widens to a double
        await anyio.sleep(0.1)
        assert changed(log.events) == [("speed", 0.75), ("count", 4), ("speed", 1.0)]
        assert all(e.node == "/tuned" for e in log.events)
        declared = [p.name for e in log.events for p in e.new_parameters]
        assert declared == ["speed", "count", "model", "names", "flag"]


async def test_set_atomically_is_all_or_nothing():
    async with Runtime() as rt:
        node = rt.spawn(Tuned)
        result = node.set_parameters_atomically([Parameter("speed", value=0.1), Parameter("count", value=99)])
        assert not result.successful
        assert node.get_parameter("speed").value == 0.5


async def test_overrides_from_spawn_win_and_are_type_checked():
    async with Runtime() as rt:
        node = rt.spawn(Tuned, params={"speed": 0.9, "model": "waffle"})
        assert node.get_parameter("speed").value == 0.9
        assert node.get_parameter("model").value == "waffle"  # read-only, but set at launch
        with pytest.raises(ParameterError, match="wrong type: expected"):
            rt.spawn(Tuned, name="other", params={"count": "three"})


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
        assert listed.result.names == ["count", "flag", "model", "names", "speed"]
        got = await core.create_client(GetParameters, "/tuned/get_parameters").call(
            GetParameters.Request(names=["speed", "names"]), timeout=1)
        assert [value_from_msg(v) for v in got.values] == [0.5, ["a", "b"]]
        setter = core.create_client(SetParameters, "/tuned/set_parameters")
        response = await setter.call(SetParameters.Request(parameters=[
            ParameterMsg(name="speed", value=value_to_msg(0.25)),
            ParameterMsg(name="model", value=value_to_msg("x"))]), timeout=1)
        assert [r.successful for r in response.results] == [True, False]
        described = await core.create_client(DescribeParameters, "/tuned/describe_parameters").call(
            DescribeParameters.Request(names=["count"]), timeout=1)
        assert described.descriptors[0].integer_range[0].to_value == 10
        assert rt.node("tuned").get_parameter("speed").value == 0.25


async def test_param_talker_says_hello_to_the_override_first(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        rt.spawn(MinimalParam, params={"my_parameter": "earth"})
        await anyio.sleep(3.5)
    hellos = [r.getMessage() for r in caplog.records if r.getMessage().startswith("Hello")]
    assert hellos == ["Hello earth!", "Hello world!", "Hello world!"]


def test_parameter_values_round_trip_through_messages():
    for value in [True, 3, 2.5, "s", b"\x01\x02", [True, False], [1, 2], [1.5, 2.0], ["x"]]:
        assert value_from_msg(value_to_msg(value)) == value
    with pytest.raises(ValueError):
        value_to_msg([1, "mixed"])
