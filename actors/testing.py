"""pytest plugin (auto-loaded): ``@pytest.mark.virtual_time`` runs an async test on virtual time.

::

    @pytest.mark.asyncio          # not needed with asyncio_mode = "auto"
    @pytest.mark.virtual_time
    async def test_an_hour():
        await anyio.sleep(3600)   # takes milliseconds

The test's loop is a :class:`~actors.clock.VirtualTimeLoop`, provided through
pytest-asyncio's ``pytest_asyncio_loop_factories`` hook (pytest-asyncio 1.4+).
Unmarked async tests keep an ordinary asyncio loop.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Mapping
from typing import Any

import pytest

from actors.clock import VirtualTimeLoop

__all__ = ["pytest_configure", "pytest_asyncio_loop_factories"]


def pytest_configure(config: pytest.Config) -> None:
    """Declare the ``virtual_time`` marker."""
    config.addinivalue_line(
        "markers", "virtual_time: run this async test on actors' VirtualTimeLoop (virtual time)"
    )


@pytest.hookimpl(optionalhook=True, trylast=True)
def pytest_asyncio_loop_factories(
    config: pytest.Config, item: pytest.Item
) -> Mapping[str, Callable[[], Any]]:
    """The virtual-time loop for tests marked ``virtual_time``, a plain asyncio loop otherwise."""
    if item.get_closest_marker("virtual_time") is not None:
        return {"virtual_time": VirtualTimeLoop}
    return {"asyncio": asyncio.new_event_loop}
