"""rclpy.action on actors: servers and clients of script nodes, with the overlay's executor semantics.

The test's thread is the script (the ``rclpy_session`` fixture: a virtual-clock session with rclpy
initialized); a server spins on an executor in a thread of its own, as a second program would.
"""

from __future__ import annotations

import asyncio
import threading
import time
from array import array
from collections.abc import Callable, Iterator
from typing import Any

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.action import (
    ActionClient,
    ActionServer,
    CancelResponse,
    GoalResponse,
    get_action_client_names_and_types_by_node,
    get_action_names_and_types,
    get_action_server_names_and_types_by_node,
)
from actors.compat.rclpy.action.client import ClientGoalHandle
from actors.compat.rclpy.action.server import RCLError, ServerGoalHandle
from actors.compat.rclpy.callback_groups import ReentrantCallbackGroup
from actors.compat.rclpy.executors import (
    ExternalShutdownException,
    MultiThreadedExecutor,
    SingleThreadedExecutor,
)
from interfaces.action_msgs.msg import GoalStatus
from interfaces.example_interfaces.action import Fibonacci
from interfaces.unique_identifier_msgs.msg import UUID

SUCCEEDED, CANCELED, ABORTED = GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED


def now(session: Any) -> float:
    return session.loop.time()


def count_up(goal: ServerGoalHandle) -> Fibonacci.Result:
    """An execute callback: one number a (virtual) second, as a blocking script writes it."""
    numbers = [0, 1]
    while len(numbers) <= goal.request.order:
        if goal.is_cancel_requested:
            goal.canceled()
            return Fibonacci.Result(sequence=numbers)
        numbers.append(numbers[-1] + numbers[-2])
        goal.publish_feedback(Fibonacci.Feedback(sequence=numbers))
        time.sleep(1.0)
    goal.succeed()
    return Fibonacci.Result(sequence=numbers)


class Serving:
    """A server node spun by an executor on a thread of its own; its callbacks' threads, in order."""

    def __init__(self, session: Any, executor: Any, execute: Callable[..., Any] = count_up, **options: Any) -> None:
        self.node = rclpy.create_node("server")
        self.calls: list[tuple[str, str]] = []
        options.setdefault("goal_callback", self.note("goal", GoalResponse.ACCEPT))
        options.setdefault("cancel_callback", self.note("cancel", CancelResponse.ACCEPT))
        self.server = ActionServer(self.node, Fibonacci, "fibonacci", execute, **options)
        self.executor = executor
        executor.add_node(self.node)
        self.thread = threading.Thread(target=self._spin, name="server spin", daemon=True)
        self.thread.start()

    def note(self, what: str, answer: Any) -> Callable[[Any], Any]:
        def callback(_request: Any) -> Any:
            self.calls.append((what, threading.current_thread().name))
            return answer

        return callback

    def _spin(self) -> None:
        try:
            self.executor.spin()
        except ExternalShutdownException:
            pass


@pytest.fixture
def serving(rclpy_session: Any) -> Iterator[Callable[..., Serving]]:
    made: list[Serving] = []

    def make(executor: Any = None, **options: Any) -> Serving:
        made.append(Serving(rclpy_session, executor or MultiThreadedExecutor(num_threads=4), **options))
        return made[-1]

    yield make
    for each in made:
        each.executor.shutdown(timeout_sec=5.0)


@pytest.fixture
def client(rclpy_session: Any) -> tuple[Any, ActionClient]:
    node = rclpy.create_node("client")
    return node, ActionClient(node, Fibonacci, "fibonacci")


def send(node: Any, action: ActionClient, order: int) -> ClientGoalHandle:
    """Wait for the server, send a goal of ``order`` and spin the client until it is answered."""
    action.wait_for_server()
    sent = action.send_goal_async(Fibonacci.Goal(order=order))
    rclpy.spin_until_future_complete(node, sent)
    return sent.result()


def spun(node: Any, future: Any) -> Any:
    """Spin the client's node until ``future`` is done; its result."""
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def test_a_goal_runs_to_its_result_with_feedback_messages_while_spun(rclpy_session, serving, client):
    server = serving(callback_group=ReentrantCallbackGroup())
    node, action = client
    assert action.wait_for_server(timeout_sec=1.0)
    heard: list[tuple[float, Any]] = []
    sent = action.send_goal_async(
        Fibonacci.Goal(order=4), feedback_callback=lambda m: heard.append((now(rclpy_session), m))
    )
    rclpy_session.sleep(0.5)
    assert not sent.done()  # the answer waits for the client's node to be spun, as in rclpy
    goal = spun(node, sent)
    assert isinstance(goal, ClientGoalHandle) and goal.accepted
    assert goal.status == GoalStatus.STATUS_EXECUTING  # the status topic said so meanwhile
    result = spun(node, goal.get_result_async())
    assert (result.status, result.result.sequence) == (SUCCEEDED, array("i", [0, 1, 1, 2, 3]))
    assert goal.status == SUCCEEDED
    # rclpy's feedback callback gets the whole FeedbackMessage: the goal's id and the feedback.
    assert all(type(m) is Fibonacci.Impl.FeedbackMessage and m.goal_id == goal.goal_id for _, m in heard)
    # Printed as a real rclpy client logs the feedback: array('i', [0, 1, 1]).
    assert [(t, repr(m.feedback.sequence)) for t, m in heard] == [
        (0.5, "array('i', [0, 1, 1])"),
        (pytest.approx(1.0), "array('i', [0, 1, 1, 2])"),
        (pytest.approx(2.0), "array('i', [0, 1, 1, 2, 3])"),
    ]  # what came while nobody spun the client waited for the spin, then one message a second
    assert [what for what, _ in server.calls] == ["goal"]


def test_callbacks_run_on_the_executors_threads_and_goals_run_side_by_side(rclpy_session, serving, client):
    threads: dict[str, str] = {}

    def execute(goal: ServerGoalHandle) -> Fibonacci.Result:
        threads[f"execute {goal.request.order}"] = threading.current_thread().name
        return count_up(goal)

    server = serving(execute=execute, callback_group=ReentrantCallbackGroup())
    node, action = client
    action.wait_for_server()
    futures = [action.send_goal_async(Fibonacci.Goal(order=n)) for n in (4, 2)]
    for future in futures:
        rclpy.spin_until_future_complete(node, future)
    results = [goal.get_result_async() for goal in (f.result() for f in futures)]
    for result in results:
        rclpy.spin_until_future_complete(node, result)
    assert now(rclpy_session) == pytest.approx(3.0)  # not 4: they overlapped on two pool threads
    assert [list(r.result().result.sequence) for r in results] == [[0, 1, 1, 2, 3], [0, 1, 1]]
    assert {name for _, name in server.calls} <= {t.name for t in threading.enumerate()} | {"rclpy executor_0"}
    assert all(name.startswith("rclpy executor") for name in [*threads.values(), *(n for _, n in server.calls)])
    assert threads["execute 4"] != threads["execute 2"]


def test_a_single_threaded_executor_runs_one_blocking_goal_at_a_time(rclpy_session, serving, client):
    serving(executor=SingleThreadedExecutor())
    node, action = client
    action.wait_for_server()
    futures = [action.send_goal_async(Fibonacci.Goal(order=n)) for n in (2, 2)]
    results = []
    for future in futures:
        rclpy.spin_until_future_complete(node, future)
        results.append(future.result().get_result_async())
    for result in results:
        rclpy.spin_until_future_complete(node, result)
    assert now(rclpy_session) == pytest.approx(2.0)  # the execute callbacks' sleeps held the one thread


def test_a_goal_is_rejected_by_the_goal_callback(rclpy_session, serving, client):
    serving(goal_callback=lambda goal: GoalResponse.REJECT if goal.order > 10 else GoalResponse.ACCEPT)
    node, action = client
    goal = send(node, action, 11)
    assert not goal.accepted and goal.status == GoalStatus.STATUS_UNKNOWN
    result = spun(node, goal.get_result_async())  # as a server answers for a goal it does not know
    assert result.status == GoalStatus.STATUS_UNKNOWN


def test_a_goal_callback_that_answers_no_goal_response_rejects_with_a_warning(rclpy_session, serving, client, caplog):
    serving(goal_callback=lambda goal: True)
    node, action = client
    goal = send(node, action, 1)
    assert not goal.accepted
    assert "Goal request callback did not return a GoalResponse type. Rejecting goal." in caplog.text


def test_cancel_an_executing_goal(rclpy_session, serving, client):
    server = serving(callback_group=ReentrantCallbackGroup())
    node, action = client
    goal = send(node, action, 9)
    rclpy_session.sleep(1.5)
    cancel = spun(node, goal.cancel_goal_async())
    assert [info.goal_id for info in cancel.goals_canceling] == [goal.goal_id]
    result = spun(node, goal.get_result_async())
    assert (result.status, result.result.sequence) == (CANCELED, array("i", [0, 1, 1, 2]))
    assert now(rclpy_session) == pytest.approx(2.0)  # the execute callback saw it at its next step
    assert [what for what, _ in server.calls] == ["goal", "cancel"]


def test_the_default_cancel_callback_refuses(rclpy_session, serving, client):
    serving(cancel_callback=None)
    node, action = client
    goal = send(node, action, 2)
    cancel = spun(node, goal.cancel_goal_async())
    assert cancel.goals_canceling == []
    result = spun(node, goal.get_result_async())
    assert result.status == SUCCEEDED


def test_an_execute_callback_that_raises_aborts_the_goal_and_the_server_goes_on(rclpy_session, serving, client, caplog):
    def execute(goal: ServerGoalHandle) -> Fibonacci.Result:
        if goal.request.order == 13:
            raise ValueError("unlucky")
        return count_up(goal)

    serving(execute=execute)
    node, action = client
    outcomes = [spun(node, send(node, action, order).get_result_async()).status for order in (13, 1)]
    assert outcomes == [ABORTED, SUCCEEDED]
    assert "ValueError('unlucky')" in caplog.text


def test_deferred_execution_and_the_goal_handle_states(rclpy_session, serving, client):
    handles: list[ServerGoalHandle] = []
    seen: list[tuple[int, bool, bool]] = []

    def accepted(goal: ServerGoalHandle) -> None:
        handles.append(goal)
        seen.append((goal.status, goal.is_active, goal.is_cancel_requested))

    def execute(goal: ServerGoalHandle) -> Fibonacci.Result:
        seen.append((goal.status, goal.is_active, goal.is_cancel_requested))
        goal.abort()
        return Fibonacci.Result(sequence=[7])

    serving(execute=execute, handle_accepted_callback=accepted)
    node, action = client
    sent = send(node, action, 1)
    rclpy_session.sleep(1.0)
    (goal,) = handles
    assert goal.request.order == 1 and goal.goal_id == sent.goal_id and goal == handles[0]
    goal.execute()  # from the script's thread, when it likes
    result = spun(node, sent.get_result_async())
    assert (result.status, result.result.sequence) == (ABORTED, array("i", [7]))
    assert seen == [(GoalStatus.STATUS_ACCEPTED, True, False), (GoalStatus.STATUS_EXECUTING, True, False)]
    assert (goal.status, goal.is_active) == (ABORTED, False)
    with pytest.raises(RCLError, match="cannot succeed from ABORTED"):
        goal.succeed()
    with pytest.raises(RCLError, match="cannot execute"):
        goal.execute()
    with pytest.raises(TypeError):
        goal.publish_feedback(Fibonacci.Result())


def test_blocking_send_goal_cancel_and_result_while_another_thread_spins(rclpy_session, serving, client):
    serving(callback_group=ReentrantCallbackGroup())
    node, action = client
    action.wait_for_server()
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    spinner = threading.Thread(target=Serving._spin, args=(type("S", (), {"executor": executor})(),), daemon=True)
    spinner.start()
    response = action.send_goal(Fibonacci.Goal(order=2))
    assert (response.status, response.result.sequence) == (SUCCEEDED, array("i", [0, 1, 1]))
    chosen = UUID(uuid=bytes(range(16)))
    sent = action.send_goal_async(Fibonacci.Goal(order=6), goal_uuid=chosen)
    while not sent.done():
        rclpy_session.sleep(0.1)
    goal = sent.result()
    assert bytes(goal.goal_id.uuid) == bytes(range(16))
    assert [g.goal_id for g in goal.cancel_goal().goals_canceling] == [goal.goal_id]
    assert goal.get_result().status == CANCELED
    executor.shutdown()
    with pytest.raises(TypeError, match="Expected goal type"):
        action.send_goal_async(Fibonacci.Feedback())


def test_asyncio_tasks_await_rclpy_futures(rclpy_session, serving, client):
    serving(callback_group=ReentrantCallbackGroup())
    node, action = client
    action.wait_for_server()

    async def one(order: int) -> list[int]:
        goal = await action.send_goal_async(Fibonacci.Goal(order=order))
        return list((await goal.get_result_async()).result.sequence)

    async def main() -> list[list[int]]:
        async def spin() -> None:
            while True:
                rclpy.spin_once(node, timeout_sec=0.1)
                await asyncio.sleep(0)

        spinner = asyncio.ensure_future(spin())
        try:
            return await asyncio.gather(one(2), one(3))
        finally:
            spinner.cancel()

    assert asyncio.run(main()) == [[0, 1, 1], [0, 1, 1, 2]]


def test_wait_for_server_times_out_in_virtual_seconds_and_the_graph_lists_the_action(rclpy_session, serving, client):
    node, action = client
    start = now(rclpy_session)
    assert action.wait_for_server(timeout_sec=2.0) is False and not action.server_is_ready()
    assert now(rclpy_session) - start == pytest.approx(2.0)
    serving()
    assert action.wait_for_server(timeout_sec=2.0) is True and action.server_is_ready()
    assert get_action_names_and_types(node) == [("/fibonacci", ["example_interfaces/action/Fibonacci"])]
    assert get_action_server_names_and_types_by_node(node, "server", "/") == get_action_names_and_types(node)
    assert get_action_client_names_and_types_by_node(node, "client", "/") == get_action_names_and_types(node)
    assert get_action_client_names_and_types_by_node(node, "server", "/") == []


@pytest.mark.slow
def test_wait_for_server_returns_when_the_context_shuts_down(rclpy_session, client):
    _node, action = client
    threading.Timer(0.5, rclpy.get_default_context().interrupt).start()
    assert action.wait_for_server() is False


def test_a_destroyed_server_aborts_its_goals_and_a_destroyed_client_stops(rclpy_session, serving, client):
    server = serving(callback_group=ReentrantCallbackGroup())
    node, action = client
    goal = send(node, action, 9)
    rclpy_session.sleep(1.0)
    server.server.destroy()
    result = spun(node, goal.get_result_async())
    assert result.status == ABORTED
    assert not action.server_is_ready() and server.server not in server.node.waitables
    action.destroy()
    assert action not in node.waitables


def test_a_goal_is_held_until_its_result_expires(rclpy_session, serving, client):
    server = serving(result_timeout=2)
    node, action = client
    assert server.server._goal_handles == {}
    handle = send(node, action, 2)
    spun(node, handle.get_result_async())
    assert len(server.server._goal_handles) == 1  # its result stays asked-for a while
    time.sleep(3)  # virtual time: the result's 2 s pass
    assert server.server._goal_handles == {}
    counts = (server.server.get_num_entities(), action.get_num_entities())
    assert [(n.num_services, n.num_timers, n.num_clients, n.num_subscriptions) for n in counts] == [
        (3, 1, 0, 0),
        (0, 0, 3, 2),
    ]


def _goal_request(first_byte: int) -> Any:
    return Fibonacci.Impl.SendGoalService.Request(goal_id=UUID(uuid=bytes([first_byte, *range(15)])))


def test_a_goal_is_answered_after_its_accepted_callback_has_run(rclpy_session):
    # As rclpy's server, which answers and runs the accepted callback in one step: when the client
    # sees the answer, the accepted callback has run, and an execute callback it started has
    # published its first feedback.  (Server and client share one node and one executor here.)
    node = rclpy.create_node("one_node")
    executor = SingleThreadedExecutor()
    events: list[Any] = []
    send_goal = node.create_client(Fibonacci.Impl.SendGoalService, "/counting/_action/send_goal")
    feedback_topic = "/counting/_action/feedback"
    node.create_subscription(Fibonacci.Impl.FeedbackMessage, feedback_topic, lambda m: events.append("feedback"), 10)

    def accepted(goal: ServerGoalHandle) -> None:
        events.append(("accepted", goal.status))
        if goal.request.order:
            goal.execute()

    def execute(goal: ServerGoalHandle) -> Fibonacci.Result:
        goal.publish_feedback(Fibonacci.Feedback(sequence=[1]))
        goal.succeed()
        return Fibonacci.Result()

    def goal_callback(goal: Any) -> GoalResponse:
        return GoalResponse.REJECT if goal.order < 0 else GoalResponse.ACCEPT

    ActionServer(node, Fibonacci, "counting", execute, goal_callback=goal_callback, handle_accepted_callback=accepted)
    executing = _goal_request(1)
    executing.goal.order = 3
    sent = send_goal.call_async(executing)
    rclpy.spin_until_future_complete(node, sent, executor)
    assert sent.result().accepted
    assert events == [("accepted", GoalStatus.STATUS_ACCEPTED), "feedback"]
    events.clear()
    deferred = send_goal.call_async(_goal_request(2))  # order 0: the accepted callback keeps it waiting
    rclpy.spin_until_future_complete(node, deferred, executor)
    assert deferred.result().accepted and events == [("accepted", GoalStatus.STATUS_ACCEPTED)]
    events.clear()
    refused = _goal_request(3)
    refused.goal.order = -1
    answer = send_goal.call_async(refused)
    rclpy.spin_until_future_complete(node, answer, executor)
    assert not answer.result().accepted and events == []
    executor.shutdown()
