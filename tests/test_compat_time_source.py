"""rclpy's clock jump callbacks and TimeSource on the overlay: clocks moved by /clock, on the virtual clock."""

from __future__ import annotations

import threading

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.clock import Clock, ClockChange, JumpThreshold, ROSClock, TimeJump
from actors.compat.rclpy.time_source import CLOCK_TOPIC, TimeSource
from actors.ros.parameter import Parameter
from actors.ros.time import ClockType, Duration, Time
from interfaces.rosgraph_msgs.msg import Clock as ClockMsg


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _recorder() -> tuple[list[str], list[TimeJump], dict[str, object]]:
    events: list[str] = []
    jumps: list[TimeJump] = []
    return events, jumps, {"pre_callback": lambda: events.append("pre"), "post_callback": jumps.append}


def test_thresholds_refuse_what_could_never_fire():
    with pytest.raises(ValueError, match="min_forward"):
        JumpThreshold(min_forward=Duration(seconds=0), min_backward=None)
    with pytest.raises(ValueError, match="min_backward"):
        JumpThreshold(min_forward=None, min_backward=Duration(seconds=2))
    with pytest.raises(ValueError, match="must be enabled"):
        JumpThreshold(min_forward=None, min_backward=None, on_clock_change=False)


def test_a_hand_set_clock_calls_back_only_for_jumps_past_the_threshold():
    clock = ROSClock()
    events, jumps, callbacks = _recorder()
    big = JumpThreshold(min_forward=Duration(seconds=2), min_backward=Duration(seconds=-1), on_clock_change=False)
    with clock.create_jump_callback(big, **callbacks):
        clock.set_ros_time_override(Time(seconds=10))  # ROS time is off: setting it is no jump
        clock._set_ros_time_is_active(True)  # a source change, which this threshold ignores
        clock.set_ros_time_override(Time(seconds=11))  # one second forward: under the threshold
        assert events == [] and jumps == []
        clock.set_ros_time_override(Time(seconds=14))
        clock.set_ros_time_override(Time(seconds=12.5))
    clock.set_ros_time_override(Time(seconds=100))  # unregistered on leaving the with
    assert events == ["pre", "pre"]
    assert [(j.clock_change, j.delta.nanoseconds) for j in jumps] == [
        (ClockChange.ROS_TIME_NO_CHANGE, 3_000_000_000),
        (ClockChange.ROS_TIME_NO_CHANGE, -1_500_000_000),
    ]


def test_switching_ros_time_calls_back_once_per_change():
    clock = Clock(clock_type=ClockType.ROS_TIME)
    assert isinstance(clock, ROSClock)
    events, jumps, callbacks = _recorder()
    handle = clock.create_jump_callback(JumpThreshold(min_forward=None, min_backward=None), **callbacks)
    clock._set_ros_time_is_active(True)
    clock._set_ros_time_is_active(True)  # no change, no call
    clock._set_ros_time_is_active(False)
    handle.unregister()
    handle.unregister()
    clock._set_ros_time_is_active(True)
    assert events == ["pre", "pre"]
    assert [j.clock_change for j in jumps] == [ClockChange.ROS_TIME_ACTIVATED, ClockChange.ROS_TIME_DEACTIVATED]
    assert all(j.delta.nanoseconds == 0 for j in jumps)


def test_a_sleep_on_ros_time_ends_when_the_time_is_set_past_it(session):
    clock = ROSClock()
    clock._set_ros_time_is_active(True)
    clock.set_ros_time_override(Time(seconds=5))
    result: list[bool] = []
    wake_at = Time(seconds=8, clock_type=ClockType.ROS_TIME)
    sleeper = threading.Thread(target=lambda: result.append(clock.sleep_until(wake_at)))
    sleeper.start()
    session.sleep(0.5)
    clock.set_ros_time_override(Time(seconds=7))  # not yet
    session.sleep(0.5)
    assert result == []
    clock.set_ros_time_override(Time(seconds=8))
    sleeper.join()
    assert result == [True]


def test_a_sleep_ends_false_when_ros_time_is_switched_off(session):
    clock = ROSClock()
    clock._set_ros_time_is_active(True)
    result: list[bool] = []
    sleeper = threading.Thread(target=lambda: result.append(clock.sleep_for(Duration(seconds=60))))
    sleeper.start()
    session.sleep(0.5)
    clock._set_ros_time_is_active(False)
    sleeper.join()
    assert result == [False]


def test_a_nodes_clock_follows_the_clock_topic_while_use_sim_time_is_true(session):
    node = rclpy.create_node("sim_timed")
    clock = node.get_clock()
    assert isinstance(clock, ROSClock)
    assert clock.now().nanoseconds == session.runtime.clock.now_ns()  # the runtime's time by default
    _, jumps, callbacks = _recorder()
    clock.create_jump_callback(JumpThreshold(min_forward=Duration(seconds=1), min_backward=None), **callbacks)
    feeder = rclpy.create_node("clock_feeder")
    pub = feeder.create_publisher(ClockMsg, CLOCK_TOPIC, 10)

    node.set_parameters([Parameter("use_sim_time", Parameter.Type.BOOL, True)])
    assert clock.ros_time_is_active
    assert clock.now() == Time(seconds=0, clock_type=ClockType.ROS_TIME)  # no /clock message yet
    for sec in (100, 100.5, 103):
        msg = ClockMsg()
        msg.clock.sec, msg.clock.nanosec = int(sec), int(sec % 1 * 1e9)
        pub.publish(msg)
        rclpy.spin_once(node, timeout_sec=1)
    assert clock.now() == Time(seconds=103, clock_type=ClockType.ROS_TIME)
    # The first message jumped from zero, the last by 2.5 s; half a second was under the threshold.
    assert [j.delta for j in jumps if j.clock_change == ClockChange.ROS_TIME_NO_CHANGE] == [
        Duration(seconds=100),
        Duration(seconds=2.5),
    ]

    node.set_parameters([Parameter("use_sim_time", Parameter.Type.BOOL, False)])
    assert clock.now().nanoseconds == session.runtime.clock.now_ns()  # back on the runtime's (virtual) time
    assert [j.clock_change for j in jumps][-1] == ClockChange.ROS_TIME_DEACTIVATED


def test_use_sim_time_takes_only_a_bool(session):
    node = rclpy.create_node("strict_sim_time")
    results = node.set_parameters([Parameter("use_sim_time", Parameter.Type.INTEGER, 1)])
    assert not results[0].successful
    assert node.get_parameter("use_sim_time").value is False
    assert node.get_clock().now().nanoseconds == session.runtime.clock.now_ns()


def test_a_time_source_drives_every_clock_attached_even_late(session):
    node = rclpy.create_node("source_owner")
    source = TimeSource(node=node)
    early = ROSClock()
    source.attach_clock(early)
    with pytest.raises(ValueError):
        source.attach_clock(Clock(clock_type=ClockType.STEADY_TIME))
    source.ros_time_is_active = True
    source.clock_callback(ClockMsg(clock=Time(seconds=42).to_msg()))
    late = ROSClock()
    source.attach_clock(late)
    assert early.now() == late.now() == Time(seconds=42, clock_type=ClockType.ROS_TIME)
    source.detach_node()
    assert source._get_node() is None
