"""The event loops a graph runs on: virtual time, a precise wall clock, uvloop.

:class:`VirtualTimeLoop` is an asyncio ``SelectorEventLoop`` whose clock starts
at 0 and jumps to the next timer whenever nothing is ready, so an hour of robot
time costs milliseconds.  It never jumps while work is pending in an executor
or in anyio's worker threads (that work runs in real time), and it turns a wait
on nothing (no timer, no I/O, no thread) into
:class:`~actors.errors.VirtualTimeDeadlock` after ``idle_timeout`` real
seconds, instead of hanging.  The epoch that turns loop time into ROS time is
kept by :class:`~actors.ros.time.ROSClock`, not here.
"""

from __future__ import annotations

import asyncio
import importlib.util
import selectors
import time
import weakref
from collections.abc import Callable
from contextvars import copy_context
from heapq import heapify, heappop, heappush
from typing import TYPE_CHECKING, Any, TypeVar, cast

from actors.errors import VirtualTimeDeadlock

__all__ = ["VirtualTimeLoop", "loop_clock", "precise_loop", "uvloop_loop", "WALL_LOOPS", "wall_loop"]

if TYPE_CHECKING:
    from collections import deque
    from concurrent.futures import Executor
    from contextvars import Context
    from typing import TypeVarTuple

    _T = TypeVar("_T")
    _Ts = TypeVarTuple("_Ts")

    # asyncio's private state that this module reads and writes, which typeshed leaves out
    # (the loop's own fields, a timer handle's, a selector's).  Seen by mypy only: at run time
    # the bases below are asyncio's and selectors' own classes.
    class _Timer(asyncio.TimerHandle):
        _when: float
        _scheduled: bool
        _callback: Callable[..., object]
        _context: Context

    class _Selector(selectors.DefaultSelector):
        _selector: Any  # the epoll (or poll) object of an EpollSelector
        _fd_to_key: dict[int, selectors.SelectorKey]

    class _SelectorLoop(asyncio.SelectorEventLoop):
        _debug: bool
        _closed: bool
        _stopping: bool
        _clock_resolution: float
        _ready: deque[asyncio.Handle]
        _scheduled: list[_Timer]
        _timer_cancelled_count: int
        _selector: _JumpingSelector
        _signal_handlers: dict[int, asyncio.Handle]

        def _run_once(self) -> None: ...
        def _process_events(self, event_list: list[tuple[selectors.SelectorKey, int]]) -> None: ...
else:
    _Selector = selectors.DefaultSelector
    _SelectorLoop = asyncio.SelectorEventLoop


def loop_clock(loop: asyncio.AbstractEventLoop) -> Callable[[], float]:
    """What tells ``loop.time()`` cheapest: ``time.monotonic`` itself on asyncio's own loops.

    Called directly it costs half of ``loop.time()``, a Python method around
    it.  Loops that keep their own time (virtual time, uvloop) give their ``time``.
    """
    return time.monotonic if type(loop).time is asyncio.BaseEventLoop.time else loop.time


def precise_loop() -> asyncio.AbstractEventLoop:
    """A wall-clock asyncio loop whose waits have microsecond precision.

    asyncio's default loop on Linux waits in ``epoll_wait``, which takes whole
    milliseconds and rounds every wait up, so a 1 kHz timer lands up to 1 ms
    late (p99 1.16 ms in BENCHMARKS.md).  ``select()`` takes microseconds (p99
    0.31 ms).  Its limits (file descriptors below 1024, a scan per wait) do not
    matter for a graph, which watches a handful: the control socket and its
    clients.  ``python -m actors.run`` uses this loop on the wall clock.
    """
    return asyncio.SelectorEventLoop(selectors.SelectSelector())


def uvloop_loop() -> asyncio.AbstractEventLoop:
    """A uvloop event loop (the ``fast`` extra: ``pip install 'actors[fast]'``), for the wall clock only.

    Faster per wake-up than asyncio's loops (BENCHMARKS.md shows both), but
    its clock counts whole milliseconds: ``loop.time()`` is libuv's time,
    read once per loop iteration, so a timer's deadlines start from a
    millisecond-rounded time and fire up to a millisecond late, and stamps
    taken within one iteration are equal.  Fine for 10-100 Hz control loops;
    use :func:`precise_loop` for kHz timers.  Virtual time stays on
    :class:`VirtualTimeLoop`.  Raises ImportError with the install hint when
    uvloop is missing.
    """
    try:
        import uvloop
    except ImportError as exc:
        found = importlib.util.find_spec("uvloop") is not None
        reason = f"uvloop does not load ({exc})" if found else "uvloop is not installed"
        raise ImportError(f"{reason}: pip install 'actors[fast]'") from None
    return uvloop.new_event_loop()


#: The wall-clock loops ``python -m actors.run --loop NAME`` offers, by name.
WALL_LOOPS: dict[str, Callable[[], asyncio.AbstractEventLoop]] = {
    "select": precise_loop,
    "asyncio": asyncio.new_event_loop,
    "uvloop": uvloop_loop,
}


def wall_loop(name: str | None, transport: bool) -> Callable[[], asyncio.AbstractEventLoop]:
    """The wall-clock loop a graph runs on: ``name`` (``--loop``) if given, else the default.

    The default is ``select`` (:func:`precise_loop`), except for a graph with a
    transport when uvloop is installed: every message across processes
    crosses from a transport thread to the loop, and uvloop's wake-up takes
    half of select's (the service round trip and the latency across
    processes are mostly such hops).  ``--loop select`` keeps microsecond
    timers on a graph with a transport.
    """
    if name is None:
        name = "uvloop" if transport and _uvloop_imports() else "select"
    return WALL_LOOPS[name]


def _uvloop_imports() -> bool:
    # Imported, not only found: a uvloop built for another Python or missing libuv is there but
    # does not load, and a graph that never asked for it runs on select.
    try:
        import uvloop  # noqa: F401
    except ImportError:
        return False
    return True


_new_handle = object.__new__
# The fields asyncio's Handle and TimerHandle have (3.11 to 3.13): call_at and call_soon fill them
# in directly; a Python whose handles differ gets asyncio's own constructors.
_LEAN_HANDLES = set(asyncio.Handle.__slots__) == {
    "_callback",
    "_args",
    "_cancelled",
    "_loop",
    "_source_traceback",
    "_repr",
    "__weakref__",
    "_context",
} and set(asyncio.TimerHandle.__slots__) == {"_scheduled", "_when"}


def _handle(
    cls: type, callback: Callable[..., object], args: tuple[Any, ...], loop: VirtualTimeLoop, context: Any
) -> Any:
    # Handle.__init__ outside debug mode, filled in by one call instead of two (TimerHandle's and Handle's).
    handle: Any = _new_handle(cls)
    handle._callback = callback
    handle._args = args
    handle._cancelled = False
    handle._loop = loop
    handle._source_traceback = None
    handle._repr = None
    handle._context = copy_context() if context is None else context
    return handle


_MAX_WAIT = 24 * 3600.0  # asyncio's longest wait in one select (MAXIMUM_SELECT_TIMEOUT)
_MIN_SCHEDULED = 100  # asyncio's: below this many timers, cancelled ones are only popped at the head


class _JumpingSelector(_Selector):
    """The selector of :class:`VirtualTimeLoop`: polls I/O, then jumps instead of sleeping."""

    def __init__(self, loop: VirtualTimeLoop) -> None:
        super().__init__()
        self._vloop = loop
        # epoll says whether anything is ready in one C call (it is level-triggered: what it
        # saw is still there for select()), where select() spends a microsecond in Python.
        self._peek = self._selector.poll if isinstance(self, selectors.EpollSelector) else None

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
        peek = self._peek
        if timeout == 0:
            return super().select(0) if peek is None or peek(0, 1) else []
        loop = self._vloop
        # Ask the threads before polling: a thread hands its work over (call_soon_threadsafe
        # writes the self-pipe) before it goes idle, so once none is busy, the poll below sees
        # all they handed over.  Polled first, a hand-off between the poll and the question
        # would be missed and time would jump past the work it brings.
        busy = loop.threads_busy()
        if peek is None or len(self._fd_to_key) > 1 or loop._signal_handlers:
            if peek is None or peek(0, 1):  # real I/O, or a signal's byte in the self-pipe
                events = super().select(0)
                if events:
                    return events
        elif loop._ready:
            # The self-pipe alone is watched, and no signal writes to it: only threads do, and
            # call_soon_threadsafe queues the callback before it writes.  So a thread's hand-over
            # shows in the ready queue (read it, no jump) and an empty queue means nothing to
            # read: no system call (with the GIL let go and taken back) on every jump.
            return super().select(0)
        if busy:
            # Real work is running in a thread: wait for it in real time (looking again after
            # busy_poll, when set, for threads that stop being busy without waking the loop).
            poll = loop.busy_poll
            if poll is not None and (timeout is None or timeout > poll):
                timeout = poll
            return super().select(timeout)
        if timeout is not None:
            # Land exactly on the earliest deadline, not on now + (when - now), which float
            # rounding can leave a hair short of it.
            scheduled = loop._scheduled  # the base loop's heap of TimerHandles
            if scheduled and scheduled[0]._when > loop._now:
                loop._now = scheduled[0]._when
            return []
        # No timer at all: only real I/O could still wake anything.
        events = super().select(loop.idle_timeout)
        if not events and not loop.threads_busy():
            raise VirtualTimeDeadlock(
                f"virtual time is idle: no timer is scheduled and nothing happened for "
                f"{loop.idle_timeout} s of real time, so every task waits forever "
                f"(an event nobody sets, a queue nobody feeds?)"
            )
        return events


class VirtualTimeLoop(_SelectorLoop):
    """An asyncio event loop whose clock jumps to the next timer when nothing is ready.

    Use it anywhere a loop factory is taken::

        anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop})
        asyncio.Runner(loop_factory=VirtualTimeLoop).run(main())

    ``time()`` starts at 0.0.  ``epoch`` is the wall-clock time (seconds since the
    Unix epoch) that virtual time 0 stands for in timestamps; it defaults to 0,
    like simulated time in ROS.  Raises :class:`~actors.errors.VirtualTimeDeadlock`
    out of ``run_*`` when no timer, I/O or thread could ever wake a task and
    ``idle_timeout`` real seconds pass with nothing happening.

    Its iterations, ``call_at`` and ``call_soon`` are asyncio's specialised to
    virtual time (tests/test_virtual_loop.py runs the same programs on asyncio's
    own code and compares): a simulation spends most of its loop iterations on
    one timer each, and asyncio's generic iteration cost as much as a physics
    step.  In debug mode the loop takes asyncio's own code (slow-callback warnings).
    """

    def __init__(self, *, epoch: float = 0.0, idle_timeout: float = 5.0) -> None:
        # Five attributes beside asyncio's 24: CPython 3.11 keeps at most 30 of an object's
        # attributes inline, and past that the method calls made on it (every timer's
        # loop.time()) go unspecialised, 1.2k instructions a physics step (tests/test_clock.py).
        self._now = 0.0
        self._threads = _Threads(self)
        self.busy_poll: float | None = None  # see _JumpingSelector.select
        self.epoch = epoch
        self.idle_timeout = idle_timeout
        super().__init__(selector=_JumpingSelector(self))

    def time(self) -> float:
        return self._now

    def call_at(
        self, when: float, callback: Callable[[*_Ts], object], *args: *_Ts, context: Context | None = None
    ) -> asyncio.TimerHandle:
        if self._debug or self._closed or when is None or not _LEAN_HANDLES:
            return super().call_at(when, callback, *args, context=context)
        # asyncio's call_at without its two constructors' debug questions and the closed
        # check's call: the same handle, with the same fields, in the same heap.
        timer = _handle(asyncio.TimerHandle, callback, args, self, context)
        timer._when = when
        heappush(self._scheduled, timer)
        timer._scheduled = True
        return timer

    def call_again(self, handle: asyncio.TimerHandle, when: float) -> asyncio.TimerHandle:
        """``handle``, a timer handle of this loop that has run, scheduled again for ``when``; returns the handle.

        For a callback that sets its loop timer again each time it runs (a
        runtime's timers, every instant of a simulation): the same object,
        callback, arguments and context back in the heap, as ``call_at`` would
        make them, without a new handle.  A new one from ``call_at`` for a
        handle still waiting, and in debug mode.  ValueError for a cancelled
        handle (cancelling forgets the callback).
        """
        # Every timer handle has _Timer's fields; typeshed declares only some of TimerHandle's.
        timer: _Timer = handle  # type: ignore[assignment]  # see the comment above
        if timer._cancelled:
            raise ValueError("a cancelled handle cannot be called again")
        if self._debug or self._closed or timer._scheduled:
            return self.call_at(when, timer._callback, *timer._args, context=timer._context)
        timer._when = when
        heappush(self._scheduled, timer)
        timer._scheduled = True
        return timer

    def call_soon(
        self, callback: Callable[[*_Ts], object], *args: *_Ts, context: Context | None = None
    ) -> asyncio.Handle:
        if self._debug or self._closed or not _LEAN_HANDLES:
            return super().call_soon(callback, *args, context=context)
        handle = _handle(asyncio.Handle, callback, args, self, context)
        self._ready.append(handle)
        return handle

    def _run_once(self) -> None:
        # One iteration of asyncio's loop (BaseEventLoop._run_once), specialised to virtual time:
        # the same steps in the same order (drop cancelled timers, poll I/O or jump, move the due
        # timers to the ready queue, run what was ready when the iteration began), without the
        # generic parts it pays for on every instant: time() calls, the timeout's arithmetic when
        # something is ready, the debug checks, an empty _process_events.  Debug mode (slow
        # callback warnings, the current handle) takes asyncio's own iteration.
        if self._debug:
            super()._run_once()
            return
        if self._timer_cancelled_count:
            self._drop_cancelled()
        scheduled = self._scheduled
        ready = self._ready
        events: list[tuple[selectors.SelectorKey, int]] | None
        if ready or self._stopping:
            events = self._selector.select(0)
        elif scheduled:
            # min() and max() parse their arguments as keywords: plain comparisons cost a tenth.
            timeout = scheduled[0]._when - self._now
            events = self._selector.select(0 if timeout < 0 else _MAX_WAIT if timeout > _MAX_WAIT else timeout)
        else:
            events = self._selector.select(None)
        if events:
            self._process_events(events)
        events = None  # no cycle through a handle's exception
        end = self._now + self._clock_resolution
        while scheduled and scheduled[0]._when < end:
            timer = heappop(scheduled)
            timer._scheduled = False
            ready.append(timer)
        # Only what is ready now: callbacks scheduled by these run in the next iteration, after a poll.
        popleft = ready.popleft
        todo = len(ready)  # counted down: a range object costs more than the one or two handles of an instant
        handle: asyncio.Handle | None
        while todo:
            todo -= 1
            handle = popleft()
            if not handle._cancelled:
                handle._run()
        handle = None

    def _drop_cancelled(self) -> None:
        # As asyncio does: rebuild the heap when cancelled timers are most of a large one,
        # otherwise pop those at its head.
        scheduled = self._scheduled
        if len(scheduled) > _MIN_SCHEDULED and self._timer_cancelled_count * 2 > len(scheduled):
            live = []
            for handle in scheduled:
                if handle._cancelled:
                    handle._scheduled = False
                else:
                    live.append(handle)
            heapify(live)
            self._scheduled = live
            self._timer_cancelled_count = 0
        else:
            while scheduled and scheduled[0]._cancelled:
                self._timer_cancelled_count -= 1
                heappop(scheduled)._scheduled = False

    def skip_to(self, when: float, again: bool = False) -> bool:
        """From a callback of this loop: move virtual time on to ``when`` now if the loop would do only that next.

        For a callback that would set its loop timer for ``when`` and return
        (a runtime's timers, instant after instant of a simulation): True, time
        moved, means the caller may do now what that timer would, without the
        loop's iteration around it.  That is when the next iteration would jump
        to ``when`` and run that timer alone: nothing is ready, no timer of the
        loop's is due before ``when`` or within its clock resolution, no file
        descriptor but the loop's self-pipe nor any signal is watched (their
        poll is the loop's to make), no thread is at work, and the loop is
        neither stopping nor in debug mode.  False otherwise, time unmoved.

        ``again``: the caller's previous call, from this same callback, returned
        True, and only synchronous code has run since.  Then anyio's worker
        threads are not looked for again: only a task starts one, and a task
        that could have run since would have been ready, which stops the jump.
        """
        if self._ready or self._stopping or self._debug or not when > self._now:
            return False
        scheduled = self._scheduled
        if scheduled and scheduled[0]._when < when + self._clock_resolution:
            return False
        # What a callback can start without a task: a watched descriptor, a signal handler, an executor job.
        if len(self._selector._fd_to_key) > 1 or self._signal_handlers or self._threads.jobs:
            return False
        if not again and (self._selector._peek is None or self.threads_busy()):
            return False
        self._now = when
        return True

    def advance(self, seconds: float) -> None:
        """Move virtual time forward by ``seconds`` at once (timers due run next)."""
        if seconds < 0:
            raise ValueError("virtual time cannot go backwards")
        self._now += seconds

    def run_in_executor(self, executor: Executor | None, func: Callable[[*_Ts], _T], *args: *_Ts) -> asyncio.Future[_T]:
        future = super().run_in_executor(executor, func, *args)
        self._threads.jobs += 1
        future.add_done_callback(self._executor_job_done)
        return future

    def _executor_job_done(self, _future: asyncio.Future[Any]) -> None:
        self._threads.jobs -= 1

    async def shutdown_default_executor(self, *timeout: float | None) -> None:
        # Joining the executor's threads is thread work: a jump meanwhile would reach the join's
        # timeout (asyncio.Runner gives one from Python 3.12) before the threads end.
        self._threads.jobs += 1
        try:
            await super().shutdown_default_executor(*timeout)
        finally:
            self._threads.jobs -= 1

    def threads_busy(self) -> bool:
        """Whether executor jobs or anyio worker-thread calls are still running."""
        threads = self._threads
        if threads.jobs > 0:
            return True
        limiter = threads.limiter
        if limiter is None:  # made by anyio at the loop's first to_thread call, then kept
            # Asked on every jump of virtual time: the lookup inline, no call of its own.
            found = threads.run_vars.get(threads.loop)
            if found is None or (limiter := found.get(threads.limiter_key)) is None:
                return False
            threads.limiter = limiter
        return limiter.borrowed_tokens > 0


class _Threads:
    """What a VirtualTimeLoop knows of its work in other threads, in one attribute of the loop (see its __init__)."""

    __slots__ = ("jobs", "limiter", "loop", "run_vars", "limiter_key")

    def __init__(self, loop: VirtualTimeLoop) -> None:
        self.jobs = 0  # run_in_executor calls still running
        self.limiter: Any = None  # anyio's default thread limiter of the loop, once it exists
        self.loop = weakref.ref(loop)  # how anyio's per-loop run vars know the loop
        self.run_vars, self.limiter_key = _anyio_run_vars()


def _anyio_run_vars() -> tuple[dict[Any, dict[Any, Any]], Any]:
    # anyio runs ``to_thread.run_sync`` in its own workers, outside run_in_executor,
    # holding a token of the loop's default limiter while the call runs.  anyio has
    # no public way to ask this from outside a task, so read its per-loop run vars:
    # the WeakKeyDictionary's own dict, by the loop's weak reference (its get() builds
    # one per call), and the limiter's key in them.  tests/test_clock.py fails if that
    # ever stops working.
    try:
        from anyio._backends._asyncio import _default_thread_limiter
        from anyio.lowlevel import _run_vars
    except ImportError:  # pragma: no cover - a future anyio
        return {}, None
    # .data: the WeakKeyDictionary's own dict, which typeshed does not declare.
    return cast(Any, _run_vars).data, _default_thread_limiter
