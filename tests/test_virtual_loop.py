"""The virtual-time loop's own iteration and handles keep asyncio's semantics, step for step.

VirtualTimeLoop runs its iterations, ``call_at`` and ``call_soon`` without
asyncio's generic code; each test here runs the same program on it and on the
same loop driven by asyncio's own methods (the reference), and compares what
happened, in which order and at which virtual time.
"""

from __future__ import annotations

import asyncio
import contextvars
import logging
import signal
import socket
import threading

import pytest

from actors.core.loops import VirtualTimeLoop


class AsyncioIteration(VirtualTimeLoop):
    """The reference: the same virtual clock, iterated and scheduled by asyncio's own code."""

    _run_once = asyncio.SelectorEventLoop._run_once
    call_at = asyncio.SelectorEventLoop.call_at
    call_soon = asyncio.SelectorEventLoop.call_soon

    def call_again(self, handle: asyncio.TimerHandle, when: float) -> asyncio.TimerHandle:
        # What call_again stands for: a new call_at with the handle's callback, arguments and context.
        return self.call_at(when, handle._callback, *handle._args, context=handle._context)


def test_the_reference_really_is_asyncios_code():
    # Otherwise every comparison below would compare the loop with itself.
    assert VirtualTimeLoop._run_once is not asyncio.SelectorEventLoop._run_once
    assert VirtualTimeLoop.call_at is not asyncio.SelectorEventLoop.call_at
    assert VirtualTimeLoop.call_soon is not asyncio.SelectorEventLoop.call_soon


def run_both(program) -> list:
    """``program(loop, trace)`` on the lean loop and on the reference; both traces, which must be equal."""
    traces = []
    for factory in (VirtualTimeLoop, AsyncioIteration):
        trace: list = []
        loop = factory()
        try:
            loop.run_until_complete(program(loop, trace))
        finally:
            loop.close()
        traces.append(trace)
    assert traces[0] == traces[1]
    return traces[0]


def test_call_soon_runs_in_order_and_what_it_schedules_waits_for_the_next_iteration():
    async def program(loop, trace):
        def first():
            trace.append("first")
            loop.call_soon(trace.append, "scheduled by first")

        def then():
            # A timer due now, made in this iteration, runs in the next one, before what the
            # next iteration's callbacks schedule (each iteration runs only what was ready).
            loop.call_at(loop.time(), trace.append, "timer due now")
            loop.call_soon(lambda: (trace.append("next"), loop.call_soon(trace.append, "the one after")))

        loop.call_soon(first)
        loop.call_soon(trace.append, "second")
        await asyncio.sleep(0)
        trace.append("after one iteration")
        await asyncio.sleep(0)
        await asyncio.sleep(0)
        loop.call_soon(then)
        for _ in range(4):
            await asyncio.sleep(0)

    assert run_both(program) == [
        "first",
        "second",
        "after one iteration",
        "scheduled by first",
        "next",
        "timer due now",
        "the one after",
    ]


def test_timers_run_in_deadline_order_then_scheduling_order_at_their_exact_times():
    async def program(loop, trace):
        def note(label):
            trace.append((label, loop.time()))

        loop.call_at(0.3, note, "c")
        loop.call_at(0.1, note, "a")
        loop.call_later(0.1, note, "a again, same deadline")
        loop.call_at(0.2, note, "b")
        loop.call_soon(note, "soon")
        await asyncio.sleep(1)
        note("slept")

    assert run_both(program) == [
        ("soon", 0.0),
        ("a", 0.1),
        ("a again, same deadline", 0.1),
        ("b", 0.2),
        ("c", 0.3),
        ("slept", 1.0),
    ]


def test_cancelled_handles_never_run_and_the_heap_is_swept():
    async def program(loop, trace):
        loop.set_exception_handler(lambda _loop, context: trace.append(context["message"]))
        loop.call_soon(trace.append, "soon, cancelled").cancel()
        head = loop.call_at(0.1, trace.append, "earliest timer, cancelled")
        loop.call_at(0.2, trace.append, "kept")
        head.cancel()
        # Many cancelled timers: asyncio rebuilds the heap without them once they are most of it.
        for handle in [loop.call_at(5.0, trace.append, "never") for _ in range(300)]:
            handle.cancel()
        later = loop.call_at(0.3, trace.append, "cancelled by the timer before it, in the same iteration")
        loop.call_at(0.3, later.cancel)
        loop.call_at(0.3, lambda: later.cancel())  # again: still counted once
        loop.call_at(0.4, lambda: trace.append(("counted", loop._timer_cancelled_count)))
        trace.append(("before", len(loop._scheduled), loop._timer_cancelled_count))
        await asyncio.sleep(0.5)
        trace.append(("after", len(loop._scheduled), loop._timer_cancelled_count))

    trace = run_both(program)
    assert trace[0] == ("before", 306, 301)
    assert trace[1] == "kept"
    assert trace[2] == ("counted", 0)  # a due timer cancelled before its turn is not in the heap
    assert trace[3][0] == "after" and trace[3][1] < 10  # swept, not kept until 5.0
    assert "never" not in trace and "soon, cancelled" not in trace


def test_an_exception_in_a_callback_reaches_the_loops_handler_and_the_loop_goes_on():
    async def program(loop, trace):
        loop.set_exception_handler(
            lambda _loop, context: trace.append(
                (context["message"].split(" ")[0], type(context["exception"]).__name__, loop.time())
            )
        )

        def boom():
            raise ValueError("boom")

        loop.call_soon(boom)
        loop.call_at(0.25, boom)
        loop.call_at(0.25, trace.append, "after the failing timer")
        await asyncio.sleep(1)
        trace.append("done")

    assert run_both(program) == [
        ("Exception", "ValueError", 0.0),
        ("Exception", "ValueError", 0.25),
        "after the failing timer",
        "done",
    ]


def test_handles_carry_their_context_and_are_asyncios_handles():
    var = contextvars.ContextVar("var", default="unset")

    async def program(loop, trace):
        context = contextvars.copy_context()
        context.run(var.set, "given")
        var.set("caller's")
        loop.call_soon(lambda: trace.append(("soon", var.get())), context=context)
        loop.call_soon(lambda: trace.append(("soon, own copy", var.get())))
        timer = loop.call_at(0.5, lambda: trace.append(("timer", var.get())), context=context)
        trace.append((type(timer).__name__, timer.when(), timer.cancelled(), repr(timer).startswith("<TimerHandle")))
        var.set("changed after")
        await asyncio.sleep(1)

    assert run_both(program) == [
        ("TimerHandle", 0.5, False, True),
        ("soon", "given"),
        ("soon, own copy", "caller's"),
        ("timer", "given"),
    ]


def test_call_again_puts_a_handle_that_ran_back_in_line_as_call_at_would():
    var = contextvars.ContextVar("var", default="unset")

    async def program(loop, trace):
        handles = []

        def tick(label):
            handle = handles[-1]
            trace.append((label, loop.time(), var.get()))
            if loop.time() < 0.3:
                # Due at the same instant as a timer made before it: after that one, as call_at's would be.
                handles.append(loop.call_again(handle, loop.time() + 0.1))

        context = contextvars.copy_context()
        context.run(var.set, "the handle's own")
        handles.append(loop.call_at(0.1, tick, "tick", context=context))
        for when in (0.2, 0.3):
            loop.call_at(when, lambda when=when: trace.append(("other", loop.time(), var.get())))
        await asyncio.sleep(1)
        trace.append(len({id(h) for h in handles}))

    lean, reference = [], []
    for factory, into in ((VirtualTimeLoop, lean), (AsyncioIteration, reference)):
        loop = factory()
        try:
            loop.run_until_complete(program(loop, into))
        finally:
            loop.close()
    # The same ticks at the same times in the same context and order; the lean loop used one handle for all.
    assert (
        lean[:-1]
        == reference[:-1]
        == [
            ("tick", 0.1, "the handle's own"),
            ("other", 0.2, "unset"),
            ("tick", 0.2, "the handle's own"),
            ("other", 0.3, "unset"),
            ("tick", 0.3, "the handle's own"),
        ]
    )
    assert (lean[-1], reference[-1]) == (1, 3)


def test_call_again_makes_a_new_handle_for_one_still_waiting_and_in_debug_mode_and_refuses_a_cancelled_one():
    loop = VirtualTimeLoop()
    try:
        waiting = loop.call_at(1.0, print)
        again = loop.call_again(waiting, 2.0)
        assert again is not waiting and (waiting.when(), again.when()) == (1.0, 2.0)
        waiting.cancel()
        with pytest.raises(ValueError, match="cancelled"):
            loop.call_again(waiting, 3.0)
        loop.set_debug(True)
        ran = loop.call_at(0.0, print)
        loop.run_until_complete(asyncio.sleep(0.5))
        assert loop.call_again(ran, 4.0) is not ran
    finally:
        loop.close()


def test_tasks_futures_and_stop():
    async def program(loop, trace):
        async def worker(name, delay):
            for _ in range(2):
                await asyncio.sleep(delay)
                trace.append((name, loop.time()))
            return name

        done = await asyncio.gather(worker("x", 0.3), worker("y", 0.2))
        trace.append(done)
        with pytest.raises(asyncio.TimeoutError):
            await asyncio.wait_for(asyncio.sleep(10), 0.5)
        trace.append(("timed out", loop.time()))

    assert run_both(program) == [("y", 0.2), ("x", 0.3), ("y", 0.4), ("x", 0.6), ["x", "y"], ("timed out", 1.1)]
    loop = VirtualTimeLoop()
    try:
        loop.call_at(2.0, loop.stop)
        loop.call_at(3.0, loop.stop)
        loop.run_forever()
        assert loop.time() == 2.0  # stopped at the first stop, the later timer still waits
        assert len(loop._scheduled) == 1
    finally:
        loop.close()


def test_a_threads_call_soon_threadsafe_wakes_the_loop_waiting_in_real_time_before_any_jump():
    async def program(loop, trace):
        far = loop.call_at(100.0, trace.append, "far timer")
        handed = threading.Event()
        release = threading.Event()

        def work():
            loop.call_soon_threadsafe(lambda: (trace.append(("handed over", loop.time())), release.set()))
            handed.set()
            release.wait(10)  # busy until the loop has run what it handed over: no jump meanwhile
            return "worked"

        trace.append(await loop.run_in_executor(None, work))
        trace.append(("after", loop.time()))
        far.cancel()

    assert run_both(program) == [("handed over", 0.0), "worked", ("after", 0.0)]


def test_skip_to_moves_time_only_when_the_next_iteration_would_do_nothing_but_jump_there():
    loop = VirtualTimeLoop()
    try:
        assert loop.skip_to(1.0) and loop.time() == 1.0
        assert not loop.skip_to(1.0) and not loop.skip_to(0.5)  # not ahead: the loop's to run
        other = loop.call_at(2.0, print)
        assert not loop.skip_to(2.0) and not loop.skip_to(2.0 - loop._clock_resolution / 2)  # run with it
        assert not loop.skip_to(3.0)  # the other timer comes first
        assert loop.skip_to(1.5) and loop.time() == 1.5
        other.cancel()
        loop.call_soon(print)
        assert not loop.skip_to(1.6) and not loop.skip_to(1.6, again=True)  # something is ready
        loop._ready.clear()
        reader, writer = socket.socketpair()
        loop.add_reader(reader, print)
        # The loop polls its descriptors before any jump; a callback may have added one since the last.
        assert not loop.skip_to(1.6) and not loop.skip_to(1.6, again=True)
        loop.remove_reader(reader)
        reader.close(), writer.close()
        release = threading.Event()
        job = loop.run_in_executor(None, release.wait)
        assert not loop.skip_to(1.6) and not loop.skip_to(1.6, again=True)  # a thread at work: time waits for it
        release.set()
        loop.run_until_complete(job)
        loop.stop()
        assert not loop.skip_to(1.6) and not loop.skip_to(1.6, again=True)  # stopping
        loop._stopping = False
        loop.set_debug(True)
        assert not loop.skip_to(1.6) and not loop.skip_to(1.6, again=True)
        loop.set_debug(False)
        assert loop.skip_to(1.6) and loop.time() == 1.6
        loop.add_signal_handler(signal.SIGUSR1, print)
        assert not loop.skip_to(1.7) and not loop.skip_to(1.7, again=True)  # a signal is the loop's to poll for
        loop.remove_signal_handler(signal.SIGUSR1)
        assert loop.skip_to(1.7, again=True) and loop.time() == 1.7
    finally:
        loop.close()


def test_debug_mode_takes_asyncios_iteration_with_its_slow_callback_warnings(caplog):
    loop = VirtualTimeLoop()
    loop.set_debug(True)
    loop.slow_callback_duration = 0.0  # virtual time stands still in a callback: every one is "slow"
    try:
        with caplog.at_level(logging.WARNING, logger="asyncio"):
            loop.call_soon(lambda: None)
            loop.run_until_complete(asyncio.sleep(0.1))
    finally:
        loop.close()
    assert any("Executing <Handle" in r.getMessage() for r in caplog.records)


def test_a_closed_loop_refuses_new_callbacks_as_asyncios_does():
    loop = VirtualTimeLoop()
    loop.close()
    for schedule in (lambda: loop.call_soon(print), lambda: loop.call_at(1.0, print)):
        with pytest.raises(RuntimeError, match="Event loop is closed"):
            schedule()
