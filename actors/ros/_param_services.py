"""A node's parameter services, as every rclpy node has them, answered from its ParameterStore."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, ClassVar, Protocol

from actors.core._actor import Owner
from actors.errors import ParameterNotDeclaredException
from actors.ros.parameter_store import Parameter, ParameterStore
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from interfaces.rcl_interfaces.srv import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    SetParameters,
    SetParametersAtomically,
)

__all__ = ["ServiceHost", "DeferringHost", "ParameterServices", "serve"]


class ServiceHost(Protocol):
    """Who serves them: a node (``~/`` names resolve under it)."""

    def create_service(self, srv_type: type[Any], name: str, handler: Callable[[Any, Any], Any]) -> Any: ...


class DeferringHost(ServiceHost, Owner, Protocol):
    """A node that may register services now and build them when first needed."""

    fqn: str

    @property
    def params(self) -> ParameterStore: ...

    def defer_services(self, deferred: ParameterServices) -> bool: ...


def serve(host: DeferringHost) -> None:
    """Serve ``~/describe_parameters``, ``~/get_parameters``, ``~/get_parameter_types``,
    ``~/list_parameters``, ``~/set_parameters`` and ``~/set_parameters_atomically`` from ``host.params``.

    Unlike rclpy's, ``get_parameters`` answers an unknown name with a NOT_SET
    value in its place (rclpy answers nothing at all), so one unknown name does
    not hide the others.  A set of an undeclared name is an unsuccessful result,
    as in rclpy, never an error.  The six are listed and callable at once, but
    built only when something first needs one (see
    :class:`actors.services.ServiceTable`): every node has them, hardly any is
    called, and building them was a third of the cost of spawning a node.
    """
    services = ParameterServices(host)
    if not host.defer_services(services):
        services.build()


class ParameterServices:
    """A node's six parameter services as one object, whose bound methods are their handlers."""

    __slots__ = ("owner",)

    # Last name segment -> (type, handler), in the order rclpy creates them.
    _SERVED: ClassVar[dict[str, tuple[type[Any], str]]] = {
        "describe_parameters": (DescribeParameters, "describe"),
        "get_parameters": (GetParameters, "get"),
        "get_parameter_types": (GetParameterTypes, "get_types"),
        "list_parameters": (ListParameters, "list_names"),
        "set_parameters": (SetParameters, "set_each"),
        "set_parameters_atomically": (SetParametersAtomically, "set_all"),
    }
    kinds: ClassVar[dict[str, type[Any]]] = {kind: srv_type for kind, (srv_type, _) in _SERVED.items()}

    def __init__(self, owner: DeferringHost) -> None:
        self.owner = owner

    @property
    def store(self) -> ParameterStore:
        """The owner's parameters (read when a call comes: a node makes its store at first use)."""
        return self.owner.params

    def build(self) -> None:
        """Create the six services on the owner."""
        for kind, (srv_type, handler) in self._SERVED.items():
            self.owner.create_service(srv_type, "~/" + kind, getattr(self, handler))

    def get(self, request: Any, response: Any) -> Any:
        response.values = [self.store.get_or(name).get_parameter_value() for name in request.names]
        return response

    def get_types(self, request: Any, response: Any) -> Any:
        response.types = [int(self.store.get_or(name).type_) for name in request.names]
        return response

    def set_each(self, request: Any, response: Any) -> Any:
        response.results = [_set(self.store, [msg]) for msg in request.parameters]
        return response

    def set_all(self, request: Any, response: Any) -> Any:
        response.result = _set(self.store, request.parameters)
        return response

    def list_names(self, request: Any, response: Any) -> Any:
        response.result = self.store.list_parameters(request.prefixes, request.depth)
        return response

    def describe(self, request: Any, response: Any) -> Any:
        store = self.store
        response.descriptors = [
            store.describe(name) if store.has(name) else ParameterDescriptor(name=name) for name in request.names
        ]
        return response


def _set(store: ParameterStore, msgs: Sequence[ParameterMsg]) -> SetParametersResult:
    try:
        return store.set_atomically([Parameter.from_parameter_msg(m) for m in msgs])
    except (ParameterNotDeclaredException, ValueError, TypeError) as exc:
        return SetParametersResult(successful=False, reason=str(exc))
