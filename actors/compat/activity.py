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
"""

from __future__ import annotations

import threading
import time
import weakref
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from actors.clock import VirtualTimeLoop

__all__ = ["Activity", "Token", "Waiter", "ScriptTimeLoop"]


class Token:
    """One party's share of the activity: busy or idle; bound to a thread or not.

    ``until`` (a ``time.monotonic()`` deadline) makes a new thread's token count
    as busy only for a while, unless the thread waits on the runtime first:
    see :meth:`Activity.starting`.
    """

    __slots__ = ("busy", "thread", "until", "__weakref__")

    def __init__(self, thread: threading.Thread | None, until: float | None = None) -> None:
        self.busy = True
        self.thread = thread
        self.until = until


class Activity:
    """The busy tokens of every script thread and pending callback of one session."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self._tokens: set[Token] = set()
        self._local = threading.local()
        self._loop: Any = None
        self._watchers: set[Waiter] = set()

    def attach(self, loop: Any) -> None:
        """The loop to wake when someone goes idle (so it may jump)."""
        self._loop = loop

    def busy(self) -> bool:
        """Whether any live thread or pending callback is busy."""
        now = time.monotonic()
        with self.lock:
            gone = [
                t for t in self._tokens
                if (t.thread is not None and not t.thread.is_alive()) or (t.until is not None and now >= t.until)
            ]
            self._tokens.difference_update(gone)
            return any(t.busy for t in self._tokens)

    def busy_besides(self, token: Token) -> bool:
        """Whether anyone but ``token``'s holder is busy."""
        with self.lock:
            return any(t.busy for t in self._tokens if t is not token)

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

    def starting(self, grace: float) -> Token:
        """A busy token for a thread a script thread is starting (adopted by it with :meth:`adopt`).

        A thread may start and then wait on the runtime at once (``rclpy.spin`` on
        a thread of its own): it must hold virtual time still until it waits.
        But it may also never wait on the runtime (a pool's idle worker), so its
        token lapses after ``grace`` real seconds unless it waits first.
        """
        token = Token(None, time.monotonic() + grace)
        with self.lock:
            self._tokens.add(token)
        lapse = threading.Timer(grace, self.poke)  # let the loop look again when it lapses
        lapse.daemon = True
        lapse._actors_token = False  # type: ignore[attr-defined]  # not a script thread: no token
        lapse.start()
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
            token.busy = False
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
            token.busy = busy
        if not busy:
            self.poke()

    def finish_on_collect(self, owner: object, token: Token) -> None:
        """End ``token`` if ``owner`` is garbage collected before its work ran."""
        weakref.finalize(owner, self.done, token)

    def watch(self, waiter: Waiter) -> None:
        """Wake ``waiter`` whenever a token goes idle (until :meth:`unwatch`)."""
        with self.lock:
            self._watchers.add(waiter)

    def unwatch(self, waiter: Waiter) -> None:
        """Stop waking ``waiter``."""
        with self.lock:
            self._watchers.discard(waiter)

    def poke(self) -> None:
        """Someone went idle: wake the watchers, and the loop, which may wait in real time while
        anyone is busy."""
        with self.lock:
            watchers = list(self._watchers)
        for waiter in watchers:
            waiter.wake()
        loop = self._loop
        if isinstance(loop, VirtualTimeLoop) and not loop.is_closed():
            try:
                loop.call_soon_threadsafe(_nothing)
            except RuntimeError:  # closed meanwhile
                pass


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
            if self._token.until is not None:  # a new thread that waits on the runtime: tracked for good
                self._token.until = None
                activity._tokens.add(self._token)
            if self._event.is_set():
                return
            self._token.busy = False
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
        return super().threads_busy() or self.activity.busy()
