"""A node's parameters: rclpy's semantics for declaring, reading, setting, callbacks and events."""

from __future__ import annotations

import logging

import anyio
import pytest

from actors import Node, Parameter, ParameterError, Runtime
from actors.errors import (
    InvalidParameterException,
    InvalidParameterTypeException,
    InvalidParameterValueException,
    ParameterAlreadyDeclaredException,
    ParameterException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from actors.ros.parameter_store import ParameterType, value_from_msg, value_to_msg
from interfaces.rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    ParameterEvent,
    SetParametersResult,
)
from interfaces.rcl_interfaces.srv import GetParameters
from nodes.param_talker import MinimalParam

pytestmark = pytest.mark.virtual_time


class Tuned(Node):
    def __init__(self) -> None:
        super().__init__("tuned")
        self.declare_parameter(
            "speed",
            0.5,
            ParameterDescriptor(
                description="m/s", floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]
            ),
        )
        self.declare_parameter(
            "count", 3, ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=1)])
        )
        self.declare_parameter("model", "burger", ParameterDescriptor(read_only=True))
        self.declare_parameter("names", ["a", "b"])
        self.declare_parameter("flag", False)
        self.add_on_set_parameters_callback(self.veto)

    def veto(self, params: list[Parameter]) -> SetParametersResult:
        for p in params:
            if p.name == "count" and p.value == 7:
                return SetParametersResult(successful=False, reason="7 is unlucky")
        return SetParametersResult(successful=True)


class Bare(Node):
    """A node that declares nothing itself: each test declares what it needs."""

    def __init__(self, **options: object) -> None:
        super().__init__("bare", **options)


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
        assert node.describe_parameter("speed").type == ParameterType.DOUBLE  # filled in from the default
        with pytest.raises(ParameterNotDeclaredException, match="not declared"):
            node.get_parameter("nope")
        with pytest.raises(ParameterAlreadyDeclaredException, match="already declared"):
            node.declare_parameter("speed", 1.0)
        with pytest.raises(InvalidParameterException):
            node.declare_parameter("", 1)


def test_the_exceptions_are_rclpys_under_parameter_error():
    for error in (
        ParameterNotDeclaredException,
        ParameterAlreadyDeclaredException,
        InvalidParameterException,
        InvalidParameterTypeException,
        InvalidParameterValueException,
        ParameterImmutableException,
        ParameterUninitializedException,
    ):
        assert issubclass(error, ParameterError)
    assert ParameterException is ParameterError


@pytest.mark.parametrize(
    ("param", "reason"),
    [
        (Parameter("model", value="waffle"), "read-only"),
        (Parameter("speed", value="fast"), "Wrong parameter type, expected 'Type.DOUBLE' got 'Type.STRING'"),
        (Parameter("speed", value=1.5), "out of range [0.0, 1.0]"),
        (Parameter("count", value=11), "out of range [0, 10]"),
        (Parameter("count", value=7), "7 is unlucky"),
        (Parameter("count"), "Static parameter cannot be undeclared"),
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


async def test_setting_an_undeclared_name_raises_and_keeps_what_came_before():
    async with Runtime() as rt:
        node = rt.spawn(Tuned)
        with pytest.raises(ParameterNotDeclaredException, match="ghost"):
            node.set_parameters([Parameter("count", value=4), Parameter("ghost", value=1), Parameter("count", value=5)])
        assert node.get_parameter("count").value == 4  # set before the undeclared one; the last one never ran
        with pytest.raises(ParameterNotDeclaredException):
            node.set_parameters_atomically([Parameter("count", value=6), Parameter("ghost", value=1)])
        assert node.get_parameter("count").value == 4


async def test_undeclared_parameters_when_allowed():
    async with Runtime() as rt:
        node = rt.spawn(Bare, allow_undeclared_parameters=True)
        assert node.get_parameter("ghost").type_ is ParameterType.NOT_SET  # no error
        assert node.get_parameter_type("ghost") is ParameterType.NOT_SET
        (result,) = node.set_parameters([Parameter("fresh", value=3)])
        assert result.successful and node.get_parameter("fresh").value == 3
        assert node.describe_parameter("fresh").dynamic_typing  # implicitly declared, any type
        (result,) = node.set_parameters([Parameter("fresh", value="now a string")])
        assert result.successful


async def test_each_accepted_change_appears_once_on_parameter_events():
    async with Runtime() as rt:
        log = rt.spawn(EventLog)
        node = rt.spawn(Tuned)
        results = node.set_parameters(
            [
                Parameter("speed", value=0.75),
                Parameter("count", value=7),
                Parameter("count", value=4),
                Parameter("speed", value=1),
            ]
        )
        assert [r.successful for r in results] == [True, False, True, True]
        assert node.get_parameter("speed").value == 1.0  # an int widens to a double
        await anyio.sleep(0.1)
        assert changed(log.events) == [("speed", 0.75), ("count", 4), ("speed", 1.0)]
        assert all(e.node == "/tuned" for e in log.events)
        declared = [p.name for e in log.events for p in e.new_parameters]
        assert declared == ["use_sim_time", "speed", "count", "model", "names", "flag"]


async def test_a_node_whose_parameters_nobody_used_yet_has_use_sim_time_and_does_not_announce_it_late():
    # Nobody listened when it started: its store is made at first use, with use_sim_time,
    # which a listener that came since does not hear of (at the start it was not announced either).
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        log = rt.spawn(EventLog)
        node.declare_parameter("gain", 0.5)
        await anyio.sleep(0.1)
        assert [p.name for e in log.events for p in e.new_parameters] == ["gain"]
        assert node.list_parameters([], 0).names == ["use_sim_time", "gain"]
        assert node.get_parameter("use_sim_time").value is False
        other = rt.spawn(Bare, name="other")
        got = await log._core.create_client(GetParameters, "/other/get_parameters").call(
            GetParameters.Request(names=["use_sim_time"]), timeout=1
        )
        assert [value_from_msg(v) for v in got.values] == [False]  # its services read the store made now
        assert other.has_parameter("use_sim_time")


async def test_an_int_is_accepted_for_a_double_everywhere():
    # Our documented difference: rclpy refuses all three as the wrong type.
    async with Runtime() as rt:
        node = rt.spawn(Bare, params={"gain": 2})
        assert node.declare_parameter("gain", 0.5).value == 2.0
        assert isinstance(node.get_parameter("gain").value, float)
        node.declare_parameter("gains", [0.5, 1.5])
        assert node.set_parameters([Parameter("gains", value=[1, 2])])[0].successful
        assert node.get_parameter("gains").value == [1.0, 2.0]
        assert Parameter("g", Parameter.Type.DOUBLE, 3).value == 3.0
        assert not node.set_parameters([Parameter("gain", value=True)])[0].successful  # a bool is no number here


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
        with pytest.raises(InvalidParameterTypeException, match="Wrong parameter type, expected"):
            rt.spawn(Tuned, name="other", params={"count": "three"})


async def test_declaring_with_a_type_leaves_the_parameter_unset():
    async with Runtime() as rt:
        node = rt.spawn(Bare, params={"given": 5, "wrong": "five"})
        unset = node.declare_parameter("port", Parameter.Type.INTEGER)
        assert (unset.type_, unset.value) == (ParameterType.NOT_SET, None)
        assert node.describe_parameter("port").type == ParameterType.INTEGER
        with pytest.raises(ParameterUninitializedException):
            node.get_parameter("port")
        assert node.get_parameter_or("port", Parameter("alt", value=1)).value == 1
        assert node.get_parameter_or("port").type_ is ParameterType.NOT_SET
        assert node.declare_parameter("given", Parameter.Type.INTEGER).value == 5  # the override fills it
        with pytest.raises(InvalidParameterTypeException):
            node.declare_parameter("wrong", Parameter.Type.INTEGER)
        assert not node.has_parameter("wrong")
        (refused,) = node.set_parameters([Parameter("port", value="eighty")])
        assert not refused.successful and "expected 'Type.INTEGER'" in refused.reason
        (accepted,) = node.set_parameters([Parameter("port", value=80)])
        assert accepted.successful and node.get_parameter("port").value == 80
        with pytest.raises(ValueError):
            node.declare_parameter("nothing", Parameter.Type.NOT_SET)
        with pytest.raises(ValueError):
            node.declare_parameter("both", Parameter.Type.DOUBLE, ParameterDescriptor(dynamic_typing=True))
        with pytest.raises(ValueError):
            node.declare_parameter("untyped", None, ParameterDescriptor())  # neither default nor type


async def test_a_name_alone_declares_a_dynamically_typed_parameter():
    async with Runtime() as rt:
        node = rt.spawn(Bare, params={"from_graph": [1, 2]})
        assert node.declare_parameter("anything").value is None
        assert node.get_parameter("anything").type_ is ParameterType.NOT_SET  # dynamic: reading it is fine
        assert node.declare_parameter("from_graph").value == [1, 2]
        assert node.set_parameters([Parameter("anything", value="text")])[0].successful
        assert node.set_parameters([Parameter("anything", value=3.5)])[0].successful
        assert node.describe_parameter("anything").type == ParameterType.DOUBLE


async def test_ranges_apply_to_numbers_only():
    ranged = ParameterDescriptor(
        integer_range=[IntegerRange(from_value=0, to_value=1)],
        floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)],
    )
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        assert node.declare_parameter("label", "far out of any range", ranged).value == "far out of any range"
        assert node.set_parameters([Parameter("label", value="still fine")])[0].successful
        node.declare_parameter(
            "ratio",
            0.5,
            ParameterDescriptor(floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0, step=0.25)]),
        )
        assert node.set_parameters([Parameter("ratio", value=1.0 + 1e-9)])[0].successful  # a bound, within tolerance
        (off_step,) = node.set_parameters([Parameter("ratio", value=0.3)])
        assert not off_step.successful and "step of 0.25" in off_step.reason
        reversed_bounds = ParameterDescriptor(integer_range=[IntegerRange(from_value=10, to_value=0)])
        with pytest.raises(InvalidParameterValueException, match="out of range"):
            node.declare_parameter("level", 50, reversed_bounds)
        assert node.declare_parameter("level", 5, reversed_bounds).value == 5  # bounds in either order


async def test_on_set_callbacks_run_at_declaration_and_may_refuse_it():
    seen: list[list[str]] = []

    def no_rejects(params: list[Parameter]) -> SetParametersResult:
        seen.append([p.name for p in params])
        ok = not any(p.name.startswith("reject") for p in params)
        return SetParametersResult(successful=ok, reason="" if ok else "rejects are refused")

    async with Runtime() as rt:
        node = rt.spawn(Bare)
        node.add_on_set_parameters_callback(no_rejects)
        node.declare_parameter("kept", 1)
        with pytest.raises(InvalidParameterValueException, match="rejects are refused"):
            node.declare_parameter("reject_me", 1)
        assert not node.has_parameter("reject_me")
        assert seen == [["kept"], ["reject_me"]]


async def test_set_callbacks_pre_on_post_in_rclpys_order():
    calls: list[str] = []

    def first(params):
        calls.append("first")
        return SetParametersResult(successful=True)

    def second(params):
        calls.append("second")
        return SetParametersResult(successful=params[0].value != 13, reason="13 is refused")

    def also_set_mirror(params):
        calls.append("pre")
        return [*params, Parameter("mirror", value=params[0].value)] if params[0].name == "x" else params

    post: list[list[tuple[str, object]]] = []
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        node.add_on_set_parameters_callback(first)
        node.add_on_set_parameters_callback(second)  # the newest runs first, as in rclpy
        node.add_post_set_parameters_callback(lambda params: post.append([(p.name, p.value) for p in params]))
        node.declare_parameter("x", 1)
        node.declare_parameter("mirror", 0)
        assert calls == ["second", "first", "second", "first"]  # declarations run on-set callbacks...
        node.add_pre_set_parameters_callback(also_set_mirror)
        calls.clear()
        assert node.set_parameters([Parameter("x", value=2)])[0].successful
        assert calls == ["pre", "second", "first"]  # ...but not pre-set ones
        assert node.get_parameter("mirror").value == 2
        assert post == [[("x", 1)], [("mirror", 0)], [("x", 2), ("mirror", 2)]]
        (refused,) = node.set_parameters([Parameter("x", value=13)])
        assert not refused.successful and refused.reason == "13 is refused"
        assert len(post) == 3  # no post-set call for a refused set
        node.remove_pre_set_parameters_callback(also_set_mirror)
        node.remove_on_set_parameters_callback(second)
        assert node.set_parameters([Parameter("x", value=13)])[0].successful
        assert node.get_parameter("mirror").value == 2
        with pytest.raises(ValueError):
            node.remove_on_set_parameters_callback(second)
        node.add_pre_set_parameters_callback(lambda params: [])
        (emptied,) = node.set_parameters([Parameter("x", value=4)])
        assert not emptied.successful and emptied.reason.startswith("parameter list cannot be empty")


async def test_setting_not_set_undeclares_a_dynamically_typed_parameter():
    async with Runtime() as rt:
        log = rt.spawn(EventLog)
        node = rt.spawn(Bare)
        node.declare_parameter("loose", 1, ParameterDescriptor(dynamic_typing=True))
        node.declare_parameter("strict", 1)
        (result,) = node.set_parameters([Parameter("loose")])
        assert result.successful and not node.has_parameter("loose")
        (result,) = node.set_parameters([Parameter("strict")])
        assert not result.successful and node.has_parameter("strict")
        await anyio.sleep(0.1)
        assert [p.name for e in log.events for p in e.deleted_parameters] == ["loose"]


async def test_undeclare_and_read_only():
    async with Runtime() as rt:
        node = rt.spawn(Tuned)
        node.undeclare_parameter("flag")
        assert not node.has_parameter("flag")
        with pytest.raises(ParameterNotDeclaredException):
            node.undeclare_parameter("flag")
        with pytest.raises(ParameterImmutableException):
            node.undeclare_parameter("model")
        assert node.get_parameter("model").value == "burger"


async def test_reading_by_prefix_describing_and_listing():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        node.declare_parameters("arm", [("speed", 0.5), ("joint.limit", 2), ("name", "left")])
        node.declare_parameter("armrest", True)
        by_prefix = node.get_parameters_by_prefix("arm")
        assert {k: p.value for k, p in by_prefix.items()} == {"speed": 0.5, "joint.limit": 2, "name": "left"}
        assert set(node.get_parameters_by_prefix("")) == {
            "arm.speed",
            "arm.joint.limit",
            "arm.name",
            "armrest",
            "use_sim_time",
        }
        assert [d.type for d in node.describe_parameters(["arm.speed", "armrest"])] == [
            ParameterType.DOUBLE,
            ParameterType.BOOL,
        ]
        with pytest.raises(ParameterNotDeclaredException):
            node.describe_parameters(["arm.speed", "nope"])
        assert node.get_parameter_types(["arm.name", "armrest"]) == [ParameterType.STRING, ParameterType.BOOL]
        one_deep = node.list_parameters(["arm"], 1)
        assert (one_deep.names, one_deep.prefixes) == (["arm.speed", "arm.name"], ["arm"])
        # In declaration order, as rclpy answers (`param list` sorts for display).
        assert node.list_parameters(["arm"], 0).names == ["arm.speed", "arm.joint.limit", "arm.name"]
        assert node.list_parameters([], 1).names == ["use_sim_time", "armrest"]
        with pytest.raises(ParameterAlreadyDeclaredException):
            node.declare_parameters("arm", [("fresh", 1), ("speed", 1.0)])
        assert not node.has_parameter("arm.fresh")  # none declared when one is taken
        # A name given twice in one call: declared once, with its last entry (where rclpy ends too).
        twice = node.declare_parameters(
            "arm", [("grip", 1), ("reach", 0.8), ("grip", 2, ParameterDescriptor(description="later"))]
        )
        assert [(p.name, p.value) for p in twice] == [("arm.grip", 2), ("arm.reach", 0.8), ("arm.grip", 2)]
        assert node.describe_parameter("arm.grip").description == "later"


async def test_set_descriptor_keeps_a_fitting_value_or_takes_the_alternative():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        node.declare_parameter("level", 4, ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10)]))
        narrower = ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=5)])
        assert value_from_msg(node.set_descriptor("level", narrower)) == 4
        tighter = ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=3)])
        assert value_from_msg(node.set_descriptor("level", tighter, value_to_msg(2))) == 2
        assert node.describe_parameter("level").integer_range[0].to_value == 3
        assert node.describe_parameter("level").type == ParameterType.INTEGER
        with pytest.raises(InvalidParameterValueException):
            node.set_descriptor("level", ParameterDescriptor(integer_range=[IntegerRange(from_value=20, to_value=30)]))
        assert node.get_parameter("level").value == 2
        node.declare_parameter("fixed", 1, ParameterDescriptor(read_only=True))
        with pytest.raises(ParameterImmutableException):
            node.set_descriptor("fixed", ParameterDescriptor())
        with pytest.raises(ParameterNotDeclaredException):
            node.set_descriptor("ghost", ParameterDescriptor())


async def test_automatically_declare_parameters_from_overrides():
    class Blackboard(Node):
        def __init__(self) -> None:
            super().__init__(
                "blackboard",
                parameter_overrides=[Parameter("mine", value="constructor")],
                automatically_declare_parameters_from_overrides=True,
            )

    async with Runtime() as rt:
        node = rt.spawn(Blackboard, params={"from_graph": 3, "use_sim_time": True})
        assert node.get_parameter("mine").value == "constructor"
        assert node.get_parameter("from_graph").value == 3
        assert node.get_parameter("use_sim_time").value is True
        with pytest.raises(ParameterAlreadyDeclaredException):
            node.declare_parameter("from_graph", 0)


async def test_every_node_has_use_sim_time():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        assert node.get_parameter("use_sim_time").value is False
        assert node.describe_parameter("use_sim_time").type == ParameterType.BOOL
        assert node.set_parameters([Parameter("use_sim_time", value=True)])[0].successful
        assert not node.set_parameters([Parameter("use_sim_time", value="yes")])[0].successful
        with pytest.raises(ParameterAlreadyDeclaredException):
            node.declare_parameter("use_sim_time", False)
        other = rt.spawn(Bare, name="other")
        assert other.get_parameter("use_sim_time").value is False  # each node's own
        assert other.describe_parameter("use_sim_time") == ParameterDescriptor(name="use_sim_time", type=1)
        assert other.describe_parameter("use_sim_time") is not node.describe_parameter("use_sim_time")
        given = rt.spawn(Bare, name="given", params={"use_sim_time": True})
        assert given.get_parameter("use_sim_time").value is True
        with pytest.raises(InvalidParameterTypeException, match="use_sim_time"):
            rt.spawn(Bare, name="wrong", params={"use_sim_time": "yes"})


async def test_param_talker_says_hello_to_the_override_first(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        rt.spawn(MinimalParam, params={"my_parameter": "earth"})
        await anyio.sleep(3.5)
    hellos = [r.getMessage() for r in caplog.records if r.getMessage().startswith("Hello")]
    assert hellos == ["Hello earth!", "Hello world!", "Hello world!"]
