"""``rclpy.action.client``: a script node's action client, on the native one (:mod:`actors.ros.actions`).

Each request (send a goal, get its result, cancel it) runs as a call of the
native client on the runtime's thread; its answer is queued on this waitable
of the node and completes the script's rclpy Future when the node is spun, in
the client's callback group, as in rclpy (a future's done callbacks then run
as tasks of that executor).  Feedback takes the same way: the native client
hands each message of a goal to the overlay's catcher, and the script's
feedback callback gets it, as a whole FeedbackMessage (goal id and feedback),
while the node is spun.

The native client asks for a goal's result as soon as the goal is accepted, so
``get_result_async`` never finds the result expired on the server.
"""

from __future__ import annotations

import asyncio
import uuid
from collections.abc import Callable, Coroutine
from functools import partial
from typing import TYPE_CHECKING, Any

from actors.compat.dispatch import ScriptNode
from actors.compat.rclpy.action.base import ActionWork, GoalHandle
from actors.compat.rclpy.task import Future, await_or_execute
from actors.compat.rclpy.waitable import NumberOfEntities
from actors.compat.turns import Waiter
from actors.ros.actions import ActionClient as NativeClient
from actors.ros.actions import ClientGoalHandle as NativeGoal
from actors.ros.node import Node as NativeNode
from interfaces.action_msgs.msg import GoalStatus
from interfaces.unique_identifier_msgs.msg import UUID

if TYPE_CHECKING:
    from interfaces.builtin_interfaces.msg import Time

__all__ = ["ActionClient", "ClientGoalHandle"]


class ClientGoalHandle(GoalHandle):
    """A goal as its client sees it (what ``send_goal_async``'s Future gives)."""

    def __init__(self, action_client: ActionClient, native: NativeGoal) -> None:
        self._action_client = action_client
        self._native = native

    def __repr__(self) -> str:
        return f"ClientGoalHandle <id={self.goal_id.uuid}, accepted={self.accepted}, status={self.status}>"

    @property
    def stamp(self) -> Time:
        """When the server accepted the goal."""
        return self._native.stamp

    @property
    def accepted(self) -> bool:
        """Whether the server accepted the goal."""
        return bool(self._native.accepted)

    @property
    def status(self) -> int:
        """The goal's latest GoalStatus value (STATUS_UNKNOWN before the first status)."""
        return int(self._native.status)

    def cancel_goal(self) -> Any:
        """Ask to cancel the goal and wait for the CancelGoal response (another thread must spin the node)."""
        return self._action_client._cancel_goal(self)

    def cancel_goal_async(self) -> Future[Any]:
        """Ask to cancel the goal; a Future of the CancelGoal response."""
        return self._action_client._cancel_goal_async(self)

    def get_result(self) -> Any:
        """Wait for the goal's GetResult response (``.status``, ``.result``); another thread must spin the node."""
        return self._action_client._get_result(self)

    def get_result_async(self) -> Future[Any]:
        """A Future of the goal's GetResult response (``.status`` and ``.result``), done when the goal ends."""
        return self._action_client._get_result_async(self)


class ActionClient(ActionWork):
    """A client of ``action_name`` on ``node`` (rclpy's signature; the QoS profiles are accepted and
    not used: an action's services and topics have ROS's default QoS here)."""

    def __init__(
        self,
        node: ScriptNode,
        action_type: type[Any],
        action_name: str,
        *,
        callback_group: Any = None,
        goal_service_qos_profile: Any = None,
        result_service_qos_profile: Any = None,
        cancel_service_qos_profile: Any = None,
        feedback_sub_qos_profile: Any = None,
        status_sub_qos_profile: Any = None,
    ) -> None:
        super().__init__(node, callback_group)
        self._action_type = action_type
        self._action_name = action_name
        self._calls: set[asyncio.Task[Any]] = set()
        # The native client's status subscription and feedback calls run at once on the runtime's thread
        # (ScriptActor.schedule): they only keep the status or call the feedback catcher below.
        self._native: NativeClient = self._session.call(NativeNode.create_action_client, node, action_type, action_name)
        self.callback_group.add_entity(self)
        node.add_waitable(self)

    def get_num_entities(self) -> NumberOfEntities:
        """What an action client is made of: three service clients, the feedback and status subscriptions."""
        return NumberOfEntities(num_subscriptions=2, num_clients=3)

    # -- requests ---------------------------------------------------------------------------

    def send_goal_async(
        self, goal: Any, feedback_callback: Callable[[Any], Any] | None = None, goal_uuid: UUID | None = None
    ) -> Future[ClientGoalHandle]:
        """Send ``goal``; a Future of its ClientGoalHandle, done once the server has answered and the
        node is spun.  ``feedback_callback(feedback_message)`` gets the goal's FeedbackMessages while
        the node is spun.  Raises TypeError for a goal of another type.
        """
        goal_type = self._action_type.Goal
        if not isinstance(goal, goal_type):
            raise TypeError(f"Expected goal type ({type(goal_type)}) but received ({type(goal)})")
        goal_id = UUID(uuid=uuid.uuid4().bytes) if goal_uuid is None else goal_uuid
        feedback = None if feedback_callback is None else partial(self._catch_feedback, feedback_callback, goal_id)
        future: Future[ClientGoalHandle] = Future()
        send = partial(self._native.send_goal, goal, feedback=feedback, goal_id=goal_id)
        self._session.call(self._launch, send, future, partial(ClientGoalHandle, self))
        return future

    def send_goal(self, goal: Any, **kwargs: Any) -> Any:
        """Send ``goal`` and wait for its GetResult response (another thread must spin the node).

        Keyword arguments as :meth:`send_goal_async`'s; raises TypeError for a
        goal of another type and what sending raised.
        """
        goal_handle = self._wait(self.send_goal_async(goal, **kwargs))
        return self._get_result(goal_handle)

    def _get_result_async(self, goal_handle: ClientGoalHandle) -> Future[Any]:
        _check_handle(goal_handle)
        future: Future[Any] = Future()
        if goal_handle.accepted:
            self._session.call(self._launch, goal_handle._native.get_result, future)
        else:  # as a server answers for a goal it does not know
            response = self._action_type.Impl.GetResultService.Response(status=GoalStatus.STATUS_UNKNOWN)
            self._session.call(self._launch, partial(_now, response), future)
        return future

    def _get_result(self, goal_handle: ClientGoalHandle) -> Any:
        return self._wait(self._get_result_async(goal_handle))

    def _cancel_goal_async(self, goal_handle: ClientGoalHandle) -> Future[Any]:
        _check_handle(goal_handle)
        future: Future[Any] = Future()  # of a CancelGoal.Response
        self._session.call(self._launch, partial(self._native.cancel_goals, goal_id=goal_handle.goal_id), future)
        return future

    def _cancel_goal(self, goal_handle: ClientGoalHandle) -> Any:
        return self._wait(self._cancel_goal_async(goal_handle))

    def _wait(self, future: Future[Any]) -> Any:
        waiter = self._session.waiter()
        future._add_resumer(waiter.wake)
        self._session.wait_until(lambda: not future._pending(), None, waiter)
        return future.result()

    # -- on the runtime's thread --------------------------------------------------------------

    def _launch(
        self,
        call: Callable[[], Coroutine[Any, Any, Any]],
        future: Future[Any],
        convert: Callable[[Any], Any] | None = None,
    ) -> None:
        task = self._session.loop.create_task(call())
        self._calls.add(task)
        task.add_done_callback(partial(self._answered, future, convert))

    def _answered(self, future: Future[Any], convert: Callable[[Any], Any] | None, task: asyncio.Task[Any]) -> None:
        self._calls.discard(task)
        self._queue(partial(_complete, future, task, convert, self._node))

    def _catch_feedback(self, callback: Callable[[Any], Any], goal_id: UUID, feedback: Any) -> None:
        message = self._action_type.Impl.FeedbackMessage(goal_id=goal_id, feedback=feedback)
        self._queue(partial(await_or_execute, callback, message))

    # -- the server -----------------------------------------------------------------------------

    def server_is_ready(self) -> bool:
        """Whether a server of the action runs now."""
        return bool(self._session.call(self._native.server_is_ready))

    def wait_for_server(self, timeout_sec: float | None = None) -> bool:
        """Wait until a server runs (``timeout_sec`` seconds of runtime clock at most, None: no limit)
        or the context shuts down; whether one runs."""
        context = self._node.context
        waiter = self._session.waiter()
        context.add_waker(waiter)
        waiting = self._session.call(self._start_waiting, waiter)
        try:
            self._session.wait_until(lambda: waiting.done() or not context.ok(), timeout_sec, waiter)
        finally:
            self._session.call(waiting.cancel)
        return self.server_is_ready()

    def _start_waiting(self, waiter: Waiter) -> asyncio.Task[bool]:
        task = self._session.loop.create_task(self._native.wait_for_server())
        task.add_done_callback(lambda _: waiter.wake())
        return task

    def destroy(self) -> None:
        """Stop being a client: the node stops taking work from it; goals already sent go on."""
        self._node.remove_waitable(self)
        if self._node._rclpy.destroyed or not self._session.running:
            return

        def drop() -> None:
            for call in list(self._calls):
                call.cancel()
            self._native.destroy()

        self._session.call(drop)


async def _complete(
    future: Future[Any], task: asyncio.Task[Any], convert: Callable[[Any], Any] | None, node: ScriptNode
) -> None:
    # On the executor's thread: the answer completes the script's future, whose done callbacks
    # become tasks of this executor (as rclpy's futures of a waitable).
    future._set_executor(node.executor)
    if task.cancelled():
        future.cancel()
    elif (error := task.exception()) is not None:
        future.set_exception(error)
    else:
        result = task.result()
        future.set_result(convert(result) if convert is not None else result)


async def _now(value: Any) -> Any:
    return value


def _check_handle(goal_handle: Any) -> None:
    if not isinstance(goal_handle, ClientGoalHandle):
        raise TypeError(f"Expected type ClientGoalHandle but received {type(goal_handle)}")
