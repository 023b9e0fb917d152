"""pytest plugin (auto-loaded): ``@pytest.mark.virtual_time`` runs an async test on virtual time.

::

    @pytest.mark.virtual_time
    async def test_an_hour():
        await anyio.sleep(3600)   # takes milliseconds

The mark is enough, in pytest-asyncio's ``strict`` mode as in ``auto``: the
plugin adds ``asyncio`` to a marked coroutine test while it is collected, and
hands pytest-asyncio (1.4+) a :class:`~actors.core.loops.VirtualTimeLoop` through
its ``pytest_asyncio_loop_factories`` hook, so the test and its async fixtures
share one virtual clock.  The mark works on a test, a class or a module
(``pytestmark = pytest.mark.virtual_time``).  Unmarked tests are left to
pytest-asyncio as they are: nothing is marked for them, and their loop is the
ordinary one.

It also holds the grading helpers for rclpy exercises: :func:`run_script` runs
a student's unmodified rclpy program (:func:`run_node`, one node class of it)
beside a graph on the virtual clock, and lets the test wait, read topics,
publish and call services (:mod:`actors.compat.grading`).  The ``rclpy_overlay``
fixture gives a test rclpy itself, as ``actors run --clock virtual`` gives it
to a script: the test's thread is the script's.
"""

from __future__ import annotations

import asyncio
import inspect
from collections.abc import Callable, Generator, Iterator, Mapping
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

import pytest

from actors.core.loops import VirtualTimeLoop

if TYPE_CHECKING:
    from actors.compat.grading import ScriptRun

__all__ = [
    "run_script",
    "run_node",
    "rclpy_overlay",
    "pytest_addoption",
    "bag_expectation",
    "pytest_configure",
    "pytest_pycollect_makeitem",
    "pytest_runtest_setup",
    "pytest_asyncio_loop_factories_virtual_time",
    "pytest_asyncio_loop_factories",
]

_MARK = "virtual_time"
_NEEDS = "the virtual_time mark needs pytest-asyncio 1.4 or newer: pip install 'pytest-asyncio>=1.4'"


def pytest_addoption(parser: pytest.Parser) -> None:
    """``--record-bags``: the ``bag_expectation`` fixture writes expected bags instead of comparing."""
    parser.addoption(
        "--record-bags", action="store_true", help="actors: record the expected bags bag_expectation compares with"
    )


@pytest.fixture
def bag_expectation(request: pytest.FixtureRequest) -> Any:
    """An :class:`actors.recording.expect.BagExpectation`: ``bag_expectation.check(actual, expected)``."""
    from actors.recording.expect import BagExpectation

    return BagExpectation(update=request.config.getoption("--record-bags"))


def pytest_configure(config: pytest.Config) -> None:
    """Declare the ``virtual_time`` marker."""
    config.addinivalue_line("markers", f"{_MARK}: run this async test on actors' VirtualTimeLoop (virtual time)")


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_pycollect_makeitem(
    collector: pytest.Module | pytest.Class, name: str, obj: object
) -> Generator[None, Any, Any]:
    """Mark a ``virtual_time`` coroutine test ``asyncio`` before pytest-asyncio looks for the mark.

    pytest-asyncio decides while collecting (in strict mode, by the ``asyncio``
    mark alone), so adding the mark later, when the items exist, is too late.
    """
    if (
        collector.config.pluginmanager.hasplugin("asyncio")
        and inspect.iscoroutinefunction(obj)
        and collector.istestfunction(obj, name)
        and _marked(obj, collector, _MARK)
        and not _marked(obj, collector, "asyncio")
    ):
        pytest.mark.asyncio(obj)
    return (yield)


def _marked(obj: object, collector: pytest.Collector, name: str) -> bool:
    """Whether the function, its class or its module carries the mark ``name``."""
    own = getattr(obj, "pytestmark", [])
    own = own if isinstance(own, list) else [own]
    return any(mark.name == name for mark in own) or collector.get_closest_marker(name) is not None


def pytest_runtest_setup(item: pytest.Item) -> None:
    """Fail a ``virtual_time`` test at once when no pytest-asyncio could give it a virtual loop."""
    if item.get_closest_marker(_MARK) is None:
        return
    manager = item.config.pluginmanager
    if not manager.hasplugin("asyncio") or not hasattr(item.config.hook, "pytest_asyncio_loop_factories"):
        pytest.fail(_NEEDS, pytrace=False)


# pytest-asyncio's hook is firstresult: the first implementation to answer decides.  This
# one (pytest reads only names starting with pytest_, hence the suffix) runs first and
# answers only for marked tests, so a project's own hook (uvloop, say) still decides for
# every other test.
@pytest.hookimpl(optionalhook=True, tryfirst=True, specname="pytest_asyncio_loop_factories")
def pytest_asyncio_loop_factories_virtual_time(
    config: pytest.Config, item: pytest.Item
) -> Mapping[str, Callable[[], Any]] | None:
    """The virtual-time loop for a test marked ``virtual_time``; no answer for any other."""
    if item.get_closest_marker(_MARK) is not None:
        return {_MARK: VirtualTimeLoop}
    return None


# pytest-asyncio requires an answer for every async test once any implementation exists:
# the last word is the loop it would have made without one.
@pytest.hookimpl(optionalhook=True, trylast=True)
def pytest_asyncio_loop_factories(config: pytest.Config, item: pytest.Item) -> Mapping[str, Callable[[], Any]]:
    """An ordinary asyncio loop (from the current event loop policy) for every other async test."""
    return {"asyncio": asyncio.new_event_loop}


def run_script(script: str | Path, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """Run a student's rclpy program, unmodified, beside ``graph``: ``with run_script(...) as run:``.

    See :class:`actors.compat.grading.ScriptRun` for what the test can do with ``run``.
    """
    from actors.compat.grading import run_script as run

    return run(script, *args, graph=graph, clock=clock)


def run_node(node: str | type, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """Spin one node of a student's rclpy node class (``"file.py:Class"``) beside ``graph``."""
    from actors.compat.grading import run_node as run

    return run(node, *args, graph=graph, clock=clock)


@pytest.fixture
def rclpy_overlay() -> Iterator[ModuleType]:
    """``rclpy``, initialized on a virtual-clock runtime, for one test; shut down and put back after.

    While the test runs, ``import rclpy`` and ``from std_msgs.msg import String``
    are actors' (:mod:`actors.compat.overlay`); the test's thread is the script's
    thread, so virtual time moves only while it spins or sleeps through rclpy.
    """
    from actors.compat import Session, overlaid, use_session

    with overlaid(), Session(clock="virtual") as session, use_session(session), session.timekeeping():
        import rclpy

        rclpy.init(args=[])
        try:
            yield rclpy
        finally:
            rclpy.get_default_context().finish()
            rclpy.try_shutdown()
