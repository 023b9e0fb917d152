"""rclpy's blocking API on actors: spinning, executors, callback groups, futures, waits, virtual time.

These tests are the script: they call ``actors.compat.rclpy`` on the test's thread, beside a
virtual-clock session, as a program under ``actors run --clock virtual`` would.
"""

from __future__ import annotations

import threading
import time
from typing import Any

import pytest

import actors.compat.rclpy as rclpy
from actors.compat import Session
from actors.compat.rclpy.callback_groups import (
    CallbackGroup,
    MutuallyExclusiveCallbackGroup,
    ReentrantCallbackGroup,
)
from actors.compat.rclpy.executors import (
    ExternalShutdownException,
    MultiThreadedExecutor,
    SingleThreadedExecutor,
    TimeoutException,
)
from actors.compat.rclpy.qos import QoSProfile
from actors.compat.rclpy.task import Future
from actors.compat.rclpy.wait_for_message import wait_for_message
from actors.ros.node import Node as NativeNode
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import Int64, String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def now(session: Session) -> float:
    return session.loop.time()


def spawn_native(session: Session, cls: type, **options: Any) -> Any:
    return session.call(session.runtime.spawn, cls, **options)


class Adder(NativeNode):
    def __init__(self) -> None:
        super().__init__("native_adder")
        self.create_service(AddTwoInts, "add", lambda req, res: AddTwoInts.Response(sum=req.a + req.b))


class Numbers(NativeNode):
    def __init__(self) -> None:
        super().__init__("numbers")
        self.pub = self.create_publisher(Int64, "n", 100)


def test_callbacks_run_only_while_spun_and_on_the_spinning_thread(session):
    node = rclpy.create_node("ticker")
    ran: list[tuple[float, threading.Thread]] = []
    node.create_timer(0.1, lambda: ran.append((now(session), threading.current_thread())))
    session.sleep(1.05)  # ten periods pass with nobody spinning
    assert ran == []
    rclpy.spin_once(node, timeout_sec=0)  # the ticks nobody took are one call, as an rcl timer's
    assert ran == [(1.05, threading.current_thread())]
    rclpy.spin_once(node)  # waits for the next tick: virtual time moves while the thread waits
    assert [t for t, _ in ran] == [1.05, pytest.approx(1.1)]


def test_spin_once_runs_one_callback_and_a_timeout_in_virtual_seconds(session):
    node = rclpy.create_node("two")
    heard: list[str] = []
    node.create_subscription(String, "a", lambda m: heard.append(m.data), 10)
    pub = node.create_publisher(String, "a", 10)
    pub.publish(String(data="one"))
    pub.publish(String(data="two"))
    rclpy.spin_once(node, timeout_sec=0)
    assert heard == ["one"]
    rclpy.spin_once(node, timeout_sec=0)
    assert heard == ["one", "two"]
    start = now(session)
    rclpy.spin_once(node, timeout_sec=2.5)  # nothing left: returns after 2.5 virtual seconds
    assert now(session) - start == pytest.approx(2.5)


def test_a_subscription_keeps_its_depth_while_nobody_spins(session):
    node = rclpy.create_node("slow")
    heard: list[int] = []
    sub = node.create_subscription(Int64, "n", lambda m: heard.append(m.data), QoSProfile(depth=2))
    numbers = spawn_native(session, Numbers)
    for i in range(5):
        session.call(numbers.pub.publish, Int64(data=i))
    session.sleep(0.1)
    while heard != [3, 4]:
        rclpy.spin_once(node, timeout_sec=0)
        assert len(heard) <= 2
    assert sub.dropped == 3  # counted as the native subscription's drops (doctor reports them)


def test_wait_for_service_returns_false_after_its_timeout_then_true(session):
    node = rclpy.create_node("asker")
    client = node.create_client(AddTwoInts, "add")
    start = now(session)
    assert client.wait_for_service(timeout_sec=1.0) is False
    assert now(session) - start == pytest.approx(1.0)
    spawn_native(session, Adder)
    assert client.wait_for_service(timeout_sec=1.0) is True
    future = client.call_async(AddTwoInts.Request(a=2, b=3))
    session.sleep(1.0)
    assert not future.done()  # the response waits for the node to be spun, as in rclpy
    rclpy.spin_until_future_complete(node, future)
    assert future.result().sum == 5


def test_spin_until_future_complete_gives_up_after_its_timeout(session):
    node = rclpy.create_node("patient")
    start = now(session)
    future: Future[Any] = Future()
    rclpy.spin_until_future_complete(node, future, timeout_sec=3.0)
    assert not future.done()
    assert now(session) - start == pytest.approx(3.0)


def test_a_synchronous_call_while_another_thread_spins(session):
    spawn_native(session, Adder)
    node = rclpy.create_node("caller")
    client = node.create_client(AddTwoInts, "add")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    spinner = threading.Thread(target=_spin_quietly, args=(executor,), daemon=True)
    spinner.start()
    assert client.call(AddTwoInts.Request(a=40, b=2)).sum == 42
    executor.shutdown()


def test_a_synchronous_call_times_out_in_virtual_seconds(session):
    node = rclpy.create_node("nobody_answers")
    client = node.create_client(AddTwoInts, "missing")
    start = now(session)
    with pytest.raises(TimeoutError):
        client.call(AddTwoInts.Request(a=1, b=1), timeout_sec=2.0)
    assert now(session) - start == pytest.approx(2.0)


def _spin_quietly(executor: Any) -> None:
    try:
        executor.spin()
    except ExternalShutdownException:
        pass


def test_a_coroutine_callback_awaits_a_service_while_the_executor_goes_on(session):
    spawn_native(session, Adder)
    node = rclpy.create_node("async_caller")
    group = ReentrantCallbackGroup()
    client = node.create_client(AddTwoInts, "add", callback_group=group)
    results: list[int] = []
    ticks: list[float] = []

    async def ask() -> None:
        timer.cancel()
        response = await client.call_async(AddTwoInts.Request(a=1, b=2))
        results.append(response.sum)

    timer = node.create_timer(0.5, ask, callback_group=group)
    node.create_timer(0.2, lambda: ticks.append(now(session)))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    while not results:
        executor.spin_once()
    assert results == [3]
    assert ticks == [pytest.approx(0.2), pytest.approx(0.4)]


def test_multi_threaded_executor_runs_reentrant_callbacks_side_by_side(session):
    node = rclpy.create_node("parallel")
    spans: dict[str, tuple[float, float]] = {}

    def work(name: str) -> None:
        start = now(session)
        session.sleep(1.0)  # blocks its pool thread for a virtual second
        spans[name] = (start, now(session))

    group = ReentrantCallbackGroup()
    a = node.create_timer(0.5, lambda: (a.cancel(), work("a")), callback_group=group)
    b = node.create_timer(0.5, lambda: (b.cancel(), work("b")), callback_group=group)
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    while len(spans) < 2:
        executor.spin_once(timeout_sec=0.5)
    executor.shutdown()
    assert spans == {"a": (0.5, 1.5), "b": (0.5, 1.5)}


def test_a_mutually_exclusive_group_runs_one_callback_at_a_time(session):
    node = rclpy.create_node("serial")
    spans: list[tuple[float, float]] = []

    def work() -> None:
        start = now(session)
        session.sleep(1.0)
        spans.append((start, now(session)))

    group = MutuallyExclusiveCallbackGroup()
    a = node.create_timer(0.5, lambda: (a.cancel(), work()), callback_group=group)
    b = node.create_timer(0.5, lambda: (b.cancel(), work()), callback_group=group)
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    while len(spans) < 2:
        executor.spin_once(timeout_sec=0.5)
    executor.shutdown()
    assert spans == [(0.5, 1.5), (1.5, 2.5)]


def test_a_callback_group_of_ones_own_decides(session):
    class EveryOther(CallbackGroup):
        def __init__(self) -> None:
            super().__init__()
            self.asked = 0

        def can_execute(self, entity: Any) -> bool:
            return True

        def beginning_execution(self, entity: Any) -> bool:
            self.asked += 1
            return self.asked % 2 == 1

        def ending_execution(self, entity: Any) -> None:
            pass

    node = rclpy.create_node("picky")
    ran: list[float] = []
    group = EveryOther()
    node.create_timer(1.0, lambda: ran.append(now(session)), callback_group=group)
    for _ in range(4):
        rclpy.spin_once(node, timeout_sec=1.5)
    # Refused at 2.0, the tick stays ready and runs at the next spin, as in rclpy.
    assert ran == [1.0, 2.0]
    assert group.asked == 4


def test_a_custom_executor_runs_handlers_on_threads_of_its_own(session):
    from concurrent.futures import ThreadPoolExecutor

    from actors.compat.rclpy.executors import Executor

    class Pooled(Executor):
        def __init__(self) -> None:
            super().__init__()
            self.pool = ThreadPoolExecutor(max_workers=1)

        def spin_once(self, timeout_sec: float | None = None) -> None:
            try:
                handler, _entity, _node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
            except TimeoutException:
                return
            self.pool.submit(handler)

    node = rclpy.create_node("pooled")
    threads: list[str] = []
    node.create_timer(0.5, lambda: threads.append(threading.current_thread().name))
    executor = Pooled()
    executor.add_node(node)
    while len(threads) < 3:
        executor.spin_once(timeout_sec=1.0)
    executor.pool.shutdown()
    assert all(name != threading.current_thread().name for name in threads)


def test_guard_conditions_run_their_callback_at_the_next_spin(session):
    node = rclpy.create_node("guarded")
    ran: list[threading.Thread] = []
    guard = node.create_guard_condition(lambda: ran.append(threading.current_thread()))
    other = threading.Thread(target=guard.trigger)
    other.start()
    other.join()
    assert ran == []
    rclpy.spin_once(node, timeout_sec=0)
    assert ran == [threading.current_thread()]


def test_rate_sleep_paces_a_loop_while_another_thread_spins(session):
    node = rclpy.create_node("paced")
    rate = node.create_rate(4)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=_spin_quietly, args=(executor,), daemon=True).start()
    stamps = []
    for _ in range(3):
        rate.sleep()
        stamps.append(now(session))
    assert stamps == [pytest.approx(0.25), pytest.approx(0.5), pytest.approx(0.75)]


def test_wait_for_message_without_spinning(session):
    node = rclpy.create_node("waiter")
    numbers = spawn_native(session, Numbers)
    session.call(session.loop.call_later, 2.0, numbers.pub.publish, Int64(data=7))
    ok, msg = wait_for_message(Int64, node, "n", time_to_wait=5.0)
    assert (ok, msg.data, now(session)) == (True, 7, 2.0)
    assert wait_for_message(Int64, node, "n", time_to_wait=1.0) == (False, None)
    assert now(session) == 3.0


def test_an_exception_in_a_callback_leaves_spin_once(session):
    node = rclpy.create_node("raises")
    node.create_timer(0.1, lambda: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        rclpy.spin_once(node)


def test_shutdown_from_another_thread_ends_spin(session):
    node = rclpy.create_node("stopped")
    stopper = threading.Thread(target=lambda: (session.sleep(5.0), rclpy.shutdown()))
    stopper.start()
    rclpy.spin(node)  # returns, as rclpy's does when rclpy.shutdown() is called
    stopper.join()
    assert now(session) == 5.0
    assert not rclpy.ok()


def test_an_interrupt_makes_spin_raise_as_a_signal_does(session):
    node = rclpy.create_node("interrupted")
    context = rclpy.get_default_context()
    stopper = threading.Thread(target=lambda: (session.sleep(2.0), context.interrupt()))
    stopper.start()
    with pytest.raises(ExternalShutdownException):
        rclpy.spin(node)
    stopper.join()
    assert now(session) == 2.0


def test_virtual_time_stands_still_while_the_script_thread_is_busy(session):
    node = rclpy.create_node("busy")
    ticks: list[float] = []
    spawn_native(session, Numbers)  # a graph node beside it, with its parameter services
    node.create_timer(0.01, lambda: ticks.append(now(session)))
    start = now(session)
    deadline = time.monotonic() + 0.05
    while time.monotonic() < deadline:  # real work, 50 ms of it
        pass
    assert now(session) == start
    rclpy.spin_once(node)
    assert ticks == [pytest.approx(start + 0.01)]


@pytest.mark.slow
def test_a_thread_the_script_starts_holds_virtual_time_from_start_until_it_first_waits(session):
    # However late the OS gets to run it: this one works 0.4 s of real time before its first wait.
    start = now(session)
    seen: list[float] = []

    def late() -> None:
        deadline = time.monotonic() + 0.4
        while time.monotonic() < deadline:
            pass
        seen.append(now(session))
        time.sleep(0.5)  # through the runtime, as the script's own sleeps are
        seen.append(now(session))

    thread = threading.Thread(target=late)
    thread.start()
    time.sleep(1.0)
    while len(seen) < 2:  # waiting through the runtime (a join would hold the clock)
        time.sleep(0.5)
    thread.join()
    assert seen == [start, start + 0.5]
    assert now(session) == start + 1.0


def _rescue_after(seconds: float, release: Any) -> tuple[threading.Timer, list[bool]]:
    # If virtual time were held by the thread under test, the test would wait forever: release it
    # after a while of real time so that the test fails instead; the list says whether it did.
    rescued: list[bool] = []
    timer = threading.Timer(seconds, lambda: (rescued.append(True), release()))
    timer._actors_end = None  # type: ignore[attr-defined]  # not one of the script's threads: real time
    timer.start()
    return timer, rescued


def test_threads_parked_outside_rclpy_do_not_hold_virtual_time(session):
    from concurrent.futures import ThreadPoolExecutor

    gate = threading.Event()
    parked = threading.Thread(target=gate.wait)  # in a wait of threading's from the start
    parked.start()
    pool = ThreadPoolExecutor(max_workers=1)
    assert pool.submit(lambda: 42).result() == 42  # its worker idles in the pool's queue from now
    rescue, rescued = _rescue_after(20.0, gate.set)
    start = now(session)
    time.sleep(2.0)
    gate.set()
    rescue.cancel()
    parked.join()
    pool.shutdown()
    assert not rescued, "virtual time stood still while the script's other threads were parked"
    assert now(session) == start + 2.0


def _catch_warnings() -> tuple[list[str], threading.Event, Any]:
    import logging

    warnings: list[str] = []
    warned = threading.Event()

    class Catch(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            warnings.append(record.getMessage())
            warned.set()

    return warnings, warned, Catch(logging.WARNING)


def test_a_thread_holding_virtual_time_for_long_is_named_in_a_warning(session, monkeypatch):
    import logging

    import actors.compat.turns

    monkeypatch.setattr(actors.compat.turns, "HOLD_WARNING", 0.05)
    warnings, warned, catch = _catch_warnings()
    logging.getLogger("actors").addHandler(catch)

    def crunch() -> None:  # never waits: it works until the warning names it (10 s at most)
        deadline = time.monotonic() + 10.0
        while not warned.is_set() and time.monotonic() < deadline:
            pass

    try:
        thread = threading.Thread(target=crunch, name="cruncher")
        thread.start()
        start = now(session)
        time.sleep(1.0)
        thread.join()
    finally:
        logging.getLogger("actors").removeHandler(catch)
    assert len(warnings) == 1 and warnings[0].startswith("virtual time waits for thread 'cruncher'")
    assert "started in crunch at " in warnings[0] and __file__ in warnings[0]
    assert now(session) == start + 1.0


class Busy(NativeNode):
    """A native node whose 1 kHz timer takes real time: the loop has work while the script waits."""

    def __init__(self) -> None:
        super().__init__("busy")
        self.create_timer(0.001, lambda: time.perf_counter_ns() and sum(range(2000)))


def test_the_main_thread_running_the_loop_in_its_waits_is_not_named_in_a_warning(monkeypatch):
    # The main thread's waits run the loop's iterations themselves (VirtualTurn._drive): the loop's
    # own thread sees no hand-over for a long time, yet nobody holds virtual time still.  A session
    # of its own: the loop's thread first waits with the warning's bound patched.
    import logging

    import actors.compat.turns

    monkeypatch.setattr(actors.compat.turns, "HOLD_WARNING", 0.05)
    warnings, _warned, catch = _catch_warnings()
    logging.getLogger("actors").addHandler(catch)
    session = Session(clock="virtual").start()
    try:
        spawn_native(session, Busy)
        start, real = now(session), time.perf_counter()
        while time.perf_counter() - real < 0.5:  # real time, many times the warning's bound
            session.sleep(0.01)  # a wait, in which this thread runs the loop
            busy = time.perf_counter() + 0.002  # then it works between two waits, far below the bound
            while time.perf_counter() < busy:
                pass
        assert now(session) > start
        assert session.turn._drives > 10  # type: ignore[attr-defined]  # it did run the loop
    finally:
        session.close()
        logging.getLogger("actors").removeHandler(catch)
    assert warnings == []


def test_a_thread_blocked_in_a_c_call_holds_virtual_time_until_it_returns(session, monkeypatch):
    # input(), a socket, a bare lock: the clock waits for it (that keeps runs repeatable), and a
    # warning names it with the line where it last left the runtime.
    import logging

    import actors.compat.turns

    monkeypatch.setattr(actors.compat.turns, "HOLD_WARNING", 0.05)
    warnings, warned, catch = _catch_warnings()
    logging.getLogger("actors").addHandler(catch)
    lock = threading.Lock()
    lock.acquire()
    releaser = threading.Thread(target=lambda: (warned.wait(10.0), lock.release()))
    releaser._actors_end = None  # type: ignore[attr-defined]  # not one of the script's threads
    releaser.start()

    def blocked() -> None:
        time.sleep(0.5)  # virtual: a wait, after which it blocks outside the runtime
        lock.acquire()

    try:
        thread = threading.Thread(target=blocked, name="blocked", daemon=True)
        thread.start()
        start = now(session)
        time.sleep(1.0)
    finally:
        logging.getLogger("actors").removeHandler(catch)
    assert len(warnings) == 1 and warnings[0].startswith("virtual time waits for thread 'blocked'")
    assert "left the runtime in blocked at " in warnings[0]
    assert now(session) == start + 1.0


def test_waits_return_and_calls_raise_once_the_runtime_has_ended():
    session = Session(clock="virtual").start()
    outcome: list[Any] = []
    forever = threading.Thread(target=lambda: outcome.append(session.wait_until(lambda: False, None)), daemon=True)
    forever.start()  # no script thread: it queues for the turn when it first touches the runtime
    session.sleep(1.0)  # its wait begins meanwhile
    session.close()
    forever.join(timeout=10.0)
    assert outcome == [False]
    with pytest.raises(RuntimeError, match="has stopped"):
        session.call(lambda: "ran")


def test_parameter_requests_wait_for_the_spin(session):
    from actors.ros.parameter_store import Parameter
    from interfaces.rcl_interfaces.srv import SetParameters

    node = rclpy.create_node("tunable")
    node.declare_parameter("speed", 1.0)
    asker = spawn_native(session, Numbers)
    client = session.call(asker.create_client, SetParameters, "/tunable/set_parameters")
    request = SetParameters.Request(parameters=[Parameter("speed", value=2.0).to_parameter_msg()])
    answer = session.call(client.call_async, request)
    session.sleep(1.0)
    assert not answer.done()  # nobody spins the script's node: rclpy would not answer either
    assert node.get_parameter("speed").value == 1.0
    rclpy.spin_once(node, timeout_sec=0)
    assert answer.done() and answer.result().results[0].successful
    assert node.get_parameter("speed").value == 2.0


def test_a_raw_subscription_gets_the_cdr_bytes_rmw_fastrtps_delivers(session):
    from actors.messages import cdr

    node = rclpy.create_node("raw")
    got: list[bytes] = []
    node.create_subscription(String, "chatter", got.append, 10, raw=True)
    node.create_publisher(String, "chatter", 10).publish(String(data="Hello World: 0"))
    rclpy.spin_once(node, timeout_sec=0)
    # What rclpy's listener_serialized prints for this message (CDR header, length, text, padding to 4).
    assert got == [b"\x00\x01\x00\x00\x0f\x00\x00\x00Hello World: 0\x00\x00"]
    assert cdr.decode(got[0], String).data == "Hello World: 0"


def test_a_two_argument_callback_gets_message_info(session):
    node = rclpy.create_node("informed")
    got: list[Any] = []
    node.create_subscription(String, "t", lambda msg, info: got.append((msg.data, info)), 10)
    session.sleep(1.5)
    node.create_publisher(String, "t", 10).publish(String(data="x"))
    rclpy.spin_once(node, timeout_sec=0)
    ((data, info),) = got
    assert data == "x" and info["received_timestamp"] == 1_500_000_000 and info["reception_sequence_number"] == 1


def test_a_timer_callback_taking_timer_info(session):
    from actors.compat.rclpy.timer import TimerInfo

    node = rclpy.create_node("informed_timer")
    got: list[TimerInfo] = []

    def tick(info: TimerInfo) -> None:
        got.append(info)

    node.create_timer(0.5, tick)
    session.sleep(0.7)  # due at 0.5, taken at 0.7
    rclpy.spin_once(node, timeout_sec=0)
    assert got[0].expected_call_time.nanoseconds == 500_000_000
    assert got[0].actual_call_time.nanoseconds == 700_000_000  # when the spin called it, as rclpy's


def test_what_differs_node_names_are_unique(session):
    from actors.errors import InvalidNameError

    rclpy.create_node("only_one")
    with pytest.raises(InvalidNameError, match="already runs"):
        rclpy.create_node("only_one")


def test_the_graph_view_shows_a_scripts_nodes(session):
    node = rclpy.create_node("seen", namespace="/robot")
    node.create_publisher(String, "out", 10)
    infos = {info.name: info for info in session.call(session.runtime.graph.nodes)}
    seen = infos["/robot/seen"]
    assert seen.cls == "actors.compat.rclpy.node:Node" and seen.state == "running"
    assert seen.publishes == ("/robot/out",) and seen.restart == "temporary"


def test_matched_events_follow_a_script_creating_and_destroying_endpoints(session):
    from actors.compat.rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks

    watcher = rclpy.create_node("watcher")
    seen: list[tuple[str, int, int]] = []
    watcher.create_publisher(
        String,
        "out",
        10,
        event_callbacks=PublisherEventCallbacks(
            matched=lambda info: seen.append(("subs", info.current_count, info.current_count_change))
        ),
    )
    watcher.create_subscription(
        String,
        "in",
        lambda msg: None,
        10,
        event_callbacks=SubscriptionEventCallbacks(
            matched=lambda info: seen.append(("pubs", info.current_count, info.current_count_change))
        ),
    )
    other = rclpy.create_node("other")
    executor = SingleThreadedExecutor()
    executor.add_node(watcher)
    executor.add_node(other)
    sub = other.create_subscription(String, "out", lambda msg: None, 10)
    pubs = [other.create_publisher(String, "in", 10) for _ in range(2)]
    assert seen == []  # event callbacks run when the node is spun, as rclpy's
    executor.spin_once(timeout_sec=0)
    executor.spin_once(timeout_sec=0)
    assert other.destroy_subscription(sub) and other.destroy_publisher(pubs[0])
    assert not other.destroy_publisher(pubs[0])  # already gone
    executor.spin_once(timeout_sec=0)
    executor.spin_once(timeout_sec=0)
    # Changes not yet taken add up into one event, as in rclpy (the status counts since it was last read).
    assert sorted(seen) == [("pubs", 1, -1), ("pubs", 2, 2), ("subs", 0, -1), ("subs", 1, 1)]


def test_the_global_executor_is_the_one_rclpy_spin_uses_until_shutdown(session):
    executor = rclpy.get_global_executor()
    assert isinstance(executor, SingleThreadedExecutor) and rclpy.get_global_executor() is executor
    node = rclpy.create_node("globally_spun")
    heard: list[str] = []
    node.create_subscription(String, "g", lambda msg: heard.append(msg.data), 10)
    node.create_publisher(String, "g", 10).publish(String(data="one"))
    rclpy.spin_once(node, timeout_sec=0)  # spun by the global executor, which lets go of the node after
    assert heard == ["one"] and executor.get_nodes() == []
    executor.add_node(node)
    node.create_publisher(String, "g", 10).publish(String(data="two"))
    executor.spin_once(timeout_sec=0)
    assert heard == ["one", "two"]
    rclpy.shutdown()
    rclpy.init(args=[])
    assert rclpy.get_global_executor() is not executor  # a new context, a new executor


def test_a_script_nodes_logger_service(session):
    from actors.compat.rclpy.impl.logging_severity import LoggingSeverity
    from interfaces.rcl_interfaces.msg import LoggerLevel
    from interfaces.rcl_interfaces.srv import SetLoggerLevels

    served = rclpy.create_node("levels_served", enable_logger_service=True)
    asker = rclpy.create_node("levels_asker")
    client = asker.create_client(SetLoggerLevels, "/levels_served/set_logger_levels")
    executor = SingleThreadedExecutor()
    executor.add_node(served)
    executor.add_node(asker)
    try:
        future = client.call_async(
            SetLoggerLevels.Request(levels=[LoggerLevel(name="levels_served", level=int(LoggingSeverity.ERROR))])
        )
        executor.spin_until_future_complete(future, timeout_sec=1.0)  # the service answers while spun
        assert future.result().results[0].successful
        assert served.get_logger().get_effective_level() == LoggingSeverity.ERROR
        assert not served.get_logger().info("hidden")  # below the level set remotely: not logged
    finally:
        served.get_logger().set_level(LoggingSeverity.UNSET)


def test_publishing_with_a_destroyed_publisher_raises_as_rclpy_does(session):
    # rclpy.shutdown() destroys every node of the context, and with them their publishers.
    from actors.compat.rclpy.exceptions import InvalidHandle

    node = rclpy.create_node("late")
    kept, dropped = node.create_publisher(String, "late", 10), node.create_publisher(String, "later", 10)
    kept.publish(String(data="fine"))
    dropped.destroy()
    with pytest.raises(InvalidHandle, match="destruction was requested"):
        dropped.publish(String(data="x"))
    node.destroy_node()
    with pytest.raises(InvalidHandle, match="destruction was requested"):
        kept.publish(String(data="x"))
