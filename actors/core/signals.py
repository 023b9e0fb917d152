"""How our commands take SIGINT, SIGTERM and SIGHUP: all three stop a run as Ctrl-C does.

A long-running command (``python -m actors.run``, ``actors launch``, ``actors
run``, ``topic echo``, ``bag record``...) stops the same way whichever of the
three it gets, and from its first moment: the handlers go in before the slow
part of start-up (loading the runtime's modules, the graph's nodes, a Zenoh
session), so a signal then is a clean exit too, not a traceback, a death by
signal or a control socket left behind.

- :func:`remember_stops` is for code that cannot yet take an exception where it
  stands (the imports at the top of ``python -m actors.run``, an event loop
  starting before the graph listens): a stop signal is noted, and raised later
  by :func:`raise_stops`, or taken by :func:`take_noted`.
- :func:`raise_stops` makes all three raise ``KeyboardInterrupt``, as Python
  does for Ctrl-C: synchronous commands stop where they block, and an event
  loop started afterwards (``asyncio.Runner``) treats them as it treats Ctrl-C
  until the graph listens for them itself (:data:`STOP_SIGNALS`).

A signal the process inherited as ignored (``nohup`` ignores SIGHUP, a shell's
background job SIGINT) stays ignored: that was asked for.  Only the main
thread can set handlers; elsewhere these functions do nothing.
"""

from __future__ import annotations

import _thread
import os
import signal
import threading
import time
from collections.abc import Callable
from types import FrameType
from typing import Any

__all__ = ["STOP_SIGNALS", "remember_stops", "raise_stops", "stop_signals", "take_noted"]

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)

_noted: list[int] = []
_AGAIN = 0.01  # seconds before a signal that landed inside an import is sent again
_IMPORT_GRACE = 2.0  # seconds an import may take to finish before a stop interrupts it anyway
_deferred: dict[int, float] = {}  # when each signal was first put off for an import


def stop_signals() -> tuple[signal.Signals, ...]:
    """The stop signals this process takes (those it did not inherit as ignored)."""
    return tuple(s for s in STOP_SIGNALS if signal.getsignal(s) is not signal.SIG_IGN)


def remember_stops() -> None:
    """Until :func:`raise_stops`, a stop signal is only noted."""
    _install(_note)


def raise_stops() -> None:
    """From now on a stop signal raises ``KeyboardInterrupt``; one noted before raises it now."""
    _install(_interrupt)
    if _noted:
        _noted.clear()
        raise KeyboardInterrupt


def _interrupt(signum: int, frame: FrameType | None) -> None:
    # An exception in the middle of an import breaks what it was building: importlib's module locks
    # (the next import of that module waits forever) or an extension's half-made state (msgspec
    # crashed building a decoder).  There the signal is sent again a moment later, until it lands
    # outside any import, or until a module that never finishes importing has had its grace.
    if _importing(frame):
        first = _deferred.setdefault(signum, time.monotonic())
        if time.monotonic() - first < _IMPORT_GRACE:
            _thread.start_new_thread(_send_again, (signum,))
            return
    _deferred.pop(signum, None)
    raise KeyboardInterrupt


def _importing(frame: FrameType | None) -> bool:
    while frame is not None:
        if frame.f_code.co_filename.startswith("<frozen importlib"):
            return True
        frame = frame.f_back
    return False


def _send_again(signum: int) -> None:
    time.sleep(_AGAIN)  # a bare thread of its own: real time, whatever the run's clock
    os.kill(os.getpid(), signum)


def take_noted() -> bool:
    """Whether a stop signal was noted since :func:`remember_stops` (and forget it)."""
    noted = bool(_noted)
    _noted.clear()
    return noted


def _note(signum: int, frame: FrameType | None) -> None:
    _noted.append(signum)


def _install(handler: Callable[[int, FrameType | None], Any]) -> None:
    if threading.current_thread() is not threading.main_thread():
        return
    for sig in stop_signals():
        signal.signal(sig, handler)
