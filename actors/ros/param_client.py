"""AsyncParameterClient: read and change another node's parameters through its parameter services, as rclpy's."""

from __future__ import annotations

import asyncio
import functools
from collections.abc import Callable, Sequence
from typing import Any

import anyio

from actors.core._actor import OneShot
from actors.ros.parameter_store import Parameter
from actors.ros.qos import QoSProfile, qos_profile_parameter_events
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.msg import ParameterEvent
from interfaces.rcl_interfaces.srv import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    SetParameters,
    SetParametersAtomically,
)

__all__ = ["AsyncParameterClient"]

Done = Callable[[asyncio.Future[Any]], Any]


class AsyncParameterClient:
    """A client of the parameter services of the node ``remote_node_name``, on behalf of ``node``.

    Each request method returns the future of the service's response (await
    it, or pass ``callback``: it is called with the done future in ``node``'s
    task, like the node's other callbacks).  ``remote_node_name`` resolves as a
    service name does: relative to ``node``'s namespace unless it starts with
    ``/``.  ``load_parameter_file`` is not here: parameter files belong to the
    rclpy layer.
    """

    def __init__(self, node: Any, remote_node_name: str) -> None:
        self.node = node
        self.remote_node_name = remote_node_name
        prefix = remote_node_name.rstrip("/")
        self._get = node.create_client(GetParameters, f"{prefix}/get_parameters")
        self._list = node.create_client(ListParameters, f"{prefix}/list_parameters")
        self._set = node.create_client(SetParameters, f"{prefix}/set_parameters")
        self._types = node.create_client(GetParameterTypes, f"{prefix}/get_parameter_types")
        self._describe = node.create_client(DescribeParameters, f"{prefix}/describe_parameters")
        self._atomic = node.create_client(SetParametersAtomically, f"{prefix}/set_parameters_atomically")
        self._clients = (self._get, self._list, self._set, self._types, self._describe, self._atomic)

    def services_are_ready(self) -> bool:
        """Whether every parameter service of the remote node exists now."""
        return all(client.service_is_ready() for client in self._clients)

    async def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Wait until every parameter service exists; False if ``timeout_sec`` passes first."""
        with anyio.move_on_after(timeout_sec):
            for client in self._clients:
                await client.wait_for_service()
        return self.services_are_ready()

    def _call(self, client: Any, request: Any, callback: Done | None) -> asyncio.Future[Any]:
        future = client.call_async(request)
        if callback is not None:
            actor = client.node.actor
            future.add_done_callback(
                lambda done: actor.schedule(OneShot(functools.partial(callback, done), "parameter client callback"))
            )
        return future

    def list_parameters(
        self, prefixes: Sequence[str] | None = None, depth: int | None = None, callback: Done | None = None
    ) -> asyncio.Future[Any]:
        """The names under ``prefixes`` (all when None), at most ``depth`` parts deep (None: any)."""
        request = ListParameters.Request(prefixes=list(prefixes or []), depth=depth or 0)
        return self._call(self._list, request, callback)

    def get_parameters(self, names: Sequence[str], callback: Done | None = None) -> asyncio.Future[Any]:
        """The values of ``names`` (``response.values``, NOT_SET for an unknown name)."""
        return self._call(self._get, GetParameters.Request(names=list(names)), callback)

    def get_parameter_types(self, names: Sequence[str], callback: Done | None = None) -> asyncio.Future[Any]:
        """The types of ``names`` (``response.types``)."""
        return self._call(self._types, GetParameterTypes.Request(names=list(names)), callback)

    def describe_parameters(self, names: Sequence[str], callback: Done | None = None) -> asyncio.Future[Any]:
        """The descriptors of ``names`` (``response.descriptors``)."""
        return self._call(self._describe, DescribeParameters.Request(names=list(names)), callback)

    def set_parameters(
        self, parameters: Sequence[Parameter | ParameterMsg], callback: Done | None = None
    ) -> asyncio.Future[Any]:
        """Set each parameter on its own (``response.results``, one per parameter)."""
        return self._call(self._set, SetParameters.Request(parameters=_msgs(parameters)), callback)

    def set_parameters_atomically(
        self, parameters: Sequence[Parameter | ParameterMsg], callback: Done | None = None
    ) -> asyncio.Future[Any]:
        """Set all parameters or none (``response.result``)."""
        return self._call(self._atomic, SetParametersAtomically.Request(parameters=_msgs(parameters)), callback)

    def delete_parameters(self, names: Sequence[str], callback: Done | None = None) -> asyncio.Future[Any]:
        """Unset ``names`` (only dynamically typed parameters can be; ``response.results``)."""
        return self.set_parameters([Parameter(name) for name in names], callback)

    def on_parameter_event(
        self, callback: Callable[[ParameterEvent], Any], qos_profile: QoSProfile | int = qos_profile_parameter_events
    ) -> Any:
        """Subscribe ``callback`` to ``/parameter_events`` (every node's parameter changes)."""
        return self.node.create_subscription(ParameterEvent, "/parameter_events", callback, qos_profile)


def _msgs(parameters: Sequence[Parameter | ParameterMsg]) -> list[ParameterMsg]:
    return [p.to_parameter_msg() if isinstance(p, Parameter) else p for p in parameters]
