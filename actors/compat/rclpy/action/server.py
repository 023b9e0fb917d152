"""``rclpy.action.server``: a script node's action server, on the native one (:mod:`actors.ros.actions`).

The native server keeps the goals, their states, results and timeouts; its
goal, cancel and accepted callbacks are the overlay's *catchers*, which run on
the runtime's thread and only queue the script's callback here, on this
waitable of the node, in its callback group.  So the script's goal, cancel and
accepted callbacks run while the node is spun, on the spinning thread or an
executor's pool, as in rclpy; the native server waits for their answers.  As
in rclpy, a goal's accepted callback runs in the same step as its goal
callback, right after the server took the goal and before the executor can
hand the client its answer.

An accepted goal's execute callback is a task of the node's executor
(``executor.create_task``), made as the goal is told to execute, as rclpy
makes it: it runs outside every callback group, on a pool thread of a
MultiThreadedExecutor, and may block there
(``time.sleep`` between feedback messages) without holding anything else up.
The native goal's own task waits for that task and takes what it returns as
the result.  Everything a goal handle does from a script thread (``execute``,
``publish_feedback``, ``succeed``...) runs on the runtime's thread; reading its
state (``status``, ``is_active``, ``is_cancel_requested``) reads the native
goal's, which only the runtime's thread changes.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from functools import partial
from typing import Any, cast

from actors.compat.dispatch import ScriptNode
from actors.compat.rclpy.action.base import ActionWork, GoalHandle
from actors.compat.rclpy.task import Task, await_or_execute
from actors.compat.rclpy.waitable import NumberOfEntities
from actors.errors import ActionError
from actors.ros.actions import ActionServer as NativeServer
from actors.ros.actions import CancelResponse, GoalEvent, GoalResponse
from actors.ros.actions import ServerGoalHandle as NativeGoal
from actors.ros.node import Node as NativeNode
from interfaces.action_msgs.msg import GoalStatus

__all__ = [
    "ActionServer",
    "ServerGoalHandle",
    "GoalResponse",
    "CancelResponse",
    "GoalEvent",
    "RCLError",
    "default_goal_callback",
    "default_cancel_callback",
    "default_handle_accepted_callback",
]


class RCLError(RuntimeError):
    """A goal was asked for a transition its state does not allow (rclpy's ``_rclpy.RCLError``)."""


class ServerGoalHandle(GoalHandle):
    """One accepted goal, as the script's callbacks get it: its request, state and transitions."""

    def __init__(self, server: ActionServer, native: NativeGoal) -> None:
        self._server = server
        self._native = native
        self._session = server._session

    @property
    def request(self) -> Any:
        """The goal the client sent (the action's Goal)."""
        return self._native.request

    @property
    def is_active(self) -> bool:
        """Whether the goal is accepted, executing or canceling."""
        return self._native.is_active

    @property
    def is_cancel_requested(self) -> bool:
        """Whether a cancel request was accepted (the goal is CANCELING)."""
        return self._native.status == GoalStatus.STATUS_CANCELING

    @property
    def status(self) -> int:
        """The goal's GoalStatus value."""
        return int(self._native.status)

    def execute(self, execute_callback: Callable[[ServerGoalHandle], Any] | None = None) -> None:
        """Start executing: EXECUTING (unless a cancel came first), and the execute callback as a task
        of the node's executor (``execute_callback`` instead of the server's, if given).

        Raises RCLError for a goal that has ended or already executes.
        """
        callback = self._server._execute_callback if execute_callback is None else execute_callback
        self._transition(self._server._execute, self, callback)

    def publish_feedback(self, feedback: Any) -> None:
        """Publish ``feedback`` (the action's Feedback) for this goal; TypeError for anything else."""
        if not isinstance(feedback, self._server.action_type.Feedback):
            raise TypeError()
        self._session.call(self._native.publish_feedback, feedback)

    def succeed(self) -> None:
        """The goal succeeded; RCLError unless it is executing or canceling."""
        self._transition(self._native.succeed)

    def abort(self) -> None:
        """The goal failed; RCLError unless it is executing or canceling."""
        self._transition(self._native.abort)

    def canceled(self) -> None:
        """The goal stopped on a cancel request; RCLError unless it is canceling."""
        self._transition(self._native.canceled)

    def destroy(self) -> None:
        """Nothing to release: the server forgets the goal when its result times out."""

    def _transition(self, change: Callable[..., None], *args: Any) -> None:
        try:
            self._session.call(change, *args)
        except ActionError as exc:
            raise RCLError(f"Failed to update goal state: {exc}") from None


def default_handle_accepted_callback(goal_handle: ServerGoalHandle) -> None:
    """Execute the goal."""
    goal_handle.execute()


def default_goal_callback(goal_request: Any) -> GoalResponse:
    """Accept all goals."""
    return GoalResponse.ACCEPT


def default_cancel_callback(cancel_request: Any) -> CancelResponse:
    """No cancellations."""
    return CancelResponse.REJECT


class ActionServer(ActionWork):
    """Serves ``action_name`` on ``node`` (rclpy's signature; the QoS profiles are accepted and not used:
    an action's services and topics have ROS's default QoS here).

    ``execute_callback(goal_handle)`` (plain or ``async``) runs each executed goal
    and returns the action's Result; ``goal_callback(goal)`` answers a
    GoalResponse (default: accept), ``cancel_callback(goal_handle)`` a
    CancelResponse (default: reject), ``handle_accepted_callback(goal_handle)``
    runs after a goal is accepted (default: execute it).  Raises TypeError for
    an execute callback that is not callable, ServiceError when another node
    serves the action.
    """

    def __init__(
        self,
        node: ScriptNode,
        action_type: type[Any],
        action_name: str,
        execute_callback: Callable[[ServerGoalHandle], Any],
        *,
        callback_group: Any = None,
        goal_callback: Callable[[Any], Any] = default_goal_callback,
        handle_accepted_callback: Callable[[ServerGoalHandle], Any] = default_handle_accepted_callback,
        cancel_callback: Callable[[ServerGoalHandle], Any] = default_cancel_callback,
        goal_service_qos_profile: Any = None,
        result_service_qos_profile: Any = None,
        cancel_service_qos_profile: Any = None,
        feedback_pub_qos_profile: Any = None,
        status_pub_qos_profile: Any = None,
        result_timeout: int = 10,
    ) -> None:
        super().__init__(node, callback_group)
        self._action_type = action_type
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_goal_callback(goal_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        self._handles: dict[bytes, ServerGoalHandle] = {}
        # Goals (by id of the request's goal) whose callback said ACCEPT, awaiting the server's word.
        self._accepting: dict[int, asyncio.Future[NativeGoal | None]] = {}
        self._logger = node.get_logger().get_child("action_server")
        self._native: NativeServer
        self._session.call(self._build, action_name, result_timeout)
        self.callback_group.add_entity(self)
        node.add_waitable(self)

    def _build(self, action_name: str, result_timeout: float) -> None:
        # On the runtime's thread: the native server, its entities driven before a request can come
        # (a goal parked before the server existed arrives as soon as it does).
        self._native = NativeNode.create_action_server(
            cast(NativeNode, self._node),  # a script node: an rclpy Node, so a native one
            self._action_type,
            action_name,
            self._executing_default,
            goal=self._catch_goal,
            cancel=self._catch_cancel,
            accepted=self._catch_accepted,
            result_timeout=result_timeout,
        )

    @property
    def action_type(self) -> type[Any]:
        """The action type served."""
        return self._action_type

    @property
    def _goal_handles(self) -> dict[bytes, Any]:
        # rclpy's record of the goals it holds (until their results expire), which its tests count.
        return dict(self._session.call(lambda: self._native.goals))

    def get_num_entities(self) -> NumberOfEntities:
        """What an action server is made of: three services and the timer that expires results."""
        return NumberOfEntities(num_timers=1, num_services=3)

    # -- the catchers: on the runtime's thread, they queue the script's callbacks here -------

    async def _catch_goal(self, goal: Any) -> GoalResponse:
        loop = asyncio.get_running_loop()
        answer: asyncio.Future[GoalResponse] = loop.create_future()
        self._queue(partial(self._ask, self._goal_callback, goal, answer))
        try:
            return await answer
        finally:
            # Runs once the native server has decided on the goal (it does so as this returns).
            loop.call_soon(self._refused, goal)

    async def _catch_cancel(self, native: NativeGoal) -> CancelResponse:
        answer: asyncio.Future[CancelResponse] = asyncio.get_running_loop().create_future()
        self._queue(partial(self._ask, self._cancel_callback, self._handle(native), answer))
        return await answer

    def _catch_accepted(self, native: NativeGoal) -> None:
        acceptance = self._accepting.pop(id(native.request), None)
        if acceptance is None:
            self._queue(partial(self._accepted, self._handle(native)))
        elif not acceptance.done():
            acceptance.set_result(native)

    def _refused(self, goal: Any) -> None:
        # A goal its callback accepted that the server did not take (it was being destroyed).
        if not any(native.request is goal for native in self._native.goals.values()):
            acceptance = self._accepting.pop(id(goal), None)
            if acceptance is not None and not acceptance.done():
                acceptance.set_result(None)

    async def _accept(self, goal: Any, answer: asyncio.Future[Any]) -> NativeGoal | None:
        # On the loop: answer ACCEPT, and hand back the goal the native server then accepts.
        acceptance: asyncio.Future[NativeGoal | None] = asyncio.get_running_loop().create_future()
        self._accepting[id(goal)] = acceptance
        _settle(answer, GoalResponse.ACCEPT, None)
        return await acceptance

    def _handle(self, native: NativeGoal) -> ServerGoalHandle:
        # The one handle of a goal (scripts compare them); forgotten with the native goal.
        key = bytes(native.goal_id.uuid)
        with self._session.lock:
            handle = self._handles.get(key)
            if handle is None or handle._native is not native:
                goals = self._native.goals
                self._handles = {k: h for k, h in self._handles.items() if k in goals}
                handle = self._handles[key] = ServerGoalHandle(self, native)
            return handle

    async def _executing_default(self, native: NativeGoal) -> Any:
        return await self._finished(self._start(self._handle(native), self._execute_callback))

    def _execute(self, handle: ServerGoalHandle, callback: Callable[..., Any]) -> None:
        # With the turn held: EXECUTING, and (as rclpy's execute) the execute callback's task of the
        # node's executor made at once, so the executor's next look finds it; the native goal's own
        # task, which starts later, waits for it.
        started: list[Task[Any] | None] = []
        handle._native.execute(lambda native: self._finished(started[0]))
        started.append(self._start(handle, callback))

    def _start(self, handle: ServerGoalHandle, callback: Callable[..., Any]) -> Task[Any] | None:
        executor = self._node.executor
        return None if executor is None else executor.create_task(self._execute_goal, callback, handle)

    async def _finished(self, task: Task[Any] | None) -> Any:
        # The native goal's task: the script's execute callback's outcome is the goal's result.
        loop = asyncio.get_running_loop()
        done: asyncio.Future[Any] = loop.create_future()
        if task is None:  # as rclpy: nobody spins the node, so nothing executes the goal
            return await done
        task._add_resumer(lambda: _settle_threadsafe(loop, done, task))
        result, error = await done
        if error is not None:
            raise error
        return result

    @staticmethod
    async def _execute_goal(callback: Callable[..., Any], handle: ServerGoalHandle) -> tuple[Any, Exception | None]:
        # What the callback raises goes to the native goal (which logs it and aborts), not to spin().
        try:
            return await await_or_execute(callback, handle), None
        except Exception as exc:
            return None, exc

    # -- on the executor's threads ------------------------------------------------------------

    async def _ask(self, callback: Callable[[Any], Any], request: Any, answer: asyncio.Future[Any]) -> None:
        # The goal or cancel callback's answer goes to the native server, which waits for it.
        try:
            response = await await_or_execute(callback, request)
        except Exception as exc:
            self._settle(answer, None, exc)
            raise
        if callback is self._goal_callback and not isinstance(response, GoalResponse):
            self._logger.warning("Goal request callback did not return a GoalResponse type. Rejecting goal.")
            response = GoalResponse.REJECT
        if callback is self._goal_callback and response is GoalResponse.ACCEPT and self._session.running:
            # As rclpy's server, which sends the answer and awaits the accepted callback in one task:
            # the accepted callback has run (to its first await) before the client can see the answer.
            native = self._session.block(self._accept, request, answer)
            if native is not None:
                await await_or_execute(self._handle_accepted_callback, self._handle(native))
            return
        self._settle(answer, response, None)

    async def _accepted(self, handle: ServerGoalHandle) -> None:
        await await_or_execute(self._handle_accepted_callback, handle)

    def _settle(self, answer: asyncio.Future[Any], result: Any, error: BaseException | None) -> None:
        if self._session.running:
            self._session.loop.call_soon_threadsafe(_settle, answer, result, error)

    # -- rclpy's registration methods ------------------------------------------------------------

    def register_handle_accepted_callback(self, handle_accepted_callback: Callable[..., Any] | None) -> None:
        """Replace the accepted callback (None: execute every accepted goal)."""
        self._handle_accepted_callback = handle_accepted_callback or default_handle_accepted_callback

    def register_goal_callback(self, goal_callback: Callable[..., Any] | None) -> None:
        """Replace the goal callback (None: accept every goal)."""
        self._goal_callback = goal_callback or default_goal_callback

    def register_cancel_callback(self, cancel_callback: Callable[..., Any] | None) -> None:
        """Replace the cancel callback (None: refuse every cancel request)."""
        self._cancel_callback = cancel_callback or default_cancel_callback

    def register_execute_callback(self, execute_callback: Callable[..., Any]) -> None:
        """Replace the execute callback; TypeError if it is not callable."""
        if not callable(execute_callback):
            raise TypeError("Failed to register goal execution callback: not callable")
        self._execute_callback = execute_callback

    def destroy(self) -> None:
        """Stop serving: goals not finished abort; the node stops taking work from this server."""
        self._node.remove_waitable(self)
        state = self._node._rclpy
        if state.destroyed or not self._session.running:
            return

        self._session.call(self._native.destroy)


def _settle(answer: asyncio.Future[Any], result: Any, error: BaseException | None) -> None:
    if answer.done():  # the request was given up meanwhile (the node stopped)
        return
    if error is not None:
        answer.set_exception(error)
    else:
        answer.set_result(result)


def _settle_threadsafe(loop: asyncio.AbstractEventLoop, done: asyncio.Future[Any], task: Task[Any]) -> None:
    # From the thread that finished the task: hand its outcome to the native goal's task.
    if loop.is_closed():
        return
    if task.cancelled():
        outcome: Any = (None, RuntimeError("the execute callback's task was cancelled"))
    else:
        outcome = (None, task.exception()) if task.exception() is not None else task.result()
    try:
        loop.call_soon_threadsafe(_settle, done, outcome, None)
    except RuntimeError:  # the loop closed meanwhile: nobody waits any more
        pass
