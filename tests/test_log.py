"""Logging: ROS's console form, the runtime clock's stamps, /rosout, level filtering."""

from __future__ import annotations

import io
import logging

import anyio
import pytest

from actors import Node, Runtime
from actors.log import RosFormatter, configure_console
from interfaces.rcl_interfaces.msg import Log


class Chatty(Node):
    def __init__(self) -> None:
        super().__init__("chatty")
        self.create_timer(1.5, self.speak)

    def speak(self) -> None:
        self.get_logger().debug("quiet detail")
        self.get_logger().info("hello")
        self.get_logger().warning("careful")


class RosoutReader(Node):
    def __init__(self) -> None:
        super().__init__("reader")
        self.logs: list[Log] = []
        self.create_subscription(Log, "/rosout", self.logs.append, 100)


@pytest.fixture
def console():
    stream = io.StringIO()
    handler = configure_console(logging.INFO, stream)
    yield stream
    logging.getLogger("actors").removeHandler(handler)
    logging.getLogger("actors").propagate = True
    logging.getLogger("actors").setLevel(logging.NOTSET)


@pytest.mark.virtual_time
async def test_console_lines_have_the_ros_shape_and_clock(console):
    async with Runtime() as rt:
        rt.spawn(Chatty, namespace="robot1")
        await anyio.sleep(2)
    assert console.getvalue().splitlines() == [
        "[INFO] [1.500000000] [robot1.chatty]: hello",
        "[WARN] [1.500000000] [robot1.chatty]: careful",
    ]


@pytest.mark.virtual_time
async def test_records_reach_rosout(console):
    async with Runtime() as rt:
        reader = rt.spawn(RosoutReader)
        rt.spawn(Chatty)
        await anyio.sleep(2)
        logs = [(m.level, m.name, m.msg, m.stamp.sec, m.stamp.nanosec) for m in reader.logs]
    assert logs == [(20, "chatty", "hello", 1, 500_000_000), (30, "chatty", "careful", 1, 500_000_000)]


def test_the_level_filters(console):
    logging.getLogger("actors").setLevel(logging.WARNING)
    logging.getLogger("actors.node.x").info("dropped")
    logging.getLogger("actors.node.x").error("kept")
    (line,) = console.getvalue().splitlines()
    assert line.startswith("[ERROR] [") and line.endswith("] [actors.node.x]: kept")


def test_formatter_without_a_ros_stamp_uses_the_record_time():
    record = logging.LogRecord("actors", logging.ERROR, __file__, 1, "plain", None, None)
    record.created = 12.25
    assert RosFormatter().format(record) == "[ERROR] [12.250000000] [actors]: plain"


def test_log_level_option_filters_the_demo(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "virtual", "--duration", "3", "--log-level", "warn")
    assert result.returncode == 0
    assert "[INFO]" not in result.stdout
