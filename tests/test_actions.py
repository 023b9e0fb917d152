"""Actions on the virtual clock: goals, feedback, results, cancel rules, status, timeouts, crashes."""

from __future__ import annotations

import logging
from array import array

import anyio
import anyio.lowlevel
import pytest

from actors import Node, Runtime
from actors.errors import ActionError, ServiceError
from actors.ros.actions import ActionCall, CancelResponse, GoalResponse, ServerGoalHandle, status_name, wire_names
from interfaces.action_msgs.msg import GoalStatus, GoalStatusArray
from interfaces.builtin_interfaces.msg import Time
from interfaces.example_interfaces.action import Fibonacci
from interfaces.std_msgs.msg import Empty
from interfaces.unique_identifier_msgs.msg import UUID

pytestmark = pytest.mark.virtual_time

SUCCEEDED, CANCELED, ABORTED = GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED


class FibonacciServer(Node):
    """One Fibonacci number a second; rejects orders above 20; aborts order 13; crashes on /crash."""

    instances = 0

    def __init__(self) -> None:
        super().__init__("fibonacci_server")
        FibonacciServer.instances += 1
        self.executed: list[int] = []
        self.server = self.create_action_server(
            Fibonacci, "fibonacci", self.execute, goal=self.decide, cancel=self.on_cancel, result_timeout=5.0
        )
        self.create_subscription(Empty, "/crash", self.crash, 10)

    def decide(self, goal: Fibonacci.Goal) -> GoalResponse:
        return GoalResponse.REJECT if goal.order > 20 else GoalResponse.ACCEPT

    def on_cancel(self, goal_handle: ServerGoalHandle) -> CancelResponse:
        return CancelResponse.REJECT if goal_handle.request.order == 7 else CancelResponse.ACCEPT

    async def execute(self, goal_handle: ServerGoalHandle) -> Fibonacci.Result:
        self.executed.append(goal_handle.request.order)
        sequence = [0, 1]
        for i in range(1, goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                return Fibonacci.Result(sequence=sequence)
            sequence.append(sequence[i] + sequence[i - 1])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=list(sequence)))
            await anyio.sleep(1.0)
        if goal_handle.request.order == 13:
            goal_handle.abort()
        else:
            goal_handle.succeed()
        return Fibonacci.Result(sequence=sequence)

    def crash(self, msg: Empty) -> None:
        raise RuntimeError("crash on purpose")


class FibonacciClient(Node):
    def __init__(self) -> None:
        super().__init__("fibonacci_client")
        self.client = self.create_action_client(Fibonacci, "fibonacci")
        self.feedback: list[list[int]] = []
        self.statuses: list[list[int]] = []
        self.crash = self.create_publisher(Empty, "/crash", 10)
        self.create_subscription(GoalStatusArray, "fibonacci/_action/status", self.on_status, 10)

    def on_feedback(self, feedback: Fibonacci.Feedback) -> None:
        self.feedback.append(list(feedback.sequence))

    def on_status(self, msg: GoalStatusArray) -> None:
        self.statuses.append([s.status for s in msg.status_list])


async def start(rt: Runtime) -> tuple[FibonacciServer, FibonacciClient]:
    server = rt.spawn(FibonacciServer)
    client = rt.spawn(FibonacciClient)
    assert await client.client.wait_for_server(timeout=1.0)
    return server, client


async def test_feedback_arrives_in_order_then_the_result():
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=5), feedback=node.on_feedback)
        assert handle.accepted and handle.stamp.sec == 0 and len(bytes(handle.goal_id.uuid)) == 16
        start_time = rt.clock.monotonic()
        response = await handle.get_result()
        assert rt.clock.monotonic() - start_time == pytest.approx(4.0)
        assert (response.status, response.result.sequence) == (SUCCEEDED, array("i", [0, 1, 1, 2, 3, 5]))
        await anyio.lowlevel.checkpoint()
        assert node.feedback == [[0, 1, 1], [0, 1, 1, 2], [0, 1, 1, 2, 3], [0, 1, 1, 2, 3, 5]]
        assert handle.status == SUCCEEDED and handle.done


async def test_a_callback_can_follow_feedback_live_while_it_awaits_the_goal():
    class Follower(Node):
        def __init__(self) -> None:
            super().__init__("follower")
            self.client = self.create_action_client(Fibonacci, "fibonacci")
            self.seen: list[tuple[float, list[int]]] = []
            self.response = None

        async def on_start(self) -> None:
            await self.client.wait_for_server()
            handle = await self.client.send_goal(Fibonacci.Goal(order=4))
            async for feedback in handle.feedback():
                self.seen.append((self.get_clock().monotonic(), list(feedback.sequence)))
            self.response = await handle.get_result()

    async with Runtime() as rt:
        rt.spawn(FibonacciServer)
        node = rt.spawn(Follower)
        await anyio.sleep(5.0)
        # Each message when it was published (one a second), not all at the end.
        assert node.seen == [(0.0, [0, 1, 1]), (1.0, [0, 1, 1, 2]), (2.0, [0, 1, 1, 2, 3])]
        assert node.response.status == SUCCEEDED and node.response.result.sequence == array("i", [0, 1, 1, 2, 3])


async def test_a_feedback_callback_that_raises_crashes_the_client_node(caplog):
    caplog.set_level(logging.ERROR, logger="actors")
    async with Runtime() as rt:
        _, node = await start(rt)

        def broken(feedback: Fibonacci.Feedback) -> None:
            raise ValueError("bad feedback")

        handle = await node.client.send_goal(Fibonacci.Goal(order=3), feedback=broken)
        await anyio.sleep(0.5)
        assert rt.graph.nodes()[1].crashes == 1
        assert (await handle.get_result()).status == SUCCEEDED  # the server did not notice
    assert any("feedback callback of /fibonacci raised ValueError" in r.getMessage() for r in caplog.records)


async def test_the_status_topic_follows_the_goal_through_its_states():
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=2))
        await handle.get_result()
        await anyio.sleep(0.1)
        assert node.statuses == [[GoalStatus.STATUS_ACCEPTED], [GoalStatus.STATUS_EXECUTING], [SUCCEEDED]]
        await anyio.sleep(5.0)  # the result timeout: the goal is forgotten
        assert node.statuses[-1] == []


async def test_an_aborted_goal_reports_aborted_with_its_result():
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=13))
        response = await handle.get_result()
        assert response.status == ABORTED and response.result.sequence[-1] == 233
        assert status_name(response.status) == "ABORTED"


async def test_cancel_an_executing_goal():
    async with Runtime() as rt:
        _server, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=10), feedback=node.on_feedback)
        await anyio.sleep(2.5)
        assert handle.status == GoalStatus.STATUS_EXECUTING
        cancel = await handle.cancel()
        assert cancel.return_code == cancel.ERROR_NONE
        assert [bytes(g.goal_id.uuid) for g in cancel.goals_canceling] == [bytes(handle.goal_id.uuid)]
        response = await handle.get_result()
        assert response.status == CANCELED and response.result.sequence == array("i", [0, 1, 1, 2, 3])
        assert rt.clock.monotonic() == pytest.approx(3.0)  # stopped at its next check, not at the end
        again = await handle.cancel()
        assert (again.return_code, again.goals_canceling) == (again.ERROR_GOAL_TERMINATED, [])


async def test_a_refused_cancel_lets_the_goal_finish():
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=7))
        cancel = await handle.cancel()
        assert (cancel.return_code, cancel.goals_canceling) == (cancel.ERROR_REJECTED, [])
        assert (await handle.get_result()).status == SUCCEEDED


async def test_a_rejected_goal_has_no_result():
    async with Runtime() as rt:
        server, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=21))
        assert not handle.accepted
        with pytest.raises(ActionError, match="was rejected"):
            await handle.get_result()
        with pytest.raises(ActionError, match="nothing to cancel"):
            await handle.cancel()
        assert server.executed == [] and server.server.goals == {}


async def test_two_concurrent_goals_run_side_by_side():
    async with Runtime() as rt:
        server, node = await start(rt)
        first = await node.client.send_goal(Fibonacci.Goal(order=4))
        second = await node.client.send_goal(Fibonacci.Goal(order=3))
        assert bytes(first.goal_id.uuid) != bytes(second.goal_id.uuid)
        second_result = await second.get_result()
        assert rt.clock.monotonic() == pytest.approx(2.0)
        first_result = await first.get_result()
        assert rt.clock.monotonic() == pytest.approx(3.0)  # not 5: they overlapped
        assert first_result.result.sequence == array("i", [0, 1, 1, 2, 3])
        assert second_result.result.sequence == array("i", [0, 1, 1, 2])
        assert server.executed == [4, 3]


async def test_a_goal_can_carry_an_id_its_client_chose():
    async with Runtime() as rt:
        server, node = await start(rt)
        chosen = UUID(uuid=bytes(range(16)))
        handle = await node.client.send_goal(Fibonacci.Goal(order=3), goal_id=chosen)
        assert handle.accepted and bytes(handle.goal_id.uuid) == bytes(range(16))
        assert list(server.server.goals) == [bytes(range(16))]
        with pytest.raises(ActionError, match="was sent already"):
            await node.client.send_goal(Fibonacci.Goal(order=3), goal_id=chosen)
        assert (await handle.get_result()).status == SUCCEEDED
        # The server still holds the ended goal (its result timeout): the same id again is rejected there.
        again = await node.client.send_goal(Fibonacci.Goal(order=3), goal_id=chosen)
        assert not again.accepted


async def test_accepted_and_feedback_callbacks_reach_the_actor_as_action_calls():
    accepted: list[ServerGoalHandle] = []

    class Scheduled(list):
        def schedule(self, entity):
            self.append(entity)
            entity._run()

    async with Runtime() as rt:
        server, node = await start(rt)
        actors = server._core.actor, node._core.actor
        server._core.actor, node._core.actor = server_calls, client_calls = Scheduled(), Scheduled()
        server.server.accepted_callback = lambda handle: (accepted.append(handle), handle.execute())
        try:
            handle = await node.client.send_goal(Fibonacci.Goal(order=2), feedback=node.on_feedback)
            await handle.get_result()
        finally:
            server._core.actor, node._core.actor = actors
        assert [type(c) for c in server_calls] == [ActionCall] and len(accepted) == 1
        assert [type(c) for c in client_calls] == [ActionCall] and node.feedback == [[0, 1, 1]]


async def test_cancel_by_stamp_and_cancel_all():
    async with Runtime() as rt:
        _, node = await start(rt)
        early = await node.client.send_goal(Fibonacci.Goal(order=10))
        await anyio.sleep(1.5)
        late = await node.client.send_goal(Fibonacci.Goal(order=10))
        # Accepted at or before 1 s: only the early goal.
        cancel = await node.client.cancel_goals(stamp=Time(sec=1))
        assert [bytes(g.goal_id.uuid) for g in cancel.goals_canceling] == [bytes(early.goal_id.uuid)]
        assert (await early.get_result()).status == CANCELED
        third = await node.client.send_goal(Fibonacci.Goal(order=10))
        everything = await node.client.cancel_goals()
        assert {bytes(g.goal_id.uuid) for g in everything.goals_canceling} == {
            bytes(late.goal_id.uuid),
            bytes(third.goal_id.uuid),
        }
        assert [(await h.get_result()).status for h in (late, third)] == [CANCELED, CANCELED]


async def test_cancel_an_unknown_goal():
    async with Runtime() as rt:
        _, node = await start(rt)
        unknown = Fibonacci.Impl.FeedbackMessage().goal_id
        unknown.uuid = bytes(range(1, 17))
        cancel = await node.client.cancel_goals(goal_id=unknown)
        assert (cancel.return_code, cancel.goals_canceling) == (cancel.ERROR_UNKNOWN_GOAL_ID, [])


async def test_a_result_is_kept_for_the_result_timeout_then_forgotten(caplog):
    caplog.set_level(logging.WARNING, logger="actors")
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=1))
        assert (await handle.get_result()).status == SUCCEEDED
        ended = rt.clock.monotonic()
        ask = Fibonacci.Impl.GetResultService.Request(goal_id=handle.goal_id)
        await anyio.sleep(4.9)
        kept = await node.client._results.call(ask)
        assert (kept.status, kept.result.sequence) == (SUCCEEDED, array("i", [0, 1]))
        await anyio.sleep(ended + 5.0 - rt.clock.monotonic())
        gone = await node.client._results.call(ask)
        assert (gone.status, gone.result.sequence) == (GoalStatus.STATUS_UNKNOWN, array("i"))
    assert any("unknown or expired goal" in r.getMessage() for r in caplog.records)


async def test_a_server_crash_aborts_its_goals_and_the_supervisor_restarts_it(caplog):
    caplog.set_level(logging.WARNING, logger="actors")
    FibonacciServer.instances = 0
    async with Runtime() as rt:
        _, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=10), feedback=node.on_feedback)
        await anyio.sleep(2.5)
        node.crash.publish(Empty())
        response = await handle.get_result(timeout=1.0)
        assert (response.status, response.result.sequence) == (ABORTED, array("i"))
        assert handle.status == ABORTED
        received = len(node.feedback)
        await anyio.sleep(1.0)
        assert len(node.feedback) == received  # the goal's task was stopped with it
        assert FibonacciServer.instances == 2 and rt.graph.nodes()[0].restarts == 1
        again = await node.client.send_goal(Fibonacci.Goal(order=2))
        assert (await again.get_result()).status == SUCCEEDED
    assert any("aborted 1 goal(s)" in r.getMessage() and "stopped" in r.getMessage() for r in caplog.records)


async def test_execute_that_raises_aborts_the_goal_and_the_server_keeps_serving(caplog):
    caplog.set_level(logging.ERROR, logger="actors")

    class Broken(Node):
        def __init__(self) -> None:
            super().__init__("broken")
            self.create_action_server(Fibonacci, "fibonacci", self.execute)

        async def execute(self, goal_handle: ServerGoalHandle) -> Fibonacci.Result:
            if goal_handle.request.order < 0:
                raise ValueError("negative order")
            goal_handle.succeed()
            return Fibonacci.Result(sequence=[goal_handle.request.order])

    async with Runtime() as rt:
        rt.spawn(Broken)
        node = rt.spawn(FibonacciClient)
        bad = await node.client.send_goal(Fibonacci.Goal(order=-1))
        assert (await bad.get_result()).status == ABORTED
        good = await node.client.send_goal(Fibonacci.Goal(order=3))
        assert (await good.get_result()).result.sequence == array("i", [3])
        assert rt.graph.nodes()[0].crashes == 0
    assert any("execute callback raised ValueError('negative order')" in r.getMessage() for r in caplog.records)


async def test_execute_that_ends_without_a_terminal_state_aborts(caplog):
    caplog.set_level(logging.WARNING, logger="actors")

    class Forgetful(Node):
        def __init__(self) -> None:
            super().__init__("forgetful")
            self.create_action_server(Fibonacci, "fibonacci", lambda goal_handle: Fibonacci.Result(sequence=[1]))

    async with Runtime() as rt:
        rt.spawn(Forgetful)
        node = rt.spawn(FibonacciClient)
        response = await (await node.client.send_goal(Fibonacci.Goal())).get_result()
        assert (response.status, response.result.sequence) == (ABORTED, array("i", [1]))
    assert any("ended without succeed()" in r.getMessage() for r in caplog.records)


async def test_deferred_goals_start_when_the_server_says():
    class Deferring(Node):
        def __init__(self) -> None:
            super().__init__("deferring")
            self.waiting: list[ServerGoalHandle] = []
            self.create_action_server(Fibonacci, "fibonacci", self.execute, accepted=self.waiting.append)
            self.create_timer(3.0, self.start_one)

        def start_one(self) -> None:
            if self.waiting:
                self.waiting.pop(0).execute()

        def execute(self, goal_handle: ServerGoalHandle) -> Fibonacci.Result:
            goal_handle.succeed()
            return Fibonacci.Result(sequence=[goal_handle.request.order])

    async with Runtime() as rt:
        server = rt.spawn(Deferring)
        node = rt.spawn(FibonacciClient)
        handle = await node.client.send_goal(Fibonacci.Goal(order=4))
        await anyio.sleep(1.0)
        assert handle.status == GoalStatus.STATUS_ACCEPTED and len(server.waiting) == 1
        assert (await handle.get_result()).result.sequence == array("i", [4])
        assert rt.clock.monotonic() == pytest.approx(3.0)
        with pytest.raises(ActionError, match="cannot execute"):
            ServerGoalHandle.execute(handle_of(server))


def handle_of(node: Node) -> ServerGoalHandle:
    (server,) = node._core.action_servers
    (goal,) = server.goals.values()
    return goal


async def test_invalid_transitions_are_refused():
    async with Runtime() as rt:
        server, node = await start(rt)
        await node.client.send_goal(Fibonacci.Goal(order=3))
        await anyio.sleep(0.5)
        goal = handle_of(server)
        with pytest.raises(ActionError, match="cannot canceled from EXECUTING"):
            goal.canceled()
        with pytest.raises(TypeError, match="feedback of /fibonacci is example_interfaces/action/Fibonacci_Feedback"):
            goal.publish_feedback(Fibonacci.Result())


async def test_a_goal_sent_before_its_server_starts_waits_for_it():
    async with Runtime() as rt:
        node = rt.spawn(FibonacciClient)
        assert not node.client.server_is_ready()
        assert await node.client.wait_for_server(timeout=0.5) is False

        async def later() -> None:
            await anyio.sleep(2.0)
            rt.spawn(FibonacciServer)

        async with anyio.create_task_group() as tg:
            tg.start_soon(later)
            handle = await node.client.send_goal(Fibonacci.Goal(order=2))
        assert handle.accepted and (await handle.get_result()).status == SUCCEEDED


async def test_destroying_the_server_answers_waiting_clients():
    async with Runtime() as rt:
        server, node = await start(rt)
        handle = await node.client.send_goal(Fibonacci.Goal(order=10))
        await anyio.sleep(1.0)
        server.server.destroy()
        assert (await handle.get_result(timeout=1.0)).status == ABORTED
        assert not node.client.server_is_ready()
        names = wire_names("/fibonacci")
        assert names["send_goal"] not in {s.name for s in rt.graph.services()}
        with pytest.raises(TimeoutError):
            await node.client.send_goal(Fibonacci.Goal(order=1), timeout=0.5)


async def test_the_action_is_made_of_rosnamed_services_and_topics():
    async with Runtime() as rt:
        await start(rt)
        services = {s.name: s.type for s in rt.graph.services()}
        assert services["/fibonacci/_action/send_goal"] == "example_interfaces/action/Fibonacci_SendGoal"
        assert services["/fibonacci/_action/cancel_goal"] == "action_msgs/srv/CancelGoal"
        assert services["/fibonacci/_action/get_result"] == "example_interfaces/action/Fibonacci_GetResult"
        topics = {t.name: t for t in rt.graph.topics()}
        feedback, status = topics["/fibonacci/_action/feedback"], topics["/fibonacci/_action/status"]
        assert feedback.type == "example_interfaces/action/Fibonacci_FeedbackMessage"
        assert status.type == "action_msgs/msg/GoalStatusArray"
        assert status.publishers[0].qos.durability.name == "TRANSIENT_LOCAL"
        assert {e.node for e in feedback.subscriptions} == {"/fibonacci_client"}


async def test_wrong_types_are_refused_early():
    async with Runtime() as rt:
        _, node = await start(rt)
        with pytest.raises(TypeError, match="goal of /fibonacci is example_interfaces/action/Fibonacci_Goal"):
            await node.client.send_goal(Fibonacci.Result())
        with pytest.raises(TypeError, match="needs an action type"):
            node.create_action_client(Fibonacci.Goal, "other")


async def test_a_node_cannot_send_goals_to_its_own_server():
    class Selfish(Node):
        def __init__(self) -> None:
            super().__init__("selfish")
            self.create_action_server(Fibonacci, "fibonacci", lambda handle: Fibonacci.Result())
            self.client = self.create_action_client(Fibonacci, "fibonacci")

    async with Runtime() as rt:
        node = rt.spawn(Selfish)
        with pytest.raises(ServiceError, match="calls its own service"):
            await node.client.send_goal(Fibonacci.Goal())


async def test_the_graph_lists_actions_read_off_their_topics():
    from actors.system.introspection import action_of

    assert action_of("/a/_action/send_goal", "p/action/Move_SendGoal") == ("/a", "p/action/Move")
    assert action_of("/a/_action/feedback", "p/action/Move_FeedbackMessage") == ("/a", "p/action/Move")
    assert action_of("/a/_action/status", "action_msgs/msg/GoalStatusArray") is None
    assert action_of("/a/feedback", "p/action/Move_FeedbackMessage") is None
    async with Runtime() as rt:
        await start(rt)
        (info,) = rt.graph.actions()
        assert (info.name, info.type) == ("/fibonacci", "example_interfaces/action/Fibonacci")
        assert (info.servers, info.clients) == (("/fibonacci_server",), ("/fibonacci_client",))
