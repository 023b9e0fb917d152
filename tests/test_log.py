"""Logging: ROS's console form, the runtime clock's stamps, /rosout, levels, rclpy's once/throttle/skip_first."""

from __future__ import annotations

import io
import logging
import time

import anyio
import pytest

from actors import Node, Runtime
from actors.ros.log import (
    LoggingSeverity,
    RosFormatter,
    configure_console,
    get_logger,
    get_logger_effective_level,
    get_logger_level,
    get_logging_severity_from_string,
    set_logger_level,
)
from actors.ros.time import ClockType, ROSClock, Time
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


@pytest.mark.slow
def test_log_level_option_filters_the_demo(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "virtual", "--duration", "3", "--log-level", "warn")
    assert result.returncode == 0
    assert "[INFO]" not in result.stdout


# -- rclpy's logging filters and levels ----------------------------------------------


def test_once_is_per_call_site_not_per_text():
    logger = get_logger("filters")
    first_site = [logger.warning(f"tick {i}", once=True) for i in range(4)]
    assert first_site == [True, False, False, False]  # a changing text is still the same call site
    assert logger.warning("tick 0", once=True)  # another line: its own once
    assert [logger.warning("again", once=False) for _ in range(2)] == [True, True]


def test_two_calls_on_one_line_are_two_call_sites():
    logger = get_logger("filters")
    assert [logger.warning("a", once=True), logger.warning("b", once=True)] == [True, True]


def test_skip_first_and_its_order_with_once():
    logger = get_logger("filters")
    assert [logger.warning("m", skip_first=True) for _ in range(3)] == [False, True, True]
    assert [logger.warning("m", skip_first=True, once=True) for _ in range(4)] == [False, True, False, False]


def test_throttle_on_a_clock_given_and_skip_first_after_it():
    clock = ROSClock()
    clock._set_ros_time_is_active(True)
    logger = get_logger("filters")
    logged, skipped = [], []
    for tenths in range(0, 17, 4):  # 0, 0.4, 0.8, 1.2, 1.6 s
        clock.set_ros_time_override(Time(nanoseconds=tenths * 100_000_000, clock_type=ClockType.ROS_TIME))
        logged.append(logger.warning("t", throttle_duration_sec=1, throttle_time_source_type=clock))
        skipped.append(logger.warning("t", throttle_duration_sec=1, throttle_time_source_type=clock, skip_first=True))
    assert logged == [True, False, False, True, False]  # the first call logs, even at time 0
    assert skipped == [False, False, False, True, False]  # throttled first, then the first one skipped


@pytest.mark.virtual_time
async def test_throttle_follows_the_nodes_clock(console):
    class Busy(Node):
        def __init__(self) -> None:
            super().__init__("busy")
            self.create_timer(0.1, lambda: self.get_logger().info("busy", throttle_duration_sec=1.0))

    async with Runtime() as rt:
        rt.spawn(Busy)
        await anyio.sleep(3.05)
    stamps = [line.split("] [")[1] for line in console.getvalue().splitlines()]
    assert stamps == ["0.100000000", "1.100000000", "2.100000000"]


def test_a_call_site_cannot_change_its_filters():
    logger = get_logger("filters")
    with pytest.raises(ValueError, match="parameters cannot be changed"):
        for duration in (1, 2):
            logger.warning("m", throttle_duration_sec=duration)
    with pytest.raises(ValueError, match="severity cannot be changed"):
        for level in (LoggingSeverity.WARN, LoggingSeverity.ERROR):
            logger.log("m", level, once=True)


def test_filters_are_not_consulted_below_the_level():
    logger = get_logger("quiet_filters")
    logger.set_level(LoggingSeverity.ERROR)
    assert [logger.warning("m", once=True) for _ in range(2)] == [False, False]
    logger.set_level(LoggingSeverity.WARN)
    assert logger.warning("m", once=True)  # a different line; the one above never logged
    logger.set_level(LoggingSeverity.UNSET)


def test_levels_by_name_and_number():
    logger = get_logger("levels.child")
    set_logger_level("levels", "debug")
    assert get_logger_level("levels.child") is LoggingSeverity.UNSET
    assert logger.get_effective_level() is LoggingSeverity.DEBUG  # inherited from its parent
    assert get_logger_effective_level("levels.child") is LoggingSeverity.DEBUG
    logger.set_level(LoggingSeverity.ERROR)
    assert not logger.is_enabled_for(LoggingSeverity.WARN) and logger.is_enabled_for(40)
    assert get_logging_severity_from_string("Warn") is LoggingSeverity.WARN
    with pytest.raises(ValueError):
        logger.set_level("loud")
    with pytest.raises(ValueError):
        get_logger("")
    with pytest.raises(ValueError):
        logger.get_child("")
    assert logger.get_child("leaf").name == "levels.child.leaf"
    set_logger_level("levels", LoggingSeverity.UNSET)
    logger.set_level(0)


def test_a_free_logger_prints_in_the_ros_form_with_the_system_clock(console):
    before = time.time()
    assert get_logger("free").info("hi")
    (line,) = console.getvalue().splitlines()
    level, stamp, rest = line.split(" ", 2)
    assert (level, rest) == ("[INFO]", "[free]: hi")
    assert abs(float(stamp.strip("[]")) - before) < 60


EMBEDDED = """
import logging
import anyio
from actors import Runtime, VirtualTimeLoop
from nodes.talker import MinimalPublisher

{setup}

async def main():
    async with Runtime() as rt:
        rt.spawn(MinimalPublisher)
        await anyio.sleep(0.75)

anyio.run(main, backend_options={{"loop_factory": VirtualTimeLoop}})
"""


@pytest.mark.parametrize(
    ("setup", "expected"),
    [
        # Nothing configured: INFO on stderr in ROS's form, as rclpy prints it.
        ("", ['[INFO] [0.500000000] [minimal_publisher]: Publishing: "Hello World: 0"']),
        # The application configured logging: its choice stands.
        ("logging.basicConfig(level=logging.WARNING)", []),
        ("logging.getLogger('actors').setLevel(logging.ERROR)", []),
    ],
)
def test_an_embedded_runtime_prints_info_on_stderr_unless_logging_is_configured(setup, expected):
    import subprocess
    import sys

    from conftest import ROOT, python_env

    result = subprocess.run(
        [sys.executable, "-c", EMBEDDED.format(setup=setup)],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert (result.returncode, result.stdout) == (0, "")
    assert result.stderr.splitlines() == expected


class LevelsServed(Node):
    def __init__(self) -> None:
        super().__init__("served", namespace="robot2", enable_logger_service=True)
        self.create_timer(1.0, lambda: self.get_logger().debug("detail"))


class LevelsAsker(Node):
    def __init__(self) -> None:
        from interfaces.rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels

        super().__init__("asker")
        self.get = self.create_client(GetLoggerLevels, "/robot2/served/get_logger_levels")
        self.set = self.create_client(SetLoggerLevels, "/robot2/served/set_logger_levels")


@pytest.mark.virtual_time
async def test_the_logger_service_reads_and_sets_levels_remotely(console):
    from interfaces.rcl_interfaces.msg import LoggerLevel
    from interfaces.rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels

    name = "robot2.served"
    try:
        async with Runtime() as rt:
            reader = rt.spawn(RosoutReader)
            rt.spawn(LevelsServed)
            asker = rt.spawn(LevelsAsker)
            await anyio.sleep(1.5)  # the tick at 1.0 logs nothing: debug is off
            before = await asker.get.call(GetLoggerLevels.Request(names=[name]))
            answer = await asker.set.call(
                SetLoggerLevels.Request(
                    levels=[LoggerLevel(name=name, level=LoggerLevel.LOG_LEVEL_DEBUG), LoggerLevel(name=name, level=15)]
                )
            )
            after = await asker.get.call(GetLoggerLevels.Request(names=[name, "nobody"]))
            await anyio.sleep(1)  # the tick at 2.0 logs its detail
            served = {name for name, _ in reader.get_service_names_and_types()}
        assert [(entry.name, entry.level) for entry in before.levels] == [(name, 0)]  # never set: unset
        assert [(r.successful, r.reason) for r in answer.results] == [
            (True, ""),
            (False, "Failed reason: Invalid logger level."),
        ]  # the bad level left DEBUG in place
        assert [(entry.name, entry.level) for entry in after.levels] == [(name, 10), ("nobody", 0)]
        assert [(m.name, m.msg) for m in reader.logs if m.name == name] == [(name, "detail")]
        assert "/robot2/served/set_logger_levels" in served and "/asker/get_logger_levels" not in served  # opt-in
    finally:
        set_logger_level(name, "unset")
