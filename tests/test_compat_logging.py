"""rclpy.logging on the overlay: the root logger, strict call sites, child loggers on /rosout, log outputs."""

from __future__ import annotations

import logging
from pathlib import Path

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy import logging as rclpy_logging
from actors.compat.rclpy.context import Context
from actors.compat.rclpy.executors import SingleThreadedExecutor
from actors.ros.log import LoggingSeverity
from interfaces.rcl_interfaces.msg import Log


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_the_root_logger_is_what_others_fall_back_to():
    root = rclpy_logging._root_logger
    nodes = logging.getLogger("actors.node")  # what the root logger's level is kept on
    before = nodes.level
    try:
        root.set_level(LoggingSeverity.ERROR)
        leaf = rclpy_logging.get_logger("fallback_leaf")
        assert leaf.get_effective_level() == LoggingSeverity.ERROR
        leaf.set_level(LoggingSeverity.DEBUG)
        assert leaf.get_effective_level() == LoggingSeverity.DEBUG
        rclpy_logging.clear_config()  # every logger's own level forgotten
        assert leaf.get_effective_level() == LoggingSeverity.ERROR
    finally:
        nodes.setLevel(before)


def test_the_root_logger_set_to_unset_lets_every_record_through():
    # rcutils: a named logger at UNSET asks its parent, the root at UNSET has threshold 0.
    root = rclpy_logging._root_logger
    nodes = logging.getLogger("actors.node")
    before = nodes.level
    try:
        root.set_level(LoggingSeverity.UNSET)
        assert root.get_effective_level() == LoggingSeverity.UNSET
        leaf = rclpy_logging.get_logger("unset_leaf")
        assert leaf.get_effective_level() == LoggingSeverity.UNSET
        assert leaf.is_enabled_for(LoggingSeverity.DEBUG)
        root.set_level(LoggingSeverity.WARN)
        assert (root.get_effective_level(), leaf.get_effective_level()) == (LoggingSeverity.WARN,) * 2
        assert not leaf.is_enabled_for(LoggingSeverity.INFO)
    finally:
        nodes.setLevel(before)


def test_a_call_site_keeps_its_severity_name_and_options():
    logger = rclpy_logging.get_logger("strict_sites")

    def once_at(severity: int) -> bool:
        return logger.log("m", severity, once=True)

    assert [once_at(LoggingSeverity.INFO) for _ in range(3)] == [True, False, False]
    with pytest.raises(ValueError, match="severity cannot be changed"):
        once_at(LoggingSeverity.WARN)
    with pytest.raises(ValueError, match="parameters cannot be changed"):
        for seconds in (1, 2):
            logger.log("m", LoggingSeverity.INFO, throttle_duration_sec=seconds)
    with pytest.raises(ValueError, match="name cannot be changed"):
        for name in ("a", "b"):
            logger.log("m", LoggingSeverity.INFO, name=name)


def test_options_are_checked_by_name():
    logger = rclpy_logging.get_logger("checked_options")
    with pytest.raises(TypeError, match="not one of the recognized"):
        logger.info("m", colour="red")
    with pytest.raises(TypeError, match="required parameter 'throttle_duration_sec'"):
        logger.info("m", throttle_time_source_type=object())
    with pytest.raises(TypeError, match="multiple values for argument 'severity'"):
        logger.error("m", severity=LoggingSeverity.DEBUG)
    with pytest.raises(ValueError, match="must not be empty"):
        logger.get_child("")
    with pytest.raises(RuntimeError):
        rclpy_logging.get_logging_severity_from_string("loud")


def test_the_logging_directory_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.delenv("ROS_LOG_DIR", raising=False)
    monkeypatch.delenv("ROS_HOME", raising=False)
    monkeypatch.setenv("HOME", str(tmp_path))
    assert rclpy_logging.get_logging_directory() == tmp_path / ".ros" / "log"
    monkeypatch.setenv("ROS_HOME", "/opt/roshome")
    assert rclpy_logging.get_logging_directory() == Path("/opt/roshome/log")
    monkeypatch.setenv("ROS_LOG_DIR", "/var/ros-logs")
    assert rclpy_logging.get_logging_directory() == Path("/var/ros-logs")


def _heard_on_rosout(node, listener, log) -> list[str]:
    heard: list[str] = []
    listener.create_subscription(Log, "/rosout", lambda msg: heard.append(msg.name), 10)
    log()
    executor = SingleThreadedExecutor(context=listener.context)
    executor.add_node(listener)
    for _ in range(3):
        executor.spin_once(timeout_sec=0.1)
    return heard


def test_child_loggers_reach_rosout_under_their_dotted_names(session):
    node = rclpy.create_node("parent", namespace="/fleet")

    def log() -> None:
        node.get_logger().info("from the node")
        node.get_logger().get_child("arm").get_child("wrist").warning("from a grandchild")

    assert _heard_on_rosout(node, node, log) == ["fleet.parent", "fleet.parent.arm.wrist"]


@pytest.mark.parametrize(
    ("flag", "node_on", "heard"),
    [
        ("--enable-rosout-logs", True, True),
        ("--disable-rosout-logs", True, False),
        ("--enable-rosout-logs", False, False),
    ],
)
def test_rosout_needs_both_the_node_and_the_arguments(session, flag, node_on, heard):
    context = Context()
    context.init(["--ros-args", flag])
    try:
        quiet = rclpy.create_node("maybe_heard", enable_rosout=node_on, context=context)
        listener = rclpy.create_node("rosout_listener", context=context)
        names = _heard_on_rosout(quiet, listener, lambda: quiet.get_logger().info("hello"))
        assert names == (["maybe_heard"] if heard else [])
    finally:
        context.try_shutdown()
