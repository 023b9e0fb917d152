"""Doctor's checks on crafted graphs: each one fails for its problem and passes on a clean graph."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import threading
import time

import anyio
import pytest

from actors import DurabilityPolicy, Node, QoSProfile, ReliabilityPolicy, Runtime, SupervisorPolicy
from actors.cli._client import connect
from actors.ops.control import ControlEndpoint, Subscribe
from actors.ops.doctor import LagEvent, Report, diagnose
from interfaces.std_msgs.msg import Int64, String


class Talker(Node):
    def __init__(self, topic: str = "/chatter", qos: QoSProfile | int = 10) -> None:
        super().__init__("talker")
        self.pub = self.create_publisher(String, topic, qos)
        self.create_timer(0.1, lambda: self.pub.publish(String(data="hi")))


class Listener(Node):
    def __init__(self, topic: str = "/chatter", qos: QoSProfile | int = 10) -> None:
        super().__init__("listener")
        self.create_subscription(String, topic, lambda msg: None, qos)


def checks(report: Report) -> dict[str, tuple[str, ...] | None]:
    """Each check's reasons and warnings, or None when it passed without a warning."""
    return {c.name: (*c.reasons, *c.warnings) or None for c in report.checks}


@pytest.mark.virtual_time
async def test_a_clean_graph_passes_every_check():
    async with Runtime(name="doctor_clean") as rt:
        rt.spawn(Talker)
        rt.spawn(Listener)
        await anyio.sleep(1)
        report = diagnose(rt)
    assert checks(report) == {
        "publishers without subscribers": None,
        "subscriptions without publishers": None,
        "action servers": None,
        "topic types": None,
        "type hashes": None,
        "QoS compatibility": None,
        "node health": None,
        "dropped messages": None,
        "refused messages": None,
        "required packages": None,
    }
    assert not report.lag_measured  # virtual time: the loop's clock stands still in a callback
    assert report.clock == "virtual" and report.graph == "doctor_clean"
    assert {"system", "python"} <= report.platform.keys()
    assert {"actors", "anyio", "msgspec", "pymunk", "numpy"} <= report.versions.keys()


@pytest.mark.virtual_time
async def test_one_sided_topics_warn_but_rosout_parameter_events_and_the_cli_do_not_count():
    class Lonely(Node):
        def __init__(self) -> None:
            super().__init__("lonely")
            self.create_publisher(String, "/shout", 10)
            self.create_subscription(Int64, "/ear", lambda msg: None, 10)
            self.create_subscription(String, "/rosout_copy", lambda msg: None, 10)

    async with Runtime(name="doctor_sided") as rt:
        rt.spawn(Lonely)
        full = diagnose(rt)
        report = checks(full)
    # Warnings, as in ros2doctor: the checks pass unless warnings count as failures.
    assert full.failures() == []
    assert {c.name for c in full.failures(include_warnings=True)} == {
        "publishers without subscribers",
        "subscriptions without publishers",
    }
    assert report["publishers without subscribers"] == (
        "/shout (std_msgs/msg/String) is published by /lonely but nobody subscribes",
    )
    assert report["subscriptions without publishers"] == (
        "/ear (std_msgs/msg/Int64) is subscribed by /lonely but nobody publishes",
        "/rosout_copy (std_msgs/msg/String) is subscribed by /lonely but nobody publishes",
    )


async def test_the_command_lines_own_subscription_is_no_subscriber(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    async with Runtime(name="doctor_cli", attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)

        def echo_and_diagnose() -> dict[str, tuple[str, ...] | None]:
            with connect("doctor_cli") as conn:
                conn.request(Subscribe(topic="/chatter"))
                return checks(anyio.from_thread.run_sync(diagnose, rt))

        report = await anyio.to_thread.run_sync(echo_and_diagnose)
    assert report["publishers without subscribers"] == (
        "/chatter (std_msgs/msg/String) is published by /talker but nobody subscribes",
    )


@pytest.mark.virtual_time
@pytest.mark.parametrize(
    ("offered", "requested", "why"),
    [
        (
            QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT),
            QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE),
            "publisher offers BEST_EFFORT, subscription requests RELIABLE",
        ),
        (
            QoSProfile(depth=10, durability=DurabilityPolicy.VOLATILE),
            QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL),
            "publisher offers VOLATILE, subscription requests TRANSIENT_LOCAL",
        ),
    ],
)
async def test_incompatible_qos_fails(offered, requested, why):
    class Pub(Talker):
        def __init__(self) -> None:
            super().__init__(qos=offered)

    class Sub(Listener):
        def __init__(self) -> None:
            super().__init__(qos=requested)

    async with Runtime(name="doctor_qos") as rt:
        rt.spawn(Pub)
        rt.spawn(Sub)
        report = checks(diagnose(rt))
    assert report["QoS compatibility"] == (f"/chatter: /talker does not reach /listener: {why}",)


@pytest.mark.virtual_time
async def test_a_node_that_crashed_and_restarted_fails_node_health():
    class Fragile(Node):
        crashed = False

        def __init__(self) -> None:
            super().__init__("fragile")
            self.create_timer(0.1, self.tick)

        def tick(self) -> None:
            if not Fragile.crashed:
                Fragile.crashed = True
                raise RuntimeError("boom")

    async with Runtime(name="doctor_crash", supervisor=SupervisorPolicy(backoff=0)) as rt:
        rt.spawn(Fragile)
        await anyio.sleep(1)
        report = checks(diagnose(rt))
    assert report["node health"] == (
        "/fragile is running after 1 crash(es) and 1 restart(s); last error: RuntimeError('boom')",
    )


@pytest.mark.virtual_time
async def test_a_temporary_node_that_crashed_for_good_fails_node_health():
    class Doomed(Node):
        def __init__(self) -> None:
            super().__init__("doomed")
            self.create_timer(0.1, self.tick)

        def tick(self) -> None:
            raise RuntimeError("gone")

    async with Runtime(name="doctor_temporary") as rt:
        rt.spawn(Doomed, restart="temporary")
        await anyio.sleep(1)
        assert rt.graph.nodes() == []
        report = checks(diagnose(rt))
    assert report["node health"] == (
        "/doomed is crashed after 1 crash(es) and 0 restart(s); last error: RuntimeError('gone')",
    )


@pytest.mark.virtual_time
async def test_dropped_messages_fail():
    class Burst(Node):
        def __init__(self) -> None:
            super().__init__("burst")
            pub = self.create_publisher(String, "/burst", 10)
            self.create_timer(0.1, lambda: [pub.publish(String(data=str(i))) for i in range(5)])

    class Slow(Listener):
        def __init__(self) -> None:
            super().__init__(topic="/burst", qos=2)

    async with Runtime(name="doctor_drops") as rt:
        rt.spawn(Burst)
        rt.spawn(Slow)
        await anyio.sleep(0.15)  # one burst: five messages into a queue of two
        report = checks(diagnose(rt))
    assert report["dropped messages"] == ("/burst: /listener dropped 3 message(s) (queue depth 2)",)


class Blocker(Node):
    """A timer callback that holds the loop for 0.1 s of its thread's CPU time, every 0.05 s: what the lag check is for.

    CPU time, not wall time: on a loaded machine a wall-clock busy loop spends
    part of its 0.1 s waiting for a CPU, and the monitor rightly blames the
    callback only for the stall beyond that wait (CI failed so once).  It keeps
    blocking until told to stop: on a starved machine the monitor blames nobody
    for a stall its own watchdog slept through, and a later one is caught.
    """

    def __init__(self) -> None:
        super().__init__("blocker")
        self.timer = self.create_timer(0.05, self.block)

    def block(self) -> None:
        end = time.thread_time() + 0.1
        while time.thread_time() < end:
            pass


async def test_a_callback_blocking_the_loop_is_named_by_node_and_callback(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    async with Runtime(name="doctor_lag", attach=[endpoint := ControlEndpoint()]) as rt:
        blocker = rt.spawn(Blocker)
        assert endpoint.server is not None
        monitor = endpoint.server.monitor
        with anyio.fail_after(60):
            while not any(e.node == "/blocker" for e in monitor.events):
                await anyio.sleep(0.01)  # recorded when the monitor's sleep wakes, late
        blocker.timer.cancel()
        report = diagnose(rt, monitor)
    assert report.lag_measured
    reasons = checks(report)["callbacks blocking the loop"]
    assert reasons is not None
    (reason,) = [r for r in reasons if r.startswith("/blocker:")]
    assert re.fullmatch(r"/blocker: Blocker\.block blocked the loop \d+ time\(s\), longest \d+\.\d+ s", reason), reason
    events = [e for e in report.lag_events if e.node == "/blocker"]
    assert events and all(e.callback == "Blocker.block" and e.lag >= 0.05 for e in events)


async def test_the_command_line_prints_warnings_and_counts_them_only_with_include_warnings(
    tmp_path, monkeypatch, capsys
):
    from actors.cli import main

    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    async with Runtime(name="doctor_warnings", attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)
        assert await anyio.to_thread.run_sync(main, ["doctor"]) == 0
        plain = capsys.readouterr().out
        assert await anyio.to_thread.run_sync(main, ["doctor", "-iw"]) == 0
        strict = capsys.readouterr().out
    reason = "/chatter (std_msgs/msg/String) is published by /talker but nobody subscribes"
    lines = plain.splitlines()
    assert lines[0] == f"WARNING: publishers without subscribers: {reason}"
    assert re.fullmatch(r"All (\d+) checks passed", lines[-1])
    total = re.fullmatch(r"All (\d+) checks passed", lines[-1])[1]
    assert strict.splitlines() == [
        f"1/{total} checks failed",
        f"  publishers without subscribers: {reason}",
    ]


@pytest.mark.virtual_time
async def test_actions_alone_are_healthy_and_a_client_without_server_is_a_warning():
    from nodes.fibonacci_action_client import FibonacciActionClient
    from nodes.fibonacci_action_server import FibonacciActionServer

    async with Runtime(name="doctor_actions") as rt:
        rt.spawn(FibonacciActionServer)
        await anyio.sleep(1)
        assert not any(c.failed(include_warnings=True) for c in diagnose(rt).checks)  # feedback unheard: fine
        await rt.stop("fibonacci_action_server")
        rt.spawn(FibonacciActionClient)
        await anyio.sleep(1)
        report = diagnose(rt)
    assert checks(report)["action servers"] == (
        "/fibonacci (example_interfaces/action/Fibonacci) has clients (/fibonacci_action_client) but no server",
    )
    assert checks(report)["subscriptions without publishers"] is None
    (unserved,) = [c for c in report.checks if c.name == "action servers"]
    assert unserved.passed and unserved.failed(include_warnings=True)


async def test_an_async_callback_that_only_awaits_is_not_blamed_for_a_stall(tmp_path, monkeypatch):
    class Patient(Node):
        def __init__(self) -> None:
            super().__init__("patient")

        async def on_start(self) -> None:
            await anyio.sleep(30)  # awaiting: it does not hold the loop

    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    async with Runtime(name="doctor_await", attach=[endpoint := ControlEndpoint()]) as rt:
        rt.spawn(Patient)
        assert endpoint.server is not None
        monitor = endpoint.server.monitor
        await anyio.sleep(0.1)  # on_start has begun its wait
        end = time.perf_counter() + 0.15
        while time.perf_counter() < end:  # the loop is held here, by no node's callback
            pass
        with anyio.fail_after(5):
            while not monitor.events:
                await anyio.sleep(0.01)
        report = diagnose(rt, monitor)
    assert [e.node for e in report.lag_events] == [""]
    assert checks(report)["callbacks blocking the loop"] is None


@pytest.mark.parametrize(("frozen", "blamed"), [(0.0, ("/n", "run_watchdog.<locals>.callback")), (0.2, ("", ""))])
def test_watchdog_blames_a_running_callback_unless_the_whole_process_was_starved(frozen, blamed):
    # The watchdog thread's logic driven by hand, on a clock of the test's own.
    assert run_watchdog(frozen) == blamed


def run_watchdog(frozen: float) -> tuple[str, str] | None:
    from types import SimpleNamespace

    from actors.ops.doctor import LagMonitor

    now = [0.0]
    entity = SimpleNamespace()
    core = SimpleNamespace(fqn="/n", actor=SimpleNamespace(current=entity, busy_since=0.0))
    runtime = SimpleNamespace(name="fake", nodes={"/n": core}, clock=SimpleNamespace(monotonic=lambda: now[0]))
    monitor = LagMonitor(runtime)  # type: ignore[arg-type]
    stops = iter([False, True])

    def wait(period: float) -> bool:
        now[0] += period + frozen  # the stall: 0.2 s more when the whole process was frozen
        return next(stops)

    def callback() -> None:  # "running on the loop thread" while the watchdog looks
        monitor._watch()

    monitor._stop.wait = wait  # type: ignore[method-assign]
    entity.callback = callback
    now[0] = 1.0  # the loop's last tick was a second ago
    callback()
    return monitor._suspect


@pytest.mark.parametrize(
    ("waited", "blamed"),
    [
        (0.0, "/n"),  # the callback held the loop all along
        (0.1, "/n"),  # preempted for part of it, still 0.1 s over the threshold on its own
        (0.19, ""),  # preempted for nearly all of it: the machine was busy, not the callback
    ],
)
def test_a_stall_spent_waiting_for_a_cpu_is_not_blamed_on_the_callback(monkeypatch, waited, blamed):
    # LagMonitor.run driven by hand: a fake clock, a fake sleep that stalls 0.2 s
    # while the watchdog has named a suspect, and a fake run-queue counter.
    import asyncio
    from types import SimpleNamespace

    from actors.ops import doctor

    now = [0.0]
    queued = [0.0]
    clock = SimpleNamespace(monotonic=lambda: now[0], now_ns=lambda: int(now[0] * 1e9))
    monitor = doctor.LagMonitor(SimpleNamespace(name="fake", nodes={}, clock=clock))  # type: ignore[arg-type]
    monitor._watch = lambda: None  # type: ignore[method-assign]  # the suspect is set by hand below
    sleeps = iter([0.0, 0.2])

    class Done(Exception):
        pass

    async def sleep(period: float) -> None:
        stall = next(sleeps, None)
        if stall is None:
            raise Done
        now[0] += period + stall
        if stall:
            queued[0] += waited
            monitor._suspect = ("/n", "cb")

    class FakeWait:
        def __call__(self) -> float:
            return queued[0]

        def close(self) -> None:
            pass

    monkeypatch.setattr(doctor.anyio, "sleep", sleep)
    monkeypatch.setattr(doctor, "_CpuWait", FakeWait)
    with pytest.raises(Done):
        asyncio.run(monitor.run())
    (event,) = monitor.events
    assert event.lag == pytest.approx(0.2) and event.node == blamed


@pytest.mark.skipif(not os.path.exists("/proc/thread-self/schedstat"), reason="Linux scheduler statistics")
def test_the_run_queue_counter_counts_a_threads_wait_for_a_cpu_not_its_time_on_one():
    # One CPU shared with two busy processes: a thread gets about a third of it,
    # so it waits about twice as long as it runs.  (Counting its time on the CPU
    # instead would give a ratio of 1.)
    from actors.ops.doctor import _CpuWait

    cpu = min(os.sched_getaffinity(0))
    hogs = [
        subprocess.Popen([sys.executable, "-c", "print(flush=True)\nwhile True: pass"], stdout=subprocess.PIPE)
        for _ in range(2)
    ]
    measured: list[float] = []

    def busy() -> None:
        waited = _CpuWait()
        os.sched_setaffinity(0, {cpu})  # this thread only
        before, ran = waited(), time.thread_time()
        while time.thread_time() - ran < 0.1:
            pass
        measured.append((waited() - before) / (time.thread_time() - ran))
        waited.close()

    try:
        for hog in hogs:
            assert hog.stdout is not None and hog.stdout.readline() == b"\n"  # it is running
            os.sched_setaffinity(hog.pid, {cpu})
        thread = threading.Thread(target=busy)
        thread.start()
        thread.join()
    finally:
        for hog in hogs:
            hog.kill()
            hog.wait()
    (ratio,) = measured
    assert ratio > 1.4, ratio


def test_a_loop_lag_line_names_the_callback_or_says_none_held_the_loop():
    from actors.cli.doctor import lag_line

    blamed = LagEvent(stamp=1.5, lag=0.25, node="/sleeper", callback="timer callback on_tick")
    assert lag_line(blamed) == ("1.500", "0.250 s late, running /sleeper timer callback on_tick")
    unblamed = LagEvent(stamp=2.0, lag=0.1)
    assert lag_line(unblamed) == (
        "2.000",
        "0.100 s late, no node's callback held the loop (another task, or the process was not scheduled)",
    )
