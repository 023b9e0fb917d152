"""Whose turn it is to touch the runtime: the loop thread's, or one script thread's.

The runtime's state (topics, timers, the loop's queues) and the overlay's
(executors, ready work) belong to whoever holds the *turn*.  A script thread
takes it to call into the runtime (create a publisher, publish) and runs that
call itself, on its own thread: no hop to the loop thread.  Blocking calls are
waits: the thread parks on its :class:`Waiter` and gives the turn away; whoever
wakes it (always someone holding the turn, or a thread that takes it first)
marks it woken.

Two kinds of turn, one per clock:

- :class:`WallTurn`, on the wall clock: a lock.  The loop holds it while it
  runs an iteration and lets it go while it waits in ``select``; a script thread
  holds it for one call at a time, so a script blocked in its own code (reading
  the keyboard) never stops the graph.
- :class:`VirtualTurn`, on the virtual clock: a baton handed from party to
  party in a fixed order.  A script thread holds it from the moment it is
  woken until it waits again, and the loop runs only while it holds it, so
  nothing moves while a script runs and a script never runs while anything else
  does.  Woken threads queue in the order they were woken; the loop hands the
  baton to each in turn before it looks at the clock again.  That order is a
  function of the program alone, which makes a run repeatable.

Threads a script thread starts on the virtual clock queue for the baton from
``start()`` (:meth:`VirtualTurn.enlist`), so they run exactly when the order
says, however late the OS schedules them.  A thread that holds the baton and
blocks outside the runtime (``input()``, a busy loop) holds everything still;
after :data:`HOLD_WARNING` seconds of real time one warning line names it and
where it last left the runtime, and the run goes on waiting for it.
"""

from __future__ import annotations

import _thread
import asyncio
import logging
import os
import select
import selectors
import signal
import sys
import threading
import time
from abc import ABC, abstractmethod
from asyncio.events import _get_running_loop, _set_running_loop
from collections import deque
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
from types import FrameType
from typing import Any

from actors.core.loops import VirtualTimeLoop
from actors.errors import VirtualTimeDeadlock
from actors.ros.log import ROOT_LOGGER

__all__ = ["Turn", "WallTurn", "VirtualTurn", "Waiter", "ScriptWallLoop", "ScriptTimeLoop", "HOLD_WARNING"]

#: Real seconds the baton may stay with one thread outside the runtime before a warning names it.
HOLD_WARNING = 5.0


_ACTORS = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep  # the actors package
_STDLIB = os.path.dirname(os.__file__) + os.sep
_get_ident = threading.get_ident


class Waiter:
    """One party that parks until it is woken: a thread in an rclpy wait, or a job for a pool thread.

    The owner calls :meth:`clear`, checks its condition, then parks through
    :meth:`Turn.wait`; whoever changes the condition calls :meth:`wake`.  A
    wake-up between the check and the wait is never lost.
    """

    __slots__ = ("_turn", "_sem", "parked", "woken", "queued", "__weakref__")

    def __init__(self, turn: Turn) -> None:
        self._turn = turn
        self._sem = threading.Lock()
        self._sem.acquire()  # released once per hand-over: acquiring it blocks until then
        self.parked = False
        self.woken = False
        self.queued = False

    def clear(self) -> None:
        """Forget earlier wake-ups (before checking the condition again)."""
        self.woken = False

    def wake(self) -> None:
        """Wake the parked owner (from any thread); it runs when its turn comes."""
        self._turn.wake(self)


class Turn(ABC):
    """What both turns share: reentrant sections, waits, signals, and the end of the runtime."""

    virtual = False

    def __init__(self) -> None:
        self._lock = threading.Lock()  # guards the waiters' flags and the queue, briefly
        self.holder: int | None = None  # the ident of the thread with the turn
        self._depth = 0  # sections of the holder's open (a thread woken by a wait holds one)
        self.stopped = False
        self.closing = False  # the runtime is ending: waits return at once
        self._parked: set[Waiter] = set()
        self._after_stop = threading.RLock()  # mutual exclusion once the runtime has ended
        self.loop: asyncio.AbstractEventLoop | None = None
        # Signals land in the main thread between two bytecodes: never inside the turn's own
        # bookkeeping.  While the main thread runs the runtime's code, a signal's exception waits
        # (signal()) and is raised where that code is consistent: when the main thread's wait
        # ends, or when it leaves the runtime's code.
        self._main = threading.main_thread().ident
        self.main_inside = 0  # sections the main thread has open
        self._main_waiter: Waiter | None = None  # the main thread's wait, while it is parked
        self._main_selects = False  # the main thread blocks on its pipe (see _acquire)
        self._wakeup: int | None = None  # the signals' wake-up fd before the main thread's first wait
        self._signal: BaseException | None = None
        # Where each thread last parked, or took the turn: its script's frames, innermost first,
        # read by the thread itself (the hold warning and grading name them).
        self._where: dict[int, list[tuple[str, int, str]]] = {}

    # -- sections ---------------------------------------------------------------

    def mine(self) -> bool:
        """Whether the calling thread holds the turn."""
        return self.holder == _get_ident()

    def __enter__(self) -> None:
        me = _get_ident()
        if me == self._main:
            self.main_inside += 1  # first: a signal before this line is raised outside
        if self.holder == me:
            self._depth += 1
        elif self.stopped:
            self._after_stop.acquire()
        else:
            self._take()

    def __exit__(self, *exc: object) -> None:
        me = _get_ident()
        if self.holder == me:
            self._depth -= 1
            if not self._depth:
                self._give()
        elif self.stopped and self._after_stop._is_owned():  # type: ignore[attr-defined]  # RLock's own query
            self._after_stop.release()
        if me == self._main:
            self.main_inside -= 1  # last: a signal after this line is raised outside
            if not self.main_inside and self._signal is not None:
                self._raise_signal()

    @abstractmethod
    def _take(self) -> None:
        """Take the turn for a section (a thread that does not hold it)."""

    @abstractmethod
    def _give(self) -> None:
        """Hand the turn on at the end of the outermost section."""

    # -- signals ------------------------------------------------------------------

    def signal(self, error: BaseException, outside: BaseException | None = None) -> None:
        """From a signal handler (on the main thread): raise ``error`` as soon as the runtime's code
        the main thread runs is done with (a wait it is parked in ends at once), or ``outside``
        (default: ``error``) at once if it runs its own code."""
        if not self.main_inside:
            raise outside or error
        self._signal = error
        # On a thread of its own: this handler may run inside the main thread's own _park, with
        # _lock held and the waiter not yet recorded; the helper looks once _lock is free.
        _thread.start_new_thread(self._end_main_wait, ())

    def interrupt_main(self, error: BaseException) -> bool:
        """From the holder of the turn: end the main thread's wait with ``error``, in order, as any
        wake-up; False if the main thread does not wait on the runtime now."""
        if self._main_waiter is None:
            return False
        self._signal = error
        self._end_main_wait()
        return True

    def _end_main_wait(self) -> None:
        with self._lock:
            waiter = self._main_waiter
        if waiter is not None:
            self.wake(waiter)

    def _raise_signal(self) -> None:
        error, self._signal = self._signal, None
        if error is not None:
            raise error

    def _after_wait(self) -> None:
        # In the main thread, back from a wait with the turn: a signal that came meanwhile.
        if self._signal is not None and _get_ident() == self._main:
            self._raise_signal()

    # -- waits --------------------------------------------------------------------

    @abstractmethod
    def wake(self, waiter: Waiter) -> None:
        """Wake ``waiter``'s owner, or mark it woken if it is not parked yet."""

    @abstractmethod
    def wait(self, waiter: Waiter) -> None:
        """Park the calling thread, which holds the turn, until ``waiter`` is woken; the turn is
        someone else's meanwhile.  At once if it was woken since :meth:`Waiter.clear`, or the
        runtime has ended.  A signal's exception (:meth:`signal`) comes out of it."""

    def _park(self, waiter: Waiter) -> bool:
        # With _lock held: park ``waiter``, or say it need not (woken already, or the end came).
        if waiter.woken or self.closing or self.stopped or (self._signal is not None and _get_ident() == self._main):
            waiter.woken = False
            return False
        waiter.parked = True
        self._parked.add(waiter)
        me = _get_ident()
        if me == self._main:
            self._main_waiter = waiter
        self._where[me] = _script_frames(sys._getframe(2))
        return True

    def where(self, ident: int) -> list[tuple[str, int, str]]:
        """The script's frames (file, line, function; innermost first) where thread ``ident`` last
        parked in a wait or took the turn, as it recorded them; empty if none."""
        return self._where.get(ident, [])

    def _acquire(self, sem: _thread.LockType, timeout: float | None = None) -> bool:
        # The kernel may deliver a process's signal to any thread, and Python runs the handler only
        # when the main thread runs bytecode, which a blocking acquire would never let it do: the
        # main thread waits on a pipe that both its hand-over (_release) and the signal write to,
        # the signals' wake-up fd from its first wait until the runtime ends (stop).
        if _get_ident() != self._main:
            return sem.acquire(timeout=-1 if timeout is None else timeout)
        if sem.acquire(False):
            return True
        read, write = _main_pipe()
        if self._wakeup is None:
            self._wakeup = signal.set_wakeup_fd(write)
        deadline = None if timeout is None else time.monotonic() + timeout
        self._main_selects = True  # before the next try: a hand-over after it writes to the pipe
        try:
            while not sem.acquire(False):
                if deadline is not None and not select.select([read], [], [], max(0.0, deadline - time.monotonic()))[0]:
                    return sem.acquire(False)  # the time is up
                os.read(read, 512)  # blocks until a byte comes (select saw one, if timed)
            return True
        finally:
            self._main_selects = False

    def _release(self, waiter: Waiter) -> None:
        # With _lock held: hand over to ``waiter``'s owner (see _acquire).
        waiter._sem.release()
        if waiter is self._main_waiter and self._main_selects:
            with suppress(BlockingIOError):  # full: the main thread has bytes to read
                os.write(_main_pipe()[1], b"\0")

    def _unparked(self, waiter: Waiter) -> None:
        if self._main_waiter is waiter:
            self._main_waiter = None

    def parks(self) -> bool:
        """Whether some thread is parked (with the turn held, no thread can start to)."""
        return bool(self._parked)

    @property
    def over(self) -> bool:
        """Whether waits no longer wait: the runtime is ending or has ended."""
        return self.closing or self.stopped

    def close(self) -> None:
        """The runtime is about to end: every parked thread wakes, and no wait parks any more."""
        with self._lock:
            self.closing = True
            parked = list(self._parked)
        for waiter in parked:
            self.wake(waiter)

    def stop(self) -> None:
        """The runtime has ended: release every parked thread; sections are a plain lock from now on."""
        with self._lock:
            self.stopped = True
            parked, self._parked = list(self._parked), set()
            for waiter in parked:
                waiter.parked = False
                self._release(waiter)
        if self._wakeup is not None and _get_ident() == self._main:  # else at close(), on the main thread
            signal.set_wakeup_fd(self._wakeup)
            self._wakeup = None


class WallTurn(Turn):
    """The wall clock's turn: a lock, held by the loop between two selects and by a script for a call."""

    def __init__(self) -> None:
        super().__init__()
        self._mutex = threading.Lock()
        self._selecting = False  # the loop waits in select (and has let the turn go)
        self._poked = False
        self._until = 0.0  # the deadline of the timer that ends the loop's select

    def _take(self) -> None:
        self._mutex.acquire()
        self.holder = _get_ident()
        self._depth = 1

    def _give(self) -> None:
        poke = self._must_poke()
        self.holder = None
        self._mutex.release()
        if poke:
            self._poke()

    def _must_poke(self) -> bool:
        # With the turn held: did this section give the waiting loop something to do sooner?
        loop: Any = self.loop
        if not self._selecting or self._poked or loop is None:
            return False
        scheduled = loop._scheduled
        if loop._ready or (scheduled and scheduled[0]._when < self._until):
            self._poked = True
            return True
        return False

    def _poke(self) -> None:
        loop: Any = self.loop
        try:
            loop._write_to_self()
        except (AttributeError, OSError, ValueError):  # closing
            pass

    def wake(self, waiter: Waiter) -> None:
        with self._lock:
            if waiter.parked:
                waiter.parked = False
                self._parked.discard(waiter)
                self._release(waiter)
            else:
                waiter.woken = True

    def wait(self, waiter: Waiter) -> None:
        with self._lock:
            parked = self._park(waiter)
        if not parked:
            self._after_wait()
            return
        mine = self.holder == _get_ident()
        depth = self._depth
        if mine:
            self._give()
        self._acquire(waiter._sem)
        self._unparked(waiter)
        if mine and not self.stopped:
            self._mutex.acquire()
            self.holder = _get_ident()
            self._depth = depth
        self._after_wait()

    # -- the loop's side -----------------------------------------------------------

    def loop_select(self, select: Callable[[float | None], Any], timeout: float | None) -> Any:
        """The loop's select: with the turn let go while it waits."""
        loop: Any = self.loop
        if self.holder != _get_ident() or self.stopped:
            events = select(timeout)
            if not self.stopped:
                self._take()
            return events
        self._selecting, self._poked = True, False
        # Its select ends with the earliest timer (asyncio's timeout is derived from it), if any.
        scheduled = loop._scheduled
        self._until = scheduled[0]._when if scheduled and timeout is not None else float("inf")
        self.holder = None
        self._mutex.release()
        try:
            return select(timeout)
        finally:
            self._mutex.acquire()
            self._selecting = False
            self.holder = _get_ident()
            self._depth = 1

    def stop(self) -> None:
        super().stop()
        if self.holder == _get_ident():  # the loop's thread, as the runtime ends: its lock goes
            self.holder = None
            self._mutex.release()


class VirtualTurn(Turn):
    """The virtual clock's turn: a baton, handed on in the order its takers were woken."""

    virtual = True

    def __init__(self) -> None:
        super().__init__()
        self.queue: deque[Waiter] = deque()
        self.settling: list[Waiter] = []
        self._loop_waiter = Waiter(self)
        # Who gets the baton when no thread queues for it: the loop's thread, or the main thread
        # while it runs the loop itself (see _drive).
        self._party = self._loop_waiter
        self._drives = 0  # how often the main thread has run the loop: the hold warning's clue
        self._loop_ident: int | None = None
        self.expected = 0  # threads told to come and take the baton that have not queued yet

    def _take(self, expected: bool = False) -> None:
        # A thread that does not hold the baton (a signal's helper, a pool's worker, a thread that
        # was expected): it queues, and blocks until the baton comes to it.
        waiter = Waiter(self)
        self._where[_get_ident()] = _script_frames(sys._getframe(2))
        with self._lock:
            self.expected -= expected
            self._enqueue(waiter)
        self._poke()
        waiter._sem.acquire()
        self._received(1)

    def _give(self) -> None:
        with self._lock:
            self._pass_on()

    def _enqueue(self, waiter: Waiter) -> None:
        waiter.queued = True
        self.queue.append(waiter)

    def _pass_on(self) -> None:
        # With _lock held, by the holder: the next queued party gets the baton, or the loop.
        self.holder = None
        if self.queue:
            nxt = self.queue.popleft()
            nxt.queued = False
        else:
            nxt = self._party
        self._release(nxt)

    def _received(self, depth: int) -> None:
        self.holder = _get_ident()
        self._depth = depth

    def _poke(self) -> None:
        loop = self.loop
        if loop is not None and not loop.is_closed():
            try:
                loop.call_soon_threadsafe(_nothing)
            except RuntimeError:  # closed meanwhile
                pass

    def wake(self, waiter: Waiter) -> None:
        with self._lock:
            if not waiter.parked:
                waiter.woken = True
                return
            waiter.parked = False
            self._parked.discard(waiter)
            self._enqueue(waiter)
            foreign = self.holder != _get_ident()
        if foreign:
            self._poke()

    def wait(self, waiter: Waiter) -> None:
        if self._party is not self._loop_waiter and _get_ident() == self._main:
            raise RuntimeError("the runtime's own thread cannot wait on the runtime")
        with self._lock:
            parked = self._park(waiter)
            if parked:
                depth = self._depth
                drive = self._may_drive()
                if not drive:
                    self._pass_on()
        if not parked:
            self._after_wait()
            return
        if not drive or not self._drive(waiter):
            self._acquire(waiter._sem)
        self._unparked(waiter)
        if not self.stopped:
            self._received(depth)
        self._after_wait()

    def _may_drive(self) -> bool:
        # With _lock held, by the holder about to wait: whether it runs the loop itself.  Only the
        # main thread does (one driver at a time, and the one a signal reaches), with nobody queued
        # and the loop parked in its select with something to do; else the loop's thread runs it.
        loop: Any = self.loop
        return (
            _get_ident() == self._main
            and self._loop_ident is not None
            and not self.queue
            and loop is not None
            and not loop._stopping
            and bool(loop._ready or loop._scheduled)
        )

    def _drive(self, waiter: Waiter) -> bool:
        """Run the loop on this thread until the baton comes back to ``waiter``; False if the
        loop's own thread must run it from here (the caller then parks as any other)."""
        # A hand-over between two threads costs the scheduler two wake-ups; the loop's iterations
        # cost the same on either thread.  The order of everything stays the baton's: the queue
        # goes round between two iterations, as the loop's select would send it round, and the
        # loop stops there for ``waiter``, before the iteration the loop's thread would run after.
        loop: Any = self.loop
        self._drives += 1
        self._party = waiter  # the baton comes back here: as the loop's share, or as waiter's own
        outer = _get_running_loop()
        _set_running_loop(loop)
        try:
            while waiter.parked or waiter.queued:
                if self.queue:
                    with self._lock:
                        self._pass_on()
                    self._park_loop()
                elif self.closing or self.stopped or loop._stopping or not (loop._ready or loop._scheduled):
                    break
                else:
                    loop._run_once()
            else:
                return True
        except VirtualTimeDeadlock:  # the loop's own thread meets it too, and ends the run with it
            pass
        finally:
            _set_running_loop(outer)
            self._party = self._loop_waiter
        if not self.stopped:
            with self._lock:
                self._pass_on()
        return False

    def enlist(self, waiter: Waiter) -> Waiter:
        """Queue ``waiter`` for a party that will run later (a thread about to start, a job for a
        pool thread): it takes the baton with :meth:`arrive` when its turn comes."""
        with self._lock:
            self._enqueue(waiter)
        if self.holder != _get_ident():
            self._poke()
        return waiter

    def expect(self) -> None:
        """A thread will :meth:`come` soon: until it has queued, the clock does not move."""
        with self._lock:
            self.expected += 1

    def come(self) -> None:
        """The thread that was expected queues for the baton and takes it when its turn comes."""
        self._take(expected=True)

    def unexpect(self) -> None:
        """The thread that was expected will not come."""
        with self._lock:
            self.expected -= 1
        self._poke()

    @contextmanager
    def arriving(self) -> Iterator[None]:
        """Run the block with the baton, for a party that was expected: the holder at once; another
        thread queues for it and hands it on after."""
        if self.holder == _get_ident():
            with self._lock:
                self.expected -= 1
            yield
            return
        self._take(expected=True)
        try:
            yield
        finally:
            self._give()

    def arrive(self, waiter: Waiter) -> None:
        """Block until the baton comes to ``waiter`` (from :meth:`enlist`); the caller holds it then."""
        waiter._sem.acquire()
        if not self.stopped:
            self._received(1)

    def depart(self) -> None:
        """The holder is done with the runtime for good (its thread ends): the baton goes on."""
        if self.holder != _get_ident():
            return
        self._where.pop(_get_ident(), None)
        with self._lock:
            self._pass_on()

    @contextmanager
    def stepped_out(self) -> Iterator[None]:
        """The holder blocks outside the runtime inside the block (joining a thread that is no
        script thread): the baton goes on meanwhile, and is taken back in the queue after."""
        if self.holder != _get_ident() or self.stopped:
            yield
            return
        depth = self._depth
        with self._lock:
            self._pass_on()
        try:
            yield
        finally:
            self._take()
            self._depth = depth

    def settle(self, waiter: Waiter) -> None:
        """Park the holder until the runtime has nothing left to do at this instant (every woken
        thread has run and waits again, the loop's ready work is done)."""
        with self._lock:
            self.settling.append(waiter)
        self.wait(waiter)

    # -- the loop's side -----------------------------------------------------------------

    def loop_select(self, select: Callable[[float | None], Any], timeout: float | None) -> Any:
        """The loop's select: first the baton goes round the queue (the loop waits); when the loop
        is about to move the clock on, the threads that settle get their turn first."""
        if self.stopped:
            return select(timeout)
        if self._loop_ident is None:
            self._loop_ident = self.holder = _get_ident()
            self._depth = 1
        loop: Any = self.loop
        if timeout != 0 and self.settling and not loop._ready:
            with self._lock:
                for waiter in self.settling:
                    if waiter.parked:
                        waiter.parked = False
                        self._parked.discard(waiter)
                        self._enqueue(waiter)
                self.settling.clear()
        if self.queue:
            with self._lock:
                self._pass_on()
            self._park_loop()
            timeout = 0  # the threads may have left work: look at it before the clock moves
        return select(timeout)

    def _park_loop(self) -> None:
        sem = self._party._sem
        drives = self._drives
        while not self._acquire(sem, HOLD_WARNING):
            # The main thread running the loop (now, or since the last look) waits as often as it
            # runs: only a holder that did neither for the whole time is named.
            if sem is self._party._sem and drives == self._drives:
                self._warn_holding()
                self._acquire(sem)
                break
            drives = self._drives
        self.holder = _get_ident()
        self._depth = 1

    def _warn_holding(self) -> None:
        holder = self.holder
        if holder is None:
            return
        thread = next((t for t in threading.enumerate() if t.ident == holder), None)
        where = self._where.get(holder)
        if where:
            file, line, function = where[0]
            place = f" (it last left the runtime in {function} at {file}:{line})"
        elif (code := getattr(getattr(thread, "_target", None), "__code__", None)) is not None:
            place = f" (started in {code.co_name} at {code.co_filename}:{code.co_firstlineno})"
        else:
            place = ""
        logging.getLogger(ROOT_LOGGER).warning(
            "virtual time waits for thread %r%s, which has not waited on rclpy for %g s of real time: "
            "a busy loop or a blocking call holds the clock still",
            thread.name if thread is not None else holder,
            place,
            HOLD_WARNING,
        )

    def has_queue(self) -> bool:
        """Whether a party waits for the baton or is about to (the loop must not jump past it)."""
        return bool(self.queue) or self.expected > 0


_internal: dict[str, bool] = {}  # by file name: a str keeps its hash, a code object computes it


def _script_frames(frame: FrameType | None) -> list[tuple[str, int, str]]:
    # The frames of the script's own (not the runtime's nor the standard library's) on the stack
    # that ``frame`` tops, innermost first: where the thread is as it parks (its own frames, read
    # by itself).
    found = []
    while frame is not None:
        code = frame.f_code
        file = code.co_filename
        inside = _internal.get(file)
        if inside is None:
            inside = _internal[file] = file.startswith((_ACTORS, _STDLIB, "<frozen "))
        if not inside:
            found.append((file, frame.f_lineno, code.co_name))
        frame = frame.f_back
    return found


_pipe: list[int] = []  # the main thread's wake-up pipe (read end, write end), made at its first wait


def _main_pipe() -> list[int]:
    if not _pipe:
        read, write = os.pipe()
        os.set_blocking(write, False)  # as signal.set_wakeup_fd requires: a handler never blocks
        _pipe[:] = read, write
    return _pipe


# A forked child that waits makes its own: a shared pipe would let one process read the other's
# wake-ups.  The signals' wake-up fd a child inherits stays the parent's write end, so a signal to
# the child wakes a waiting parent once, for nothing: it looks at its semaphore and reads again.
os.register_at_fork(after_in_child=_pipe.clear)


def _nothing() -> None:
    return None


class ScriptWallLoop(asyncio.SelectorEventLoop):
    """The wall-clock loop of a session: it lets the turn go while it waits in select."""

    def __init__(self, turn: WallTurn) -> None:
        selector = selectors.SelectSelector()  # as precise_loop: microsecond timeouts
        super().__init__(selector)
        turn.loop = self
        select = selector.select
        selector.select = lambda timeout=None: turn.loop_select(select, timeout)  # type: ignore[method-assign]  # wrapped


class ScriptTimeLoop(VirtualTimeLoop):
    """The virtual-time loop of a session: script threads take their turns before the clock moves."""

    def __init__(self, turn: VirtualTurn, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.turn = turn
        turn.loop = self
        select = self._selector.select
        self._selector.select = lambda timeout=None: turn.loop_select(select, timeout)  # type: ignore[method-assign]  # wrapped

    def threads_busy(self) -> bool:
        return super().threads_busy() or self.turn.has_queue()
