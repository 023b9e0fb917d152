"""``rclpy.parameter_event_handler``: callbacks on ``/parameter_events``, per parameter or per event.

A ParameterEventHandler subscribes its node to ``/parameter_events``.  Each
event it receives is offered first to the callbacks registered for one
parameter of one node (they get that parameter, as the event carries it: an
``rcl_interfaces/msg/Parameter``), then to the callbacks registered for every
event (they get the event).  The newest callback registered runs first, as in
rclpy.  Node names given without a leading slash are taken relative to the
handler's node's namespace; an empty name is the handler's node itself.
"""

from __future__ import annotations

import itertools
import threading
from collections import defaultdict
from collections.abc import Callable, Iterator
from typing import Any

from actors.ros.qos import qos_profile_parameter_events
from interfaces.rcl_interfaces.msg import ParameterEvent

__all__ = ["ParameterCallbackHandle", "ParameterEventCallbackHandle", "ParameterEventHandler"]

_EVENTS_TOPIC = "/parameter_events"


class ParameterCallbackHandle:
    """What ``add_parameter_callback`` returns: keep it to remove the callback."""

    def __init__(self, parameter_name: str, node_name: str, callback: Callable[[Any], None]) -> None:
        self.parameter_name = parameter_name
        self.node_name = node_name
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventCallbackHandle:
    """What ``add_parameter_event_callback`` returns: keep it to remove the callback."""

    def __init__(self, callback: Callable[[Any], None]) -> None:
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventHandler:
    """Runs callbacks when parameters change, on any node of the graph (see the module's docstring)."""

    class Callbacks:
        """The registered callbacks: ``parameter_callbacks`` by (parameter, node), ``event_callbacks``."""

        def __init__(self) -> None:
            self.parameter_callbacks: defaultdict[tuple[str, str], list[ParameterCallbackHandle]] = defaultdict(list)
            self.event_callbacks: list[ParameterEventCallbackHandle] = []
            self.mutex = threading.RLock()  # a callback may register or remove others

        def event_callback(self, event: Any) -> None:
            """Offer ``event`` to the parameter callbacks it concerns, then to every event callback."""
            with self.mutex:
                for (parameter_name, node_name), handles in list(self.parameter_callbacks.items()):
                    parameter = ParameterEventHandler.get_parameter_from_event(event, parameter_name, node_name)
                    if parameter is None:
                        continue
                    for handle in list(handles):
                        with handle.mutex:
                            handle.callback(parameter)
                for event_handle in list(self.event_callbacks):
                    with event_handle.mutex:
                        event_handle.callback(event)

        def add_parameter_callback(
            self, parameter_name: str, node_name: str, callback: Callable[[Any], None]
        ) -> ParameterCallbackHandle:
            """Register ``callback`` for ``parameter_name`` of the node ``node_name`` (a full name)."""
            handle = ParameterCallbackHandle(parameter_name, node_name, callback)
            with self.mutex:
                self.parameter_callbacks[(parameter_name, node_name)].insert(0, handle)
            return handle

        def remove_parameter_callback(self, handle: ParameterCallbackHandle) -> None:
            """Forget ``handle``'s callback; RuntimeError if it is not registered."""
            key = (handle.parameter_name, handle.node_name)
            with self.mutex:
                handles = self.parameter_callbacks.get(key, [])
                if handle not in handles:
                    raise RuntimeError("Callback doesn't exist")
                handles.remove(handle)
                if not handles:
                    del self.parameter_callbacks[key]

        def add_parameter_event_callback(self, callback: Callable[[Any], None]) -> ParameterEventCallbackHandle:
            """Register ``callback`` for every event."""
            handle = ParameterEventCallbackHandle(callback)
            with self.mutex:
                self.event_callbacks.insert(0, handle)
            return handle

        def remove_parameter_event_callback(self, handle: ParameterEventCallbackHandle) -> None:
            """Forget ``handle``'s callback; RuntimeError if it is not registered."""
            with self.mutex:
                if handle not in self.event_callbacks:
                    raise RuntimeError("Callback doesn't exist")
                self.event_callbacks.remove(handle)

    def __init__(
        self,
        node: Any,
        qos_profile: Any = qos_profile_parameter_events,
        callback_group: Any = None,
        event_callbacks: Any = None,
        qos_overriding_options: Any = None,
        raw: bool = False,
    ) -> None:
        self.node = node
        self.qos_profile = qos_profile
        self._callbacks = ParameterEventHandler.Callbacks()
        options: dict[str, Any] = {"callback_group": callback_group, "raw": raw}
        if event_callbacks is not None:
            options["event_callbacks"] = event_callbacks
        if qos_overriding_options is not None:
            options["qos_overriding_options"] = qos_overriding_options
        self.parameter_event_subscription = node.create_subscription(
            ParameterEvent, _EVENTS_TOPIC, self._callbacks.event_callback, qos_profile, **options
        )

    def destroy(self) -> None:
        """Stop listening to ``/parameter_events``."""
        self.node.destroy_subscription(self.parameter_event_subscription)

    @staticmethod
    def get_parameter_from_event(event: Any, parameter_name: str, node_name: str) -> Any | None:
        """The parameter ``parameter_name`` that ``event`` says is new or changed on ``node_name``, or None."""
        if event.node != node_name:
            return None
        return next(
            (p for p in ParameterEventHandler.get_parameters_from_event(event) if p.name == parameter_name), None
        )

    @staticmethod
    def get_parameters_from_event(event: Any) -> Iterator[Any]:
        """The parameters ``event`` says are new, then those it says changed."""
        return itertools.chain(event.new_parameters, event.changed_parameters)

    def add_parameter_callback(
        self, parameter_name: str, node_name: str, callback: Callable[[Any], None]
    ) -> ParameterCallbackHandle:
        """Call ``callback(parameter)`` when ``parameter_name`` of ``node_name`` is declared or set."""
        return self._callbacks.add_parameter_callback(parameter_name, self._resolve_path(node_name), callback)

    def remove_parameter_callback(self, handle: ParameterCallbackHandle) -> None:
        """Stop calling ``handle``'s callback; RuntimeError if it is not registered."""
        self._callbacks.remove_parameter_callback(handle)

    def add_parameter_event_callback(self, callback: Callable[[Any], None]) -> ParameterEventCallbackHandle:
        """Call ``callback(event)`` for every parameter event of the graph."""
        return self._callbacks.add_parameter_event_callback(callback)

    def remove_parameter_event_callback(self, handle: ParameterEventCallbackHandle) -> None:
        """Stop calling ``handle``'s callback; RuntimeError if it is not registered."""
        self._callbacks.remove_parameter_event_callback(handle)

    def _resolve_path(self, node_path: str | None = None) -> str:
        # A node's full name: the handler's own for none, relative names under its namespace.
        if not node_path:
            return str(self.node.get_fully_qualified_name())
        if node_path.startswith("/"):
            return node_path
        namespace = self.node.get_namespace().rstrip("/")
        return f"{namespace}/{node_path}"
