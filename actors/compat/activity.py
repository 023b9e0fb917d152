"""What virtual time waits for: script threads at work, and the way they block on the runtime.

A script thread is *busy* while it runs Python code and *waiting* while it is
blocked in an rclpy call (spin, a service wait, ``Rate.sleep``...).  Virtual
time must never jump while a script thread is busy (its callback would see a
clock that moved under it), and must jump while every script thread waits
(otherwise ``spin()`` on a timer would never return).

Each busy party holds a :class:`Token`: the thread that runs the script, every
thread that ever waited through a :class:`Waiter`, and each callback handed to
an executor until it has run (it may run on a pool thread the runtime never
saw).  A thread blocks only through a :class:`Waiter`: it marks its token idle,
waits on an event, and is woken by whoever has work for it, *which marks the
token busy before waking it*.  Wakers are busy themselves (the loop thread, or
another script thread), so the loop can never see a moment where nobody is
busy while a wake-up is in flight.  Timeouts are loop timers that wake the
waiter, so every wait is measured on the runtime clock, virtual or not.

:class:`ScriptTimeLoop` is the virtual-time loop that asks the activity
whether anyone is busy before it jumps.

A thread a script starts is busy from ``start()``, before it runs at all, until
it first waits on the runtime (``threading.Thread(target=rclpy.spin)`` must not
miss a tick however late the OS runs it).  Until then it is *fresh*: one that
parks in a wait of :mod:`threading` (or is a thread pool's idle worker) outside
actors' own calls does not count while it is parked, so a script's own pools
and helper threads do not stop the clock.  A fresh thread that neither waits
nor parks (blocked in a C call: a socket, the keyboard) holds virtual time
still for :data:`HOLD_WARNING` real seconds; then a warning names it and time
goes on without it, so that a run with ``--duration`` still ends.

Not covered: a parked fresh thread that a script thread wakes (``queue.put``)
counts as parked until the OS runs it, so time may move in between; threads
that exchange work with rclpy code should wait through rclpy (or be started
before the work they wait for exists).
"""

from __future__ import annotations

import concurrent.futures.thread
import functools
import logging
import os
import sys
import sysconfig
import threading
import time
import weakref
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType
from typing import Any

from actors.core.loops import VirtualTimeLoop
from actors.ros.log import ROOT_LOGGER

__all__ = ["Activity", "Token", "Waiter", "ScriptTimeLoop", "HOLD_WARNING", "run_as"]

#: Real seconds a fresh thread may hold virtual time still before a warning names it.
HOLD_WARNING = 5.0

# Real seconds between looks at fresh threads while they hold virtual time: one that parks does
# not wake the loop, so the loop looks again.
_LOOK_AGAIN = 0.005

# Where a thread is parked, as its innermost Python frame shows it: waiting on a Condition (so in
# Event.wait, Queue.get, Semaphore.acquire...), joining a thread, or a thread pool's worker idle in
# its queue's get (a C call, so the worker's own frame is the innermost one).
_PARKED = frozenset(
    {
        threading.Condition.wait.__code__,
        # Thread.join waits in _wait_for_tstate_lock up to Python 3.12, in join itself (a C call) after.
        getattr(threading.Thread, "_wait_for_tstate_lock", threading.Thread.join).__code__,
        concurrent.futures.thread._worker.__code__,
    }
)

_STDLIB = sysconfig.get_paths()["stdlib"] + os.sep
_ACTORS = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep  # the actors package


class Token:
    """One party's share of the activity: busy or idle; bound to a thread or not.

    A *fresh* token is a started thread's that has not waited on the runtime
    yet: see :meth:`Activity.starting`.  ``held_since`` is when it was last seen
    holding virtual time without being parked (real seconds), for the warning.
    """

    __slots__ = ("busy", "thread", "fresh", "held_since", "warned", "__weakref__")

    def __init__(self, thread: threading.Thread | None, fresh: bool = False) -> None:
        self.busy = True
        self.thread = thread
        self.fresh = fresh
        self.held_since: float | None = None
        self.warned = False


class Activity:
    """The busy tokens of every script thread and pending callback of one session."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self._tokens: set[Token] = set()
        self._local = threading.local()
        self._loop: Any = None
        self._watchers: set[Waiter] = set()
        self.fresh_working = False  # a fresh thread held time at the last look: look again soon

    def attach(self, loop: Any) -> None:
        """The loop to wake when someone goes idle (so it may jump)."""
        self._loop = loop

    def busy(self) -> bool:
        """Whether any live thread or pending callback is busy (a parked fresh thread is not)."""
        busy, self.fresh_working = self._holding(None)
        return busy

    def busy_besides(self, token: Token) -> bool:
        """Whether anyone but ``token``'s holder is busy (a parked fresh thread is not)."""
        return self._holding(token)[0]

    def _holding(self, besides: Token | None) -> tuple[bool, bool]:
        # Whether anyone holds the clock, and whether only fresh threads do (they may park unseen).
        with self.lock:
            gone = [t for t in self._tokens if t.thread is not None and not t.thread.is_alive()]
            self._tokens.difference_update(gone)
            busy = [t for t in self._tokens if t.busy and t is not besides]
        if not busy:
            return False, False
        fresh = [(t, t.thread) for t in busy if t.fresh and t.thread is not None]
        if len(fresh) < len(busy):
            return True, False
        # Only threads that never waited on the runtime are busy: working, or parked?
        frames = sys._current_frames()
        now = time.monotonic()
        working = False
        for token, thread in fresh:
            ident = thread.ident  # set: the thread has started (its token is bound to it when it runs)
            frame = frames.get(ident) if ident is not None else None
            if frame is None or token.warned or _parked(frame):
                token.held_since = None
                continue
            if token.held_since is None:
                token.held_since = now
            elif now - token.held_since >= HOLD_WARNING:
                # Blocked in a C call, most likely (a socket, input()): named, and let go, so
                # that a run with --duration still ends.
                token.warned = True
                _warn_holding(thread, frame)
                continue
            working = True
        if working:
            return True, True
        # A fresh thread may have woken someone and then parked since the tokens were read.
        with self.lock:
            return any(t.busy and not t.fresh and t is not besides for t in self._tokens), False

    @contextmanager
    def starting_workers(self) -> Iterator[None]:
        """Threads started by this thread inside the block are pool workers: the callbacks they run
        hold their own tokens, so the threads themselves take no part."""
        self._local.workers = True
        try:
            yield
        finally:
            self._local.workers = False

    def starts_workers(self) -> bool:
        """Whether the calling thread is inside :meth:`starting_workers`."""
        return bool(getattr(self._local, "workers", False))

    def starting(self, thread: threading.Thread) -> Token:
        """A fresh, busy token for ``thread``, which a script thread is about to start; it adopts it.

        A thread may start and then wait on the runtime at once (``rclpy.spin`` on
        a thread of its own): it holds virtual time still from now until it
        waits, however late it first runs.  But it may also never wait on the
        runtime (a pool's idle worker): while it is parked it does not count.
        """
        token = Token(None, fresh=True)
        with self.lock:
            self._tokens.add(token)
        thread.run = functools.partial(run_as, self, token, thread.run)  # type: ignore[method-assign]  # this thread's run, wrapped
        return token

    def current(self) -> Token:
        """The token of the calling thread (made, busy, on first use)."""
        token: Token | None = getattr(self._local, "token", None)
        if token is None:
            token = Token(threading.current_thread())
            with self.lock:
                self._tokens.add(token)
            self._local.token = token
        return token

    def has_token(self) -> bool:
        """Whether the calling thread takes part (it waited on the runtime, or runs a callback)."""
        return getattr(self._local, "token", None) is not None

    def work(self) -> Token:
        """A busy token for a callback that some thread will run later; :meth:`done` ends it."""
        token = Token(None)
        with self.lock:
            self._tokens.add(token)
        return token

    def done(self, token: Token) -> None:
        """``token``'s work is over."""
        with self.lock:
            self._tokens.discard(token)
            self.idle(token)
        self.poke()

    def running(self, token: Token) -> _Running:
        """Let ``token`` stand for the calling thread while it runs that token's work.

        The thread's own token (if it has one) is idle meanwhile, so that a wait
        inside the work idles the thread entirely.
        """
        return _Running(self, token)

    def adopt(self, token: Token) -> None:
        """Make ``token`` (from :meth:`work`) the calling thread's own: a thread started for it."""
        with self.lock:
            token.thread = threading.current_thread()
        self._local.token = token

    def set_busy(self, token: Token, busy: bool) -> None:
        """Mark ``token`` busy or idle."""
        with self.lock:
            if busy:
                token.busy = True
            else:
                self.idle(token)
        if not busy:
            self.poke()

    def idle(self, token: Token) -> None:
        """Mark ``token`` idle and wake the watchers, in one step: call it with :attr:`lock` held.

        Done together, the loop never sees everyone idle while a watcher is about
        to be woken (it would jump before the watcher looked).  Then :meth:`poke`.
        """
        token.busy = False
        for waiter in self._watchers:
            waiter._token.busy = True
            waiter._event.set()

    def finish_on_collect(self, owner: object, token: Token) -> weakref.finalize:
        """End ``token`` if ``owner`` is garbage collected before its work ran; calling what this
        returns ends it now instead, and nothing runs at collection."""
        return weakref.finalize(owner, self.done, token)

    def watch(self, waiter: Waiter) -> None:
        """Wake ``waiter`` whenever a token goes idle, as it goes idle (until :meth:`unwatch`)."""
        with self.lock:
            self._watchers.add(waiter)

    def unwatch(self, waiter: Waiter) -> None:
        """Stop waking ``waiter``."""
        with self.lock:
            self._watchers.discard(waiter)

    def poke(self) -> None:
        """Someone went idle: wake the loop, which may wait in real time while anyone is busy."""
        loop = self._loop
        if isinstance(loop, VirtualTimeLoop) and not loop.is_closed():
            try:
                loop.call_soon_threadsafe(_nothing)
            except RuntimeError:  # closed meanwhile
                pass


def run_as(activity: Activity, token: Token, run: Callable[[], object]) -> None:
    """A thread's whole life: ``run()`` with ``token`` as the thread's own, ended when it returns."""
    activity.adopt(token)
    try:
        run()
    finally:
        activity.done(token)  # a thread that ends no longer holds the clock: tell the loop now


class _Running:
    def __init__(self, activity: Activity, token: Token) -> None:
        self._activity = activity
        self._token = token
        self._previous: Token | None = None

    def __enter__(self) -> Token:
        activity = self._activity
        self._previous = getattr(activity._local, "token", None)
        with activity.lock:
            self._token.busy = True
            if self._previous is not None:
                self._previous.busy = False
        activity._local.token = self._token
        return self._token

    def __exit__(self, *exc: object) -> None:
        activity = self._activity
        if self._previous is not None:
            activity.set_busy(self._previous, True)
        activity._local.token = self._previous


def _nothing() -> None:
    return None


class Waiter:
    """Blocks one thread until someone wakes it; the thread counts as waiting, not busy, meanwhile.

    The owner calls :meth:`clear`, checks its condition, then :meth:`wait`;
    whoever changes the condition calls :meth:`wake` afterwards.  A wake-up
    between the check and the wait is never lost.
    """

    __slots__ = ("_activity", "_token", "_event", "__weakref__")

    def __init__(self, activity: Activity) -> None:
        self._activity = activity
        self._token = activity.current()
        self._event = threading.Event()

    def clear(self) -> None:
        """Forget earlier wake-ups (before checking the condition again)."""
        self._event.clear()

    def wake(self) -> None:
        """Wake the waiting thread (from any thread); it is busy from this moment."""
        with self._activity.lock:
            self._token.busy = True
            self._event.set()

    def wait(self) -> None:
        """Block until :meth:`wake` (at once if it came already); KeyboardInterrupt gets through."""
        activity = self._activity
        with activity.lock:
            self._token.fresh = False  # a thread that waits on the runtime is a script thread for good
            if self._event.is_set():
                return
            activity.idle(self._token)
        self._activity.poke()
        try:
            self._event.wait()
        finally:
            with self._activity.lock:
                self._token.busy = True


class ScriptTimeLoop(VirtualTimeLoop):
    """The virtual-time loop of a session: it does not jump while a script thread is busy."""

    def __init__(self, activity: Activity, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.activity = activity
        activity.attach(self)

    def threads_busy(self) -> bool:
        busy = super().threads_busy() or self.activity.busy()
        self.busy_poll = _LOOK_AGAIN if self.activity.fresh_working else None
        return busy


def _parked(frame: FrameType) -> bool:
    # Parked in a wait of threading's, and not inside a call of actors' own (a call to the loop
    # thread waits on a Condition too, but the thread is at work then), up to where it began.
    if frame.f_code not in _PARKED:
        return False
    caller: FrameType | None = frame
    while caller is not None and caller.f_code is not run_as.__code__:
        if caller.f_code.co_filename.startswith(_ACTORS):
            return False
        caller = caller.f_back
    return True


def _warn_holding(thread: threading.Thread, frame: FrameType) -> None:
    # Name the script's own frame, not the standard library's under it (Event.is_set, socket...).
    shown: FrameType | None = frame
    while shown is not None and shown.f_code.co_filename.startswith(_STDLIB):
        shown = shown.f_back
    frame = shown or frame
    logging.getLogger(ROOT_LOGGER).warning(
        "virtual time waits for thread %r (started by the script; now in %s at %s:%d), which has "
        "not waited on rclpy for %g s of real time: virtual time goes on without it from now",
        thread.name,
        frame.f_code.co_name,
        frame.f_code.co_filename,
        frame.f_lineno,
        HOLD_WARNING,
    )
