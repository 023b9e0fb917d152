"""Actions: long-running goals with feedback, a result and cancellation, as ROS 2 defines them.

An action is built from the node's ordinary entities under the names ROS uses,
so introspection (and a later transport) sees what ROS sees::

    <action>/_action/send_goal     service  Name_SendGoal    goal id + goal -> accepted + stamp
    <action>/_action/cancel_goal   service  CancelGoal       goal info -> goals canceling
    <action>/_action/get_result    service  Name_GetResult   goal id -> status + result
    <action>/_action/feedback      topic    Name_FeedbackMessage
    <action>/_action/status        topic    GoalStatusArray (transient local, depth 1)

The server (:class:`ActionServer`) keeps a goal per UUID through ROS's state
machine: ACCEPTED -> EXECUTING -> (CANCELING ->) SUCCEEDED | ABORTED | CANCELED,
publishing the status of every goal it tracks on each change.  The goal and
cancel callbacks run in the node's actor like any callback; each accepted
goal's execute callback runs as a task of its own beside the actor, because it
lasts long and the node must meanwhile answer cancel requests and other goals.
It interleaves with the node's callbacks only where it awaits.  What the
execute callback returns is the result; an execute callback that raises, or
returns without setting a terminal state, aborts its goal (as rclpy does) and
the server keeps serving.  A finished goal's result is kept for
``result_timeout`` seconds (rclpy's default, 10), then the goal is forgotten.

When the server's node stops (a crash, a restart, a shutdown), every goal it
had not finished is aborted: the status topic says ABORTED, waiting
``get_result`` calls are answered with ABORTED and an empty result, and the
execute tasks are cancelled.  No client is left waiting; a restarted server
starts with no goals.

The client (:class:`ActionClient`) sends a goal with a fresh UUID and asks for
its result as soon as the goal is accepted, so a result is never lost to the
server's result timeout.  Feedback reaches a goal in one of two ways:

- ``send_goal(goal, feedback=cb)``: ``cb`` runs in the client's node like any
  callback, in order; while another callback of that node awaits (say, the
  result), feedback waits its turn;
- without a callback, the goal keeps its latest 100 feedback messages for
  ``async for feedback in handle.feedback()``, which a callback can await
  in place: the loop ends when the goal does.

Feedback is routed to its goal as it is published (the feedback subscription
does no more than that), so neither way needs the node's actor to be free.
"""

from __future__ import annotations

import asyncio
import uuid
from collections import deque
from collections.abc import AsyncIterator, Awaitable, Callable
from enum import Enum
from functools import partial
from inspect import isawaitable
from typing import Any, Protocol

import anyio

from actors.core._actor import AT_ONCE, OneShot, Owner
from actors.errors import ActionError
from actors.ros.qos import DurabilityPolicy, QoSProfile
from actors.ros.time import Clock
from actors.ros.topics import Publisher, Subscription, type_name
from actors.services import Client, Service
from interfaces.action_msgs.msg import GoalInfo, GoalStatus
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "GoalResponse",
    "CancelResponse",
    "GoalEvent",
    "STATUS_QOS",
    "ActionHost",
    "ActionServer",
    "ActionClient",
    "ServerGoalHandle",
    "ClientGoalHandle",
    "ActionCall",
    "wire_names",
    "status_name",
]


class GoalResponse(Enum):
    """What a goal callback answers (values as rclpy's)."""

    REJECT = 1
    ACCEPT = 2


class CancelResponse(Enum):
    """What a cancel callback answers (values as rclpy's)."""

    REJECT = 1
    ACCEPT = 2


class GoalEvent(Enum):
    """What moves a goal from one state to the next (rcl_action's goal events)."""

    EXECUTE = "execute"
    CANCEL_GOAL = "cancel_goal"
    SUCCEED = "succeed"
    ABORT = "abort"
    CANCELED = "canceled"


STATUS_QOS = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
"""The status topic's QoS: a late client gets the latest status array (rcl_action's default)."""

_ACCEPTED, _EXECUTING, _CANCELING = GoalStatus.STATUS_ACCEPTED, GoalStatus.STATUS_EXECUTING, GoalStatus.STATUS_CANCELING
_SUCCEEDED, _CANCELED, _ABORTED = GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED
_UNKNOWN = GoalStatus.STATUS_UNKNOWN

# rcl_action's goal state machine: (state, event) -> next state; anything else is refused.
_TRANSITIONS = {
    (_ACCEPTED, GoalEvent.EXECUTE): _EXECUTING,
    (_ACCEPTED, GoalEvent.CANCEL_GOAL): _CANCELING,
    (_EXECUTING, GoalEvent.CANCEL_GOAL): _CANCELING,
    (_EXECUTING, GoalEvent.SUCCEED): _SUCCEEDED,
    (_EXECUTING, GoalEvent.ABORT): _ABORTED,
    (_CANCELING, GoalEvent.SUCCEED): _SUCCEEDED,
    (_CANCELING, GoalEvent.ABORT): _ABORTED,
    (_CANCELING, GoalEvent.CANCELED): _CANCELED,
}
_ACTIVE = frozenset({_ACCEPTED, _EXECUTING, _CANCELING})
_NAMES = {
    _UNKNOWN: "UNKNOWN",
    _ACCEPTED: "ACCEPTED",
    _EXECUTING: "EXECUTING",
    _CANCELING: "CANCELING",
    _SUCCEEDED: "SUCCEEDED",
    _CANCELED: "CANCELED",
    _ABORTED: "ABORTED",
}


def status_name(status: int) -> str:
    """A GoalStatus value's name as ``ros2 action`` prints it (``SUCCEEDED``); ``UNKNOWN`` otherwise."""
    return _NAMES.get(status, "UNKNOWN")


def wire_names(action: str) -> dict[str, str]:
    """The services and topics of the action named ``action`` (absolute), by role."""
    return {
        role: f"{action}/_action/{role}" for role in ("send_goal", "cancel_goal", "get_result", "feedback", "status")
    }


def _check_action_type(action_type: Any, where: str) -> None:
    if not (
        isinstance(action_type, type) and all(hasattr(action_type, a) for a in ("Goal", "Result", "Feedback", "Impl"))
    ):
        raise TypeError(f"{where} needs an action type (with .Goal, .Result, .Feedback), got {action_type!r}")


class ActionCall(OneShot):
    """A user callback an action runs later in its node's actor (accepted, feedback).

    Whoever drives a node's actor itself (the rclpy overlay) can tell an
    action's calls from the node's other work by their type.
    """

    __slots__ = ()


def _key(goal_id: UUID) -> bytes:
    return bytes(goal_id.uuid)


def _short(goal_id: UUID) -> str:
    return bytes(goal_id.uuid).hex()


class ActionHost(Owner, Protocol):
    """What an action needs from its node: the node's entities and a place to run goals."""

    @property
    def clock(self) -> Clock: ...

    def create_service(self, srv_type: type[Any], name: str, handler: Callable[..., Any]) -> Service: ...

    def add_service(self, service: Service) -> Service: ...

    def create_client(self, srv_type: type[Any], name: str) -> Client: ...

    def create_publisher(self, msg_type: type[Any], topic: str, qos: QoSProfile | int) -> Publisher: ...

    def create_subscription(
        self, msg_type: type[Any], topic: str, callback: Callable[[Any], Any], qos: QoSProfile | int
    ) -> Subscription: ...

    def start_task(self, fn: Callable[..., Awaitable[Any]], *args: Any, name: str) -> None: ...

    def destroy_action_server(self, server: ActionServer) -> None: ...

    def destroy_action_client(self, client: ActionClient) -> None: ...


# --------------------------------------------------------------------------- the server


class _ResultService(Service):
    """The get_result service: its handler keeps the caller's future and answers when the goal ends."""

    __slots__ = ()

    def _run(self) -> None:
        queue = self._queue
        assert queue is not None
        for _ in range(len(queue)):
            request, future = queue.popleft()
            if not future.done():
                self.handled += 1
                self.handler(request, future)
        self._round_done()


class ServerGoalHandle:
    """One accepted goal on the server: its request, its state, and the calls that move it on.

    Made by the server only; the execute, cancel and accepted callbacks get it.
    """

    __slots__ = ("_server", "info", "request", "status", "_running", "_scope", "_response", "_waiters", "_expiry")

    def __init__(self, server: ActionServer, info: GoalInfo, request: Any) -> None:
        self._server = server
        self.info = info
        self.request = request
        self.status = _ACCEPTED
        self._running = False
        self._scope: anyio.CancelScope | None = None
        self._response: Any = None  # the GetResult response, once the goal has ended
        self._waiters: list[asyncio.Future[Any]] = []
        self._expiry: asyncio.TimerHandle | None = None

    def __repr__(self) -> str:
        return f"<goal {_short(self.goal_id)} of {self._server.name}: {status_name(self.status)}>"

    @property
    def goal_id(self) -> UUID:
        """The goal's UUID, as the client chose it."""
        return self.info.goal_id

    @property
    def is_active(self) -> bool:
        """Whether the goal is accepted, executing or canceling (not yet ended)."""
        return self.status in _ACTIVE

    @property
    def is_cancel_requested(self) -> bool:
        """Whether a cancel request was accepted: the execute callback should stop and call canceled()."""
        return self.status == _CANCELING

    def execute(self, execute_callback: Callable[[ServerGoalHandle], Any] | None = None) -> None:
        """Start executing: EXECUTING (unless a cancel came first), and the execute callback in its own task.

        For an ``accepted`` callback that defers or queues goals; the default
        one calls this at once.  ``execute_callback`` overrides the server's.
        Raises ActionError for a goal that has ended or already runs.
        """
        if not self.is_active or self._running:
            raise ActionError(
                f"goal {_short(self.goal_id)} of {self._server.name} cannot execute: it is "
                f"{'running' if self._running else status_name(self.status)}"
            )
        if not self.is_cancel_requested:
            self._update(GoalEvent.EXECUTE)
        self._running = True
        server = self._server
        server.node.start_task(
            server._run_goal,
            self,
            execute_callback or server.execute_callback,
            name=f"goal {_short(self.goal_id)} of {server.name}",
        )

    def publish_feedback(self, feedback: Any) -> None:
        """Publish ``feedback`` (the action's Feedback) for this goal; ignored once the goal has ended.

        Raises TypeError for a message of another type.
        """
        server = self._server
        if type(feedback) is not server.action_type.Feedback:
            raise TypeError(
                f"feedback of {server.name} is {type_name(server.action_type.Feedback)}, "
                f"got {type_name(type(feedback))}"
            )
        if self.is_active:
            server._feedback.publish(server.action_type.Impl.FeedbackMessage(goal_id=self.goal_id, feedback=feedback))

    def succeed(self) -> None:
        """The goal succeeded (from EXECUTING or CANCELING); the execute callback returns its result."""
        self._update(GoalEvent.SUCCEED)

    def abort(self) -> None:
        """The goal failed (from EXECUTING or CANCELING)."""
        self._update(GoalEvent.ABORT)

    def canceled(self) -> None:
        """The goal stopped because a cancel was requested (from CANCELING only)."""
        self._update(GoalEvent.CANCELED)

    def _update(self, event: GoalEvent) -> None:
        after = _TRANSITIONS.get((self.status, event))
        if after is None:
            raise ActionError(
                f"goal {_short(self.goal_id)} of {self._server.name}: cannot {event.value} "
                f"from {status_name(self.status)}"
            )
        self.status = after
        self._server._publish_status()
        if after not in _ACTIVE and not self._running:
            # Ended outside an execute callback (a deferred goal): nothing will return a result.
            self._server._finish(self, self._server.action_type.Result())


class ActionServer:
    """Serves one action: create with ``Node.create_action_server``.

    ``execute(goal_handle)`` (plain or ``async``) runs each accepted goal and
    returns the action's Result; it calls ``goal_handle.succeed()``,
    ``abort()`` or ``canceled()`` first (otherwise the goal is aborted).
    ``goal(goal_request)`` answers GoalResponse.ACCEPT or REJECT (or a bool;
    default: accept); ``cancel(goal_handle)`` answers CancelResponse.ACCEPT or
    REJECT (default: reject, as in ROS); ``accepted(goal_handle)`` runs after a
    goal is accepted and answered (default: ``goal_handle.execute()``: defer or
    queue goals by calling it later).  Raises ServiceError when another node
    already serves the action.
    """

    def __init__(
        self,
        node: ActionHost,
        name: str,
        action_type: type[Any],
        execute: Callable[[ServerGoalHandle], Any],
        *,
        goal: Callable[[Any], Any] | None = None,
        cancel: Callable[[ServerGoalHandle], Any] | None = None,
        accepted: Callable[[ServerGoalHandle], Any] | None = None,
        result_timeout: float = 10.0,
    ) -> None:
        _check_action_type(action_type, "create_action_server")
        for what, fn in (("execute", execute), ("goal", goal), ("cancel", cancel), ("accepted", accepted)):
            if fn is not None and not callable(fn):
                raise TypeError(f"action server {what} callback must be callable, got {fn!r}")
        if result_timeout < 0:
            raise ValueError(f"result_timeout must be >= 0 seconds, got {result_timeout}")
        self.node = node
        self.name = name
        self.action_type = action_type
        self.execute_callback = execute
        self.goal_callback = goal or (lambda request: GoalResponse.ACCEPT)
        self.cancel_callback = cancel or (lambda handle: CancelResponse.REJECT)
        self.accepted_callback = accepted or (lambda handle: handle.execute())
        self.result_timeout = float(result_timeout)
        self.goals: dict[bytes, ServerGoalHandle] = {}
        self._halted = False
        impl = action_type.Impl
        names = wire_names(name)
        self._feedback = node.create_publisher(impl.FeedbackMessage, names["feedback"], 10)
        self._status = node.create_publisher(impl.GoalStatusMessage, names["status"], STATUS_QOS)
        self._services = [
            node.create_service(impl.SendGoalService, names["send_goal"], self._on_send_goal),
            node.create_service(impl.CancelGoalService, names["cancel_goal"], self._on_cancel),
            node.add_service(_ResultService(node, names["get_result"], impl.GetResultService, self._on_get_result)),
        ]

    def __repr__(self) -> str:
        return f"<ActionServer {self.name} ({type_name(self.action_type)}) of {self.node.fqn}>"

    # -- requests ---------------------------------------------------------------

    def _on_send_goal(self, request: Any, response: Any) -> Any:
        if _key(request.goal_id) in self.goals:
            self.node.logger.warning(f"{self.name}: goal {_short(request.goal_id)} already exists; rejected")
            return response
        decision = self.goal_callback(request.goal)
        if isawaitable(decision):
            return self._decide_later(decision, request, response)
        return self._decide(decision, request, response)

    async def _decide_later(self, decision: Awaitable[Any], request: Any, response: Any) -> Any:
        return self._decide(await decision, request, response)

    def _decide(self, decision: Any, request: Any, response: Any) -> Any:
        if not isinstance(decision, (GoalResponse, bool)):
            self.node.logger.warning(
                f"{self.name}: the goal callback returned {decision!r}, not a GoalResponse; goal rejected"
            )
            decision = GoalResponse.REJECT
        if decision not in (GoalResponse.ACCEPT, True) or self._halted:
            return response
        stamp = self.node.clock.now().to_msg()
        handle = ServerGoalHandle(self, GoalInfo(goal_id=request.goal_id, stamp=stamp), request.goal)
        self.goals[_key(request.goal_id)] = handle
        self._publish_status()
        # After this response is sent, as rclpy does: the accepted callback runs next in the actor.
        self.node.actor.schedule(
            ActionCall(partial(self.accepted_callback, handle), f"accepted callback of {self.name}")
        )
        response.accepted = True
        response.stamp = stamp
        return response

    async def _on_cancel(self, request: Any, response: Any) -> Any:
        code, candidates = self._cancel_candidates(request.goal_info)
        response.return_code = code
        for handle in candidates:
            decision = self.cancel_callback(handle)
            if isawaitable(decision):
                decision = await decision
            # The goal may have ended while the callback awaited.
            if decision in (CancelResponse.ACCEPT, True) and handle.status in (_ACCEPTED, _EXECUTING):
                handle._update(GoalEvent.CANCEL_GOAL)
                response.goals_canceling.append(handle.info)
        if candidates and not response.goals_canceling:
            response.return_code = response.ERROR_REJECTED  # as CancelGoal.srv defines it
        return response

    def _cancel_candidates(self, info: GoalInfo) -> tuple[int, list[ServerGoalHandle]]:
        """rcl_action's rules: by id, by stamp (accepted at or before), or all; active goals only."""
        codes = self.action_type.Impl.CancelGoalService.Response
        key = _key(info.goal_id)
        stamp = info.stamp.sec * 1_000_000_000 + info.stamp.nanosec
        cancelable = (_ACCEPTED, _EXECUTING)
        if any(key) and stamp == 0:
            handle = self.goals.get(key)
            if handle is None:
                return codes.ERROR_UNKNOWN_GOAL_ID, []
            if handle.status not in cancelable:
                return codes.ERROR_GOAL_TERMINATED, []
            return codes.ERROR_NONE, [handle]
        limit = stamp if stamp else float("inf")
        return codes.ERROR_NONE, [
            h
            for h in self.goals.values()
            if h.status in cancelable
            and (h.info.stamp.sec * 1_000_000_000 + h.info.stamp.nanosec <= limit or _key(h.goal_id) == key)
        ]

    def _on_get_result(self, request: Any, future: asyncio.Future[Any]) -> None:
        handle = self.goals.get(_key(request.goal_id))
        if handle is None:
            self.node.logger.warning(f"{self.name}: result asked for unknown or expired goal {_short(request.goal_id)}")
            future.set_result(self.action_type.Impl.GetResultService.Response(status=_UNKNOWN))
        elif handle._response is not None:
            future.set_result(handle._response)
        else:
            handle._waiters.append(future)

    # -- goals ------------------------------------------------------------------

    async def _run_goal(self, handle: ServerGoalHandle, execute: Callable[[ServerGoalHandle], Any]) -> None:
        result_type = self.action_type.Result
        result = None
        with anyio.CancelScope() as scope:
            handle._scope = scope
            try:
                result = execute(handle)
                if isawaitable(result):
                    result = await result
                if type(result) is not result_type:
                    raise TypeError(
                        f"execute callback returned {type_name(type(result))}, expected {type_name(result_type)}"
                    )
            except Exception as exc:
                self.node.logger.error(f"{self.name}: execute callback raised {exc!r}", exc_info=exc)
                result = result_type()
        handle._scope = None
        handle._running = False
        if scope.cancelled_caught or self._halted:
            return  # _halt has answered for this goal
        if handle.is_active:
            self.node.logger.warning(
                f"{self.name}: goal {_short(handle.goal_id)} ended without succeed(), abort() or canceled(); aborted"
            )
            handle.status = _ABORTED
            self._publish_status()
        self._finish(handle, result)

    def _finish(self, handle: ServerGoalHandle, result: Any) -> None:
        handle._response = self.action_type.Impl.GetResultService.Response(status=handle.status, result=result)
        for waiter in handle._waiters:
            if not waiter.done():
                waiter.set_result(handle._response)
        handle._waiters.clear()
        if not self._halted:
            handle._expiry = self.node.loop.call_later(self.result_timeout, self._expire, handle)

    def _expire(self, handle: ServerGoalHandle) -> None:
        if self.goals.get(_key(handle.goal_id)) is handle:
            del self.goals[_key(handle.goal_id)]
            self._publish_status()

    def _publish_status(self) -> None:
        message = self.action_type.Impl.GoalStatusMessage(
            status_list=[GoalStatus(goal_info=h.info, status=h.status) for h in self.goals.values()]
        )
        self._status.publish(message)

    def _halt(self, reason: str) -> None:
        """Abort every goal not finished (its node stops): status, waiting results, execute tasks."""
        if self._halted:
            return
        self._halted = True
        ended = [h for h in self.goals.values() if h._response is None]
        for handle in ended:
            handle.status = _ABORTED
            handle._running = False
            if handle._scope is not None:
                handle._scope.cancel()
        for handle in self.goals.values():
            if handle._expiry is not None:
                handle._expiry.cancel()
        if ended:
            self._publish_status()
            ids = ", ".join(_short(h.goal_id) for h in ended)
            self.node.logger.warning(f"{self.name}: aborted {len(ended)} goal(s) ({ids}): {reason}")
        for handle in ended:
            self._finish(handle, self.action_type.Result())
        # get_result calls not yet handled: answer those for goals known here.
        results = self._services[2]
        if results._queue:
            for call in [c for c in results._queue if _key(c[0].goal_id) in self.goals]:
                results._queue.remove(call)
                request, future = call
                if not future.done():
                    future.set_result(self.goals[_key(request.goal_id)]._response)

    def destroy(self) -> None:
        """Stop serving: unfinished goals abort, the services and topics go away."""
        self.node.destroy_action_server(self)

    def _destroy_entities(self) -> None:
        self._halt("its action server was destroyed")
        for service in self._services:
            service.destroy()
        self._feedback.destroy()
        self._status.destroy()


# --------------------------------------------------------------------------- the client


class ClientGoalHandle:
    """A goal as its client sees it: accepted or not, its status, feedback, result, cancel.

    Returned by :meth:`ActionClient.send_goal`.
    """

    __slots__ = (
        "_client",
        "goal_id",
        "goal",
        "accepted",
        "stamp",
        "status",
        "_feedback",
        "_result",
        "_buffer",
        "_arrived",
    )

    def __init__(self, client: ActionClient, goal_id: UUID, goal: Any, feedback: Callable[[Any], Any] | None) -> None:
        self._client = client
        self.goal_id = goal_id
        self.goal = goal
        self.accepted = False
        self.stamp: Any = None
        self.status = _UNKNOWN
        self._feedback = feedback
        self._result: asyncio.Future[Any] | None = None
        self._buffer: deque[Any] = deque(maxlen=100)
        self._arrived: anyio.Event | None = None

    def __repr__(self) -> str:
        return f"<goal {_short(self.goal_id)} of {self._client.name}: {status_name(self.status)}>"

    @property
    def done(self) -> bool:
        """Whether the result has arrived."""
        return self._result is not None and self._result.done()

    async def feedback(self) -> AsyncIterator[Any]:
        """Each Feedback message of this goal, in order, until the goal ends.

        Messages that arrived before the loop started come first (the latest
        100).  Empty for a goal sent with a ``feedback`` callback (the callback
        gets them) and for a rejected goal.
        """
        while True:
            while self._buffer:
                yield self._buffer.popleft()
            if self._result is None or self._result.done():
                return
            self._arrived = anyio.Event()
            await self._arrived.wait()

    def _notify(self) -> None:
        if self._arrived is not None:
            self._arrived.set()
            self._arrived = None

    async def get_result(self, timeout: float | None = None) -> Any:
        """Wait for the goal to end; its GetResult response: ``.status`` (GoalStatus) and ``.result``.

        An aborted or canceled goal is not an error: read ``.status``.  Raises
        ActionError for a rejected goal, TimeoutError after ``timeout``
        seconds (the goal goes on; ask again later), ServiceError when the
        server went away without answering.  Cancelling the wait cancels only
        the wait.
        """
        if self._result is None:
            raise ActionError(f"goal {_short(self.goal_id)} of {self._client.name} was rejected: it has no result")
        with anyio.fail_after(timeout):
            return await asyncio.shield(self._result)

    async def cancel(self, timeout: float | None = None) -> Any:
        """Ask the server to cancel this goal; its CancelGoal response (``goals_canceling`` empty if refused).

        Raises ActionError for a rejected goal, TimeoutError after ``timeout`` seconds.
        """
        if not self.accepted:
            raise ActionError(f"goal {_short(self.goal_id)} of {self._client.name} was rejected: nothing to cancel")
        return await self._client.cancel_goals(goal_id=self.goal_id, timeout=timeout)


class ActionClient:
    """A client of one action: create with ``Node.create_action_client``.

    ``await client.send_goal(goal, feedback=cb)`` returns a
    :class:`ClientGoalHandle`; ``await handle.get_result()`` waits for the
    result, ``await handle.cancel()`` asks to cancel.
    """

    def __init__(self, node: ActionHost, name: str, action_type: type[Any]) -> None:
        _check_action_type(action_type, "create_action_client")
        self.node = node
        self.name = name
        self.action_type = action_type
        self.goals: dict[bytes, ClientGoalHandle] = {}
        impl = action_type.Impl
        names = wire_names(name)
        self._send = node.create_client(impl.SendGoalService, names["send_goal"])
        self._cancel = node.create_client(impl.CancelGoalService, names["cancel_goal"])
        self._results = node.create_client(impl.GetResultService, names["get_result"])
        feedback = node.create_subscription(impl.FeedbackMessage, names["feedback"], self._on_feedback, 10)
        feedback._actor = AT_ONCE  # its callback only routes: run where the feedback is published
        self._subscriptions = [
            feedback,
            node.create_subscription(impl.GoalStatusMessage, names["status"], self._on_status, STATUS_QOS),
        ]

    def __repr__(self) -> str:
        return f"<ActionClient {self.name} ({type_name(self.action_type)}) of {self.node.fqn}>"

    def server_is_ready(self) -> bool:
        """Whether a server of this action runs now."""
        return all(c.service_is_ready() for c in (self._send, self._cancel, self._results))

    async def wait_for_server(self, timeout: float | None = None, *, timeout_sec: float | None = None) -> bool:
        """Wait until a server runs; False if ``timeout`` seconds (``timeout_sec``, rclpy's name) pass first."""
        if timeout is None:
            timeout = timeout_sec
        with anyio.move_on_after(timeout):
            for client in (self._send, self._cancel, self._results):
                await client.wait_for_service()
        return self.server_is_ready()

    async def send_goal(
        self,
        goal: Any,
        *,
        feedback: Callable[[Any], Any] | None = None,
        timeout: float | None = None,
        goal_id: UUID | None = None,
    ) -> ClientGoalHandle:
        """Send ``goal`` (the action's Goal) under a new UUID; the handle once the server has answered.

        ``feedback(msg)`` (plain or ``async``) gets each of the goal's Feedback
        messages, in order, in this node's actor; without it, iterate
        ``handle.feedback()``.  Check ``handle.accepted``.  ``goal_id`` is the
        goal's UUID if the caller chose one (rclpy's ``goal_uuid``; a server
        rejects an id it already has).  Raises TypeError for a goal of another
        type, ActionError for a ``goal_id`` of a goal this client still waits
        for, TimeoutError when no server answers within ``timeout`` seconds (a
        goal sent before its server starts waits for it).
        """
        goal_type = self.action_type.Goal
        if type(goal) is not goal_type:
            raise TypeError(f"goal of {self.name} is {type_name(goal_type)}, got {type_name(type(goal))}")
        impl = self.action_type.Impl
        if goal_id is None:
            goal_id = UUID(uuid=uuid.uuid4().bytes)
        elif _key(goal_id) in self.goals:
            raise ActionError(f"goal {_short(goal_id)} of {self.name} was sent already and has not ended")
        handle = ClientGoalHandle(self, goal_id, goal, feedback)
        key = _key(goal_id)
        self.goals[key] = handle  # before sending: feedback may come before the answer
        try:
            response = await self._send.call(impl.SendGoalService.Request(goal_id=goal_id, goal=goal), timeout=timeout)
        except BaseException:
            del self.goals[key]
            raise
        handle.accepted = response.accepted
        handle.stamp = response.stamp
        if not response.accepted:
            del self.goals[key]
            return handle
        handle.status = max(handle.status, _ACCEPTED)
        handle._result = self._results.call_async(impl.GetResultService.Request(goal_id=goal_id))
        handle._result.add_done_callback(partial(self._ended, handle))
        return handle

    def _ended(self, handle: ClientGoalHandle, future: asyncio.Future[Any]) -> None:
        self.goals.pop(_key(handle.goal_id), None)
        if not future.cancelled() and future.exception() is None:
            handle.status = future.result().status
        handle._notify()

    async def cancel_goals(
        self, *, goal_id: UUID | None = None, stamp: Any = None, timeout: float | None = None
    ) -> Any:
        """Ask the server to cancel goals by ROS's rules; its CancelGoal response.

        No ``goal_id`` and no ``stamp``: every goal; a ``stamp``
        (builtin_interfaces Time): every goal accepted at or before it; a
        ``goal_id``: that goal (and with a stamp, those before it too).
        Raises TimeoutError after ``timeout`` seconds.
        """
        info = GoalInfo()
        if goal_id is not None:
            info.goal_id = goal_id
        if stamp is not None:
            info.stamp = stamp
        return await self._cancel.call(self.action_type.Impl.CancelGoalService.Request(goal_info=info), timeout=timeout)

    def _on_feedback(self, message: Any) -> None:
        # Runs where the feedback is published (see AT_ONCE): routes, never raises.
        handle = self.goals.get(_key(message.goal_id))
        if handle is None:
            return
        if handle._feedback is not None:
            callback = partial(handle._feedback, message.feedback)
            self.node.actor.schedule(ActionCall(callback, f"feedback callback of {self.name}"))
        else:
            handle._buffer.append(message.feedback)
            handle._notify()

    def _on_status(self, message: Any) -> None:
        for status in message.status_list:
            handle = self.goals.get(_key(status.goal_info.goal_id))
            if handle is not None and not handle.done:
                handle.status = status.status

    def destroy(self) -> None:
        """Forget this client: its services and topics go away; goals already sent go on."""
        self.node.destroy_action_client(self)

    def _destroy_entities(self) -> None:
        for client in (self._send, self._cancel, self._results):
            client.destroy()
        for subscription in self._subscriptions:
            subscription.destroy()
