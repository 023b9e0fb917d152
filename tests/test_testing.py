"""The pytest plugin: ``virtual_time`` alone runs a test on virtual time, in strict and auto mode."""

from __future__ import annotations

import gc

import pytest

pytest_plugins = ["pytester"]

# An hour of virtual time, a fixture on the same loop, and the loop's type checked.
MARKED = """
import asyncio
import anyio
import pytest
import pytest_asyncio
from actors import VirtualTimeLoop

@pytest_asyncio.fixture
async def started():
    return asyncio.get_running_loop()

@pytest.mark.virtual_time
async def test_an_hour_takes_no_time(started):
    loop = asyncio.get_running_loop()
    assert isinstance(loop, VirtualTimeLoop) and started is loop
    await anyio.sleep(3600)
    assert loop.time() >= 3600

@pytest.mark.virtual_time
class TestMarkedClass:
    async def test_in_a_marked_class(self):
        assert isinstance(asyncio.get_running_loop(), VirtualTimeLoop)
"""

UNMARKED = """
import asyncio
from actors import VirtualTimeLoop

async def test_unmarked():
    assert not isinstance(asyncio.get_running_loop(), VirtualTimeLoop)
"""


def run(pytester: pytest.Pytester, mode: str, *args: str) -> pytest.RunResult:
    pytester.makeini(f"[pytest]\nasyncio_mode = {mode}\nasyncio_default_fixture_loop_scope = function\n")
    return pytester.runpytest("-p", "no:cacheprovider", "-p", "no:hypothesispytest", *args)


@pytest.mark.parametrize("mode", ["strict", "auto"])
def test_the_mark_alone_runs_a_test_on_virtual_time(pytester, mode):
    pytester.makepyfile(test_marked=MARKED)
    run(pytester, mode).assert_outcomes(passed=2)


def test_a_module_mark_covers_every_test_in_it(pytester):
    pytester.makepyfile(
        test_module_mark="""
import asyncio
import pytest
from actors import VirtualTimeLoop

pytestmark = pytest.mark.virtual_time

async def test_one():
    assert isinstance(asyncio.get_running_loop(), VirtualTimeLoop)
"""
    )
    run(pytester, "strict").assert_outcomes(passed=1)


@pytest.mark.parametrize("mode", ["strict", "auto"])
def test_an_unmarked_test_is_left_as_pytest_asyncio_leaves_it(pytester, mode):
    pytester.makepyfile(test_unmarked=UNMARKED)
    with_plugin = run(pytester, mode).parseoutcomes()
    without = run(pytester, mode, "-p", "no:actors").parseoutcomes()
    assert with_plugin == without
    # Strict mode does not run an unmarked coroutine; auto mode runs it on a plain loop.
    assert with_plugin.get("passed", 0) == (1 if mode == "auto" else 0)


def test_a_projects_own_loop_factory_still_decides_for_unmarked_tests(pytester):
    pytester.makeconftest(
        """
import asyncio

class OwnLoop(asyncio.SelectorEventLoop):
    pass

def pytest_asyncio_loop_factories(config, item):
    return {"own": OwnLoop}
"""
    )
    pytester.makepyfile(
        test_both="""
import asyncio
import pytest
from actors import VirtualTimeLoop

async def test_unmarked():
    assert type(asyncio.get_running_loop()).__name__ == "OwnLoop"

@pytest.mark.virtual_time
async def test_marked():
    assert isinstance(asyncio.get_running_loop(), VirtualTimeLoop)
"""
    )
    run(pytester, "auto").assert_outcomes(passed=2)


def test_without_pytest_asyncio_a_marked_test_fails_saying_what_to_install(pytester):
    pytester.makepyfile(
        test_lonely="""
import pytest

@pytest.mark.virtual_time
async def test_marked():
    pass
"""
    )
    # The inner session runs in this process with warnings as errors: garbage that earlier tests
    # left (a runtime never closed warns when collected) must be collected before, not in it.
    gc.collect()
    result = pytester.runpytest(
        "-p", "no:cacheprovider", "-p", "no:hypothesispytest", "-p", "no:asyncio", "-W", "error"
    )
    result.assert_outcomes(errors=1)
    result.stdout.fnmatch_lines(["*the virtual_time mark needs pytest-asyncio 1.4 or newer*"])


RCLPY_TEST = """
import time

def test_a_node_spun_in_the_test(rclpy_overlay):
    import rclpy
    from std_msgs.msg import String

    assert rclpy is rclpy_overlay and rclpy.ok()
    node = rclpy.create_node("probe")
    heard = []
    node.create_subscription(String, "beat", lambda msg: heard.append(msg.data), 10)
    pub = node.create_publisher(String, "beat", 10)
    node.create_timer(60.0, lambda: pub.publish(String(data="minute")))
    started = time.monotonic()
    while not heard:
        rclpy.spin_once(node, timeout_sec=120.0)
    assert heard == ["minute"] and node.get_clock().now().nanoseconds == 60 * 10**9
    assert time.monotonic() - started < 30  # a simulated minute, not a real one

def test_outside_the_fixture_rclpy_is_not_actors():
    import sys
    assert "rclpy" not in sys.modules or not sys.modules["rclpy"].__name__.startswith("actors")
"""


def test_the_rclpy_overlay_fixture(pytester):
    pytester.makepyfile(test_rclpy=RCLPY_TEST)
    run(pytester, "strict").assert_outcomes(passed=2)
