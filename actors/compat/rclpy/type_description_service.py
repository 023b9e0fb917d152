"""``rclpy.type_description_service``: a script node's ``~/get_type_description`` service, as rcl answers it.

Every rclpy node declares the read-only parameter
``start_type_description_service`` (true unless an override says otherwise)
and, while it is true, serves ``type_description_interfaces/srv/GetTypeDescription``
on ``~/get_type_description``.  A request names a type and its RIHS01 hash;
as in rcl the hash alone picks the type, among those the node uses (its
topics', services' and actions' types, its parameter services' and its own),
and the answer holds the type's description with the default values its
definition gives, those of the types it references, and with
``include_type_sources`` the definition texts they come from.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from actors.compat.rclpy.logging import get_logger
from actors.messages._fields import layout
from actors.messages.typehash import type_description, type_hash
from actors.ros._param_services import ParameterServices
from interfaces.rcl_interfaces.msg import ParameterDescriptor, ParameterEvent, ParameterType
from interfaces.type_description_interfaces.msg import (
    Field,
    FieldType,
    IndividualTypeDescription,
    TypeDescription,
    TypeSource,
)
from interfaces.type_description_interfaces.srv import GetTypeDescription

__all__ = ["START_TYPE_DESCRIPTION_SERVICE_PARAM", "TypeDescriptionService"]

START_TYPE_DESCRIPTION_SERVICE_PARAM = "start_type_description_service"
_HASH = re.compile(r"RIHS[0-9a-fA-F]{2}_[0-9a-fA-F]{64}")  # what rcl can parse (its version, then the hash)


class TypeDescriptionService:
    """Declares ``start_type_description_service`` on ``node`` and, if it is true, serves the descriptions.

    A value of another type than bool is logged as an error and leaves the
    service off, as rclpy does.
    """

    def __init__(self, node: Any) -> None:  # an rclpy Node (whose module imports this one)
        self._node = node
        self.service: Any = None
        if not node.has_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM):
            descriptor = ParameterDescriptor(
                name=START_TYPE_DESCRIPTION_SERVICE_PARAM,
                type=ParameterType.PARAMETER_BOOL,
                description="If enabled, start the ~/get_type_description service.",
                read_only=True,
            )
            node.declare_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM, True, descriptor)
        value = node.get_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM).value
        if not isinstance(value, bool):
            node.get_logger().error(
                f"Invalid type for parameter '{START_TYPE_DESCRIPTION_SERVICE_PARAM}' {value!r} should be bool"
            )
        elif value:
            self.service = node.create_service(GetTypeDescription, "~/get_type_description", self._answer)

    def _answer(self, request: Any, response: Any) -> Any:
        if not _HASH.fullmatch(request.type_hash):
            get_logger("rcl").error(f"Failed to parse type hash '{request.type_hash}'")
            response.successful = False
            response.failure_reason = "Failed to parse type hash"
            return response
        found = next((t for t in self._types_in_use() if type_hash(t) == request.type_hash), None)
        if found is None:
            response.successful = False
            response.failure_reason = "Type not currently in use by this node"
            return response
        described = type_description(found)
        classes = dict(_classes(found))
        response.type_description = TypeDescription(
            type_description=_individual(described["type_description"], classes),
            referenced_type_descriptions=[_individual(d, classes) for d in described["referenced_type_descriptions"]],
        )
        if request.include_type_sources:
            # The files the types come from: the one asked for, then the messages it uses, by name
            # (a service's request or an action's goal is part of its file, not one of its own).
            files = [found.__ros_type__, *sorted(name for name in classes if "/msg/" in name)]
            response.type_sources = [
                TypeSource(
                    type_name=name, encoding=kind, raw_file_contents=classes[name].__ros_definition__.removesuffix("\n")
                )
                for name in dict.fromkeys(files)
                for kind in [name.split("/")[1]]
            ]
        response.successful = True
        return response

    def _types_in_use(self) -> Iterator[type[Any]]:
        core = self._node._core
        yield from (publisher.msg_type for publisher in core.publishers)
        yield from (subscription.msg_type for subscription in core.subscriptions)
        yield from (service.srv_type for service in core.services)
        yield from (client.srv_type for client in core.clients)
        yield from (server.action_type for server in core.action_servers)
        yield from (client.action_type for client in core.action_clients)
        yield ParameterEvent
        yield from ParameterServices.kinds.values()
        yield GetTypeDescription


def _classes(type_: type[Any]) -> Iterator[tuple[str, type[Any]]]:
    """``type_`` and every type it is made of, by ROS name (a service's parts, a message's nested ones...)."""
    yield type_.__ros_type__, type_
    if hasattr(type_, "Goal"):
        impl = type_.Impl
        parts = [type_.Goal, type_.Result, type_.Feedback, impl.SendGoalService, impl.GetResultService]
        parts.append(impl.FeedbackMessage)
    elif hasattr(type_, "Request"):
        parts = [type_.Request, type_.Response]
    else:
        parts = [field.nested.cls for field in layout(type_).fields if field.nested is not None]
    for part in parts:
        yield from _classes(part)


def _individual(described: dict[str, Any], classes: dict[str, type[Any]]) -> IndividualTypeDescription:
    defaults = _defaults(classes.get(described["type_name"]))
    return IndividualTypeDescription(
        type_name=described["type_name"],
        fields=[
            Field(name=f["name"], type=FieldType(**f["type"]), default_value=defaults.get(f["name"], ""))
            for f in described["fields"]
        ],
    )


def _defaults(cls: type[Any] | None) -> dict[str, str]:
    """A message's default values as rosidl writes them: Python's text of the value, a tuple for an array."""
    try:
        fields = layout(cls).spec.fields if cls is not None else ()
    except TypeError:  # a service's or an action's own type: its fields are whole messages
        return {}
    return {
        f.name: str(tuple(f.default) if isinstance(f.default, (list, bytes)) else f.default)
        for f in fields
        if f.default is not None
    }
