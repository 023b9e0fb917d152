"""Virtual time (the loop jumps to the next timer, waits for threads, reports deadlocks), Time, Duration, Clock."""

from __future__ import annotations

import asyncio
import concurrent.futures
import os
import signal
import socket
import sys
import threading
import time

import anyio
import pytest

from actors import Node, Runtime
from actors.core.loops import VirtualTimeLoop
from actors.errors import VirtualTimeDeadlock
from actors.ros.time import Clock, ClockType, Duration, Infinite, Rate, ROSClock, Time


class Idle(Node):
    def __init__(self) -> None:
        super().__init__("idle")


@pytest.mark.virtual_time
async def test_an_hour_of_sleep_takes_no_real_time():
    loop = asyncio.get_running_loop()
    assert isinstance(loop, VirtualTimeLoop)
    assert loop.time() == 0.0
    started = time.perf_counter()
    await anyio.sleep(3600)
    assert loop.time() == 3600.0
    assert time.perf_counter() - started < 60  # an hour would take an hour without the jump


def test_anyio_run_with_the_virtual_loop_factory():
    async def main() -> float:
        await anyio.sleep(10.5)
        return asyncio.get_running_loop().time()

    assert anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop}) == 10.5


def test_the_clock_starts_at_the_epoch_offset():
    async def main() -> tuple[int, int]:
        clock = ROSClock(asyncio.get_running_loop())
        first = clock.now_ns()
        await asyncio.sleep(2.5)
        return first, clock.now().nanoseconds

    with asyncio.Runner(loop_factory=lambda: VirtualTimeLoop(epoch=1000.0)) as runner:
        assert runner.run(main()) == (1_000_000_000_000, 1_002_500_000_000)


@pytest.mark.virtual_time
async def test_no_jump_while_executor_work_runs():
    loop = asyncio.get_running_loop()
    far_timer = asyncio.ensure_future(asyncio.sleep(100))
    await loop.run_in_executor(None, threading.Event().wait, 0.05)
    assert loop.time() < 100, "virtual time jumped while a thread was working"
    far_timer.cancel()


@pytest.mark.virtual_time
async def test_no_jump_while_the_default_executor_is_joined():
    # asyncio.Runner joins the default executor at its end, with a timeout (Python >= 3.12) that
    # a jump would reach at once, leaving the threads behind with a warning.
    loop = asyncio.get_running_loop()
    executor = concurrent.futures.ThreadPoolExecutor(max_workers=1)
    loop.set_default_executor(executor)
    executor.submit(threading.Event().wait, 0.05)
    far_timer = asyncio.ensure_future(asyncio.sleep(100))
    await loop.shutdown_default_executor()
    assert loop.time() < 100, "virtual time jumped while the executor's threads were joined"
    far_timer.cancel()


@pytest.mark.virtual_time
async def test_no_jump_while_anyio_thread_work_runs():
    loop = asyncio.get_running_loop()
    far_timer = asyncio.ensure_future(asyncio.sleep(100))
    await anyio.to_thread.run_sync(threading.Event().wait, 0.05)
    assert loop.time() < 100, "virtual time jumped while an anyio worker thread was working"
    far_timer.cancel()


def test_work_a_thread_hands_over_as_it_goes_idle_runs_before_any_jump():
    # A thread hands work to the loop (call_soon_threadsafe) and then goes idle; that may happen
    # at the very moment the loop asks whether any thread is busy, just before it would jump.
    class HandOverWhenAsked(VirtualTimeLoop):
        handed = False

        def threads_busy(self) -> bool:
            if not self.handed:
                self.handed = True
                self.call_soon_threadsafe(lambda: ran_at.append(self.time()))
            return False

    ran_at: list[float] = []

    async def main() -> None:
        far = asyncio.ensure_future(asyncio.sleep(100))
        while not ran_at:
            await asyncio.sleep(0.5)
        far.cancel()

    with asyncio.Runner(loop_factory=HandOverWhenAsked) as runner:
        runner.run(main())
    assert ran_at == [0.0], "virtual time jumped past work handed over as its thread went idle"


def _ticks(loop: VirtualTimeLoop, at: float, then) -> asyncio.Future[None]:
    """Ten timers 0.1 s apart, one at a time (each jump of time alone in its iteration); ``then()`` runs at ``at``."""
    done = loop.create_future()

    def tick(n: int) -> None:
        if abs(loop.time() - at) < 1e-9:
            then()
        if n:
            loop.call_at(loop.time() + 0.1, tick, n - 1)
        else:
            done.set_result(None)

    loop.call_at(0.1, tick, 9)
    return done


def test_with_only_the_self_pipe_watched_time_jumps_without_asking_the_kernel():
    loop = VirtualTimeLoop()
    peek = loop._selector._peek  # type: ignore[attr-defined]
    if peek is None:
        pytest.skip("no epoll here: every jump polls with select()")
    peeks: list[float] = []
    loop._selector._peek = lambda *args: (peeks.append(loop.time()), peek(*args))[1]  # type: ignore[attr-defined]
    try:
        loop.run_until_complete(_ticks(loop, -1, lambda: None))
        assert loop.time() == pytest.approx(1.0)
    finally:
        loop.close()
    # Only where a callback was ready (the end): ten jumps without a system call each.
    assert peeks == [pytest.approx(1.0)]


def test_data_on_a_watched_socket_is_read_before_time_jumps_on():
    loop = VirtualTimeLoop()
    reader, writer = socket.socketpair()
    seen: list[tuple[bytes, float]] = []
    loop.add_reader(reader, lambda: seen.append((reader.recv(10), loop.time())))
    try:
        loop.run_until_complete(_ticks(loop, 0.3, lambda: writer.send(b"x")))
    finally:
        loop.remove_reader(reader)
        loop.close()
        reader.close()
        writer.close()
    assert seen == [(b"x", pytest.approx(0.3))]


@pytest.mark.skipif(not hasattr(signal, "SIGUSR1"), reason="needs POSIX signals")
def test_a_signal_handler_runs_at_the_instant_its_signal_came():
    loop = VirtualTimeLoop()
    seen: list[float] = []
    loop.add_signal_handler(signal.SIGUSR1, lambda: seen.append(loop.time()))
    try:
        loop.run_until_complete(_ticks(loop, 0.3, lambda: os.kill(os.getpid(), signal.SIGUSR1)))
    finally:
        loop.remove_signal_handler(signal.SIGUSR1)
        loop.close()
    assert seen == [pytest.approx(0.3)]


def test_waiting_on_nothing_is_a_clear_error():
    async def main() -> None:
        await asyncio.Event().wait()

    with (
        asyncio.Runner(loop_factory=lambda: VirtualTimeLoop(idle_timeout=0.05)) as runner,
        pytest.raises(VirtualTimeDeadlock, match="no timer is scheduled"),
    ):
        runner.run(main())


@pytest.mark.virtual_time
async def test_rate_sleeps_to_absolute_deadlines():
    loop = asyncio.get_running_loop()
    rate = Rate(4.0, loop)
    stamps = []
    for _ in range(4):
        await rate.sleep()
        stamps.append(loop.time())
        await asyncio.sleep(0.1)  # work inside the period does not shift the deadlines
    assert stamps == [0.25, 0.5, 0.75, 1.0]


# -- Time and Duration: rclpy's semantics (checked against rclpy Kilted) ---------------


def test_time_and_duration_are_built_from_seconds_and_nanoseconds():
    t = Time(seconds=1, nanoseconds=5e8)
    assert (t.nanoseconds, t.clock_type) == (1_500_000_000, ClockType.SYSTEM_TIME)
    assert t.seconds_nanoseconds() == (1, 500_000_000)
    assert Time(nanoseconds=15e8).seconds_nanoseconds() == (1, 500_000_000)
    assert Time(nanoseconds=2**63 - 1).nanoseconds == 2**63 - 1
    assert Duration(seconds=-1).nanoseconds == -1_000_000_000  # a duration may be negative
    assert Duration(nanoseconds=-(2**63)).nanoseconds == -(2**63)
    assert Duration(seconds=1.001).nanoseconds == 1_001_000_000  # rounded (rclpy truncates: 1000999999)


@pytest.mark.parametrize(
    ("make", "error"),
    [
        (lambda: Time(seconds=-1), ValueError),
        (lambda: Time(nanoseconds=-1), ValueError),
        (lambda: Time(nanoseconds=2**63), OverflowError),
        (lambda: Time(clock_type="STEADY_TIME"), TypeError),
        (lambda: Duration(nanoseconds=2**63), OverflowError),
        (lambda: Duration(nanoseconds=-(2**63) - 1), OverflowError),
    ],
)
def test_out_of_range_times_and_durations_are_refused(make, error):
    with pytest.raises(error):
        make()


def test_duration_arithmetic():
    one, two = Duration(seconds=1), Duration(seconds=2)
    assert (one + two).nanoseconds == 3_000_000_000
    assert (two - one) == one and (one - two).nanoseconds == -1_000_000_000
    assert one * 2 == two and two * 0.5 == one
    assert one * float("inf") == Infinite and str(Infinite) == "Infinite"
    assert str(one) == "1000000000 nanoseconds"
    with pytest.raises(ValueError):
        one * float("nan")
    with pytest.raises(TypeError):
        one + 1
    with pytest.raises(TypeError):
        one * "2"


def test_time_arithmetic_keeps_the_clock_type():
    t = Time(nanoseconds=1, clock_type=ClockType.STEADY_TIME)
    one_ns = Duration(nanoseconds=1)
    for later in (t + one_ns, one_ns + t):
        assert isinstance(later, Time)
        assert (later.nanoseconds, later.clock_type) == (2, ClockType.STEADY_TIME)
    assert (t - one_ns).nanoseconds == 0 and (t - one_ns).clock_type == ClockType.STEADY_TIME
    diff = Time(nanoseconds=3) - Time(nanoseconds=1)
    assert isinstance(diff, Duration) and diff.nanoseconds == 2
    assert (Time(nanoseconds=1) - Time(nanoseconds=2)).nanoseconds == -1
    with pytest.raises(ValueError):
        t - Duration(nanoseconds=2)  # before the epoch
    with pytest.raises(OverflowError):
        Time(nanoseconds=2**63 - 1) + one_ns
    with pytest.raises(TypeError):
        Time() + Time()
    with pytest.raises(TypeError):
        Time(clock_type=ClockType.ROS_TIME) - Time(clock_type=ClockType.SYSTEM_TIME)
    with pytest.raises(TypeError):
        Duration() - Time()


def test_times_compare_only_with_times_of_the_same_clock():
    early, late = Time(nanoseconds=1), Time(nanoseconds=2)
    assert early < late and early <= late and late > early and late >= early
    assert early != late and early == Time(nanoseconds=1)
    steady = Time(nanoseconds=1, clock_type=ClockType.STEADY_TIME)
    for compare in (lambda: early == steady, lambda: early < steady, lambda: early >= steady):
        with pytest.raises(TypeError):
            compare()
    duration = Duration(nanoseconds=1)
    assert (early == 1) is False and (early == duration) is False and early != duration
    for compare in (lambda: early < duration, lambda: early >= duration, lambda: duration > early):
        with pytest.raises(TypeError):
            compare()
    assert Duration(seconds=1) < Duration(seconds=2) and Duration(seconds=1) == Duration(nanoseconds=10**9)


def test_message_conversions():
    t = Time(seconds=3, nanoseconds=5, clock_type=ClockType.ROS_TIME)
    msg = t.to_msg()
    assert (type(msg).__ros_type__, msg.sec, msg.nanosec) == ("builtin_interfaces/msg/Time", 3, 5)
    back = Time.from_msg(msg)
    assert back == t and back.clock_type == ClockType.ROS_TIME  # from_msg means ROS time
    assert Time.from_msg(msg, clock_type=ClockType.SYSTEM_TIME).clock_type == ClockType.SYSTEM_TIME
    big = Time(nanoseconds=2**63 - 1, clock_type=ClockType.ROS_TIME)
    assert Time.from_msg(big.to_msg()) == big
    d = Duration(seconds=-1, nanoseconds=1)
    assert Duration.from_msg(d.to_msg()) == d
    with pytest.raises(TypeError):
        Time.from_msg(d.to_msg())
    with pytest.raises(TypeError):
        Duration.from_msg(msg)


def test_clocks_of_each_type():
    assert type(Clock()) is Clock and Clock().clock_type == ClockType.SYSTEM_TIME
    assert Clock(clock_type=ClockType.STEADY_TIME).clock_type == ClockType.STEADY_TIME
    ros = Clock(clock_type=ClockType.ROS_TIME)
    assert isinstance(ros, ROSClock) and ros.clock_type == ClockType.ROS_TIME
    assert ROSClock().clock_type == ClockType.ROS_TIME
    with pytest.raises(TypeError):
        Clock(clock_type="STEADY_TIME")
    now = Clock().now()
    assert now.clock_type == ClockType.SYSTEM_TIME
    assert abs(now.nanoseconds / 1e9 - time.time()) < 5  # the system clock, as in ROS
    steady = Clock(clock_type=ClockType.STEADY_TIME)
    first = steady.now()
    assert steady.now() >= first


def test_an_unbound_ros_clock_can_be_driven_by_hand():
    clock = ROSClock()
    assert not clock.ros_time_is_active
    clock._set_ros_time_is_active(True)
    clock.set_ros_time_override(Time(seconds=42, clock_type=ClockType.ROS_TIME))
    assert clock.ros_time_is_active and clock.now() == Time(seconds=42, clock_type=ClockType.ROS_TIME)
    with pytest.raises(TypeError):
        clock.set_ros_time_override(42)


def test_a_loop_time_read_earlier_converts_to_what_now_said_then():
    for loop in (asyncio.new_event_loop(), VirtualTimeLoop(epoch=5.0)):
        try:
            clock = ROSClock(loop)
            then = loop.time()
            now = clock.now_ns()
            at_then, at_later, at_now = clock.ns_at([then, then + 0.25, loop.time()])
            assert at_then <= now <= at_now
            if isinstance(loop, VirtualTimeLoop):
                assert at_then == now == 5_000_000_000
            assert at_later - at_then == 250_000_000
            assert clock.ns_at([]) == []
            clock._set_ros_time_is_active(True)  # a time set by hand counts as it is now
            clock.set_ros_time_override(Time(seconds=42, clock_type=ClockType.ROS_TIME))
            assert clock.ns_at([then, then + 1.0]) == [42_000_000_000] * 2
        finally:
            loop.close()


def test_now_is_checked_as_a_time_made_by_hand():
    class Odd(Clock):
        def __init__(self, ns: object) -> None:
            super().__init__(clock_type=ClockType.STEADY_TIME)
            self.ns = ns

        def now_ns(self) -> object:
            return self.ns

    assert Odd(7).now() == Time(nanoseconds=7, clock_type=ClockType.STEADY_TIME)
    assert Odd(7.6).now().nanoseconds == 8  # rounded, as Time(nanoseconds=7.6) is
    with pytest.raises(ValueError, match="negative nanoseconds"):
        Odd(-1).now()
    with pytest.raises(OverflowError):
        Odd(2**63).now()
    loop = VirtualTimeLoop(epoch=-1.0)  # virtual time 0 is a second before 1970
    try:
        with pytest.raises(ValueError, match="negative nanoseconds"):
            ROSClock(loop).now()
    finally:
        loop.close()


@pytest.mark.virtual_time
async def test_the_runtime_clock_is_ros_time_on_the_loop():
    async with Runtime() as rt:
        node = rt.spawn(Idle)
        clock = node.get_clock()
        assert isinstance(clock, ROSClock) and clock.ros_time_is_active  # virtual = simulated time
        await anyio.sleep(1.5)
        now = clock.now()
        assert now == Time(seconds=1.5, clock_type=ClockType.ROS_TIME)
        assert await clock.sleep_for(Duration(seconds=0.5))
        assert await clock.sleep_until(now + Duration(seconds=1))
        assert clock.now() - now == Duration(seconds=1)
        with pytest.raises(ValueError):
            await clock.sleep_until(Time(seconds=9))  # a SYSTEM_TIME Time


def test_precise_loop_waits_in_select():
    import selectors

    from actors.core.loops import precise_loop

    loop = precise_loop()
    try:
        assert isinstance(loop._selector, selectors.SelectSelector)  # microsecond waits, not epoll's ms
    finally:
        loop.close()


def test_actors_run_uses_the_precise_loop_on_the_wall_clock(monkeypatch):
    import actors.run
    from actors.core.loops import precise_loop

    seen = {}
    monkeypatch.setattr(actors.run.anyio, "run", lambda fn, backend_options: seen.update(backend_options))
    monkeypatch.setattr(actors.run, "configure_console", lambda level: None)
    assert actors.run.main(["graph.toml", "--clock", "wall"]) == 0
    assert seen["loop_factory"] is precise_loop
    assert actors.run.main(["graph.toml", "--clock", "virtual", "--duration", "1"]) == 0
    assert seen["loop_factory"] is VirtualTimeLoop


@pytest.mark.virtual_time
async def test_advance_moves_virtual_time_at_once():
    loop = asyncio.get_running_loop()
    due = loop.create_future()
    loop.call_at(5.0, due.set_result, None)
    loop.advance(10.0)
    await due
    assert loop.time() == 10.0  # without the advance, the loop would have jumped to 5.0
    with pytest.raises(ValueError, match="backwards"):
        loop.advance(-1)


@pytest.mark.virtual_time
async def test_a_nodes_rate_and_destroying_it():
    async with Runtime() as rt:
        node = rt.spawn(Idle)
        rate = node.create_rate(2.0)
        await rate.sleep()
        assert node.get_clock().now() == Time(seconds=0.5, clock_type=ClockType.ROS_TIME)
        woke_at = []

        async def sleeper() -> None:
            await rate.sleep()
            woke_at.append(asyncio.get_running_loop().time())

        async with anyio.create_task_group() as tg:
            tg.start_soon(sleeper)
            await anyio.sleep(0.1)
            assert node.destroy_rate(rate)  # wakes the sleeper before its deadline at 1.0
        assert woke_at == [0.6]
        with pytest.raises(RuntimeError, match="destroyed"):
            await rate.sleep()
        with pytest.raises(ValueError):
            node.create_rate(0)
        with pytest.raises(ValueError):
            node.create_rate(1.0, clock=Clock())


def test_uvloop_loop_without_uvloop_names_the_extra(monkeypatch):
    from actors.core.loops import uvloop_loop

    monkeypatch.setitem(sys.modules, "uvloop", None)  # as if not installed
    with pytest.raises(ImportError, match=r"uvloop is not installed: pip install 'actors\[fast\]'"):
        uvloop_loop()


def test_a_graph_with_a_transport_runs_on_uvloop_by_default_when_it_is_installed(monkeypatch):
    pytest.importorskip("uvloop")
    from actors.core.loops import precise_loop, uvloop_loop, wall_loop

    assert wall_loop(None, transport=True) is uvloop_loop
    assert wall_loop(None, transport=False) is precise_loop
    assert wall_loop("select", transport=True) is precise_loop  # --loop says otherwise
    assert wall_loop("asyncio", transport=False) is asyncio.new_event_loop
    monkeypatch.setitem(sys.modules, "uvloop", None)  # as if not installed
    assert wall_loop(None, transport=True) is precise_loop  # no error: the usual loop


def test_a_uvloop_that_does_not_load_leaves_a_transport_graph_on_select(monkeypatch, tmp_path):
    from test_run import broken_uvloop

    from actors.core.loops import precise_loop, wall_loop

    broken_uvloop(monkeypatch, tmp_path)
    assert wall_loop(None, transport=True) is precise_loop


def test_ros_time_on_uvloop_has_nanoseconds_within_one_callback():
    # uvloop's loop.time() is its clock as of its last turn, in whole milliseconds: ROS time read
    # from it would stand still within a callback and move in steps of a millisecond.
    pytest.importorskip("uvloop")

    async def main() -> tuple[int, int]:
        clock = ROSClock(asyncio.get_running_loop())
        first = later = clock.now_ns()
        for _ in range(10_000_000):  # the clock moves within microseconds: no wait for time to pass
            later = clock.now_ns()
            if later != first:
                break
        return first, later

    first, later = anyio.run(main, backend_options={"use_uvloop": True})
    assert later > first
    assert (later - first) % 1_000_000, f"ROS time moved by whole milliseconds: {later - first} ns"


def test_a_runtime_runs_on_uvloop():
    uvloop = pytest.importorskip("uvloop")
    from actors.core.loops import uvloop_loop

    class Ticker(Node):
        def __init__(self) -> None:
            super().__init__("ticker")
            self.third = anyio.Event()
            self.ticks = 0
            self.create_timer(0.005, self.tick)

        def tick(self) -> None:
            self.ticks += 1
            if self.ticks == 3:
                self.third.set()

    async def main() -> None:
        async with Runtime() as rt:
            assert isinstance(asyncio.get_running_loop(), uvloop.Loop)
            node = rt.spawn(Ticker)
            with anyio.fail_after(5):
                await node.third.wait()

    anyio.run(main, backend_options={"loop_factory": uvloop_loop})


def _reads(clock: ROSClock) -> tuple[int, int, int]:
    """now_ns(), then the reader's time as ROS time, then now_ns() again."""
    before = clock.now_ns()
    (read,) = clock.ns_at([clock.reader()()])
    return before, read, clock.now_ns()


def test_the_clocks_reader_reads_what_now_ns_reads_on_virtual_time():
    async def main() -> tuple[tuple[int, int, int], float]:
        clock = ROSClock(asyncio.get_running_loop())
        await asyncio.sleep(2.5)
        return _reads(clock), clock.reader()()

    with asyncio.Runner(loop_factory=lambda: VirtualTimeLoop(epoch=1000.0)) as runner:
        assert runner.run(main()) == ((1_002_500_000_000,) * 3, 2.5)
    with pytest.raises(RuntimeError, match="unbound ROSClock"):
        ROSClock().reader()


def test_the_clocks_reader_on_uvloop_moves_within_a_callback_as_now_ns_does():
    # A recorder stamps with the reader (ROSClock.reader): on uvloop it must not be loop.time(),
    # the millisecond of the loop's last turn.
    pytest.importorskip("uvloop")

    async def main() -> tuple[tuple[int, int, int], float, float]:
        clock = ROSClock(asyncio.get_running_loop())
        read = clock.reader()
        first = later = read()
        for _ in range(10_000_000):  # the clock moves within microseconds: no wait for time to pass
            later = read()
            if later != first:
                break
        return _reads(clock), first, later

    (before, read, after), first, later = anyio.run(main, backend_options={"use_uvloop": True})
    assert before <= read <= after
    assert later > first
    assert round((later - first) * 1e9) % 1_000_000, f"the reader moved by whole milliseconds: {later - first} s"
