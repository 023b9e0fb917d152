"""RIHS01 type hashes (REP 2016): a type's description and every type it references, hashed with SHA-256.

ROS 2 names a type on the wire by a hash of its *type description*: for the
type itself and for each type it references (transitively, sorted by name),
the type's name and its fields, each field with its name, a numeric type id
(``type_description_interfaces/msg/FieldType``), its array capacity, its
string bound and its nested type's name.  Default values and comments do not
count.  The JSON text of that description, written with ``", "`` and
``": "`` separators and no other spacing, is what SHA-256 hashes.

A service is described as a type with three fields, ``request_message``,
``response_message`` and ``event_message``; the event type
(``Name_Event``: ``service_msgs/ServiceEventInfo info``, at most one
request, at most one response) exists in the description even where no code
uses it.  An action is described by its goal, result, feedback, the
``Name_SendGoal`` and ``Name_GetResult`` services and ``Name_FeedbackMessage``.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

from actors.messages._fields import MessageLayout, layout
from actors.messages.idl import FieldType

__all__ = ["FIELD_TYPE_IDS", "type_description", "type_hash"]

#: type_description_interfaces/msg/FieldType's ids of the single (non-array) types.
FIELD_TYPE_IDS: dict[str, int] = {
    "nested": 1,
    "int8": 2,
    "uint8": 3,
    "char": 3,
    "int16": 4,
    "uint16": 5,
    "int32": 6,
    "uint32": 7,
    "int64": 8,
    "uint64": 9,
    "float32": 10,
    "float64": 11,
    "bool": 15,
    "byte": 16,
    "string": 17,
    "wstring": 18,
    "bounded string": 21,
    "bounded wstring": 22,
}
# What an array kind adds to its element's id.
_ARRAY_OFFSETS = {None: 0, "fixed": 48, "bounded": 96, "unbounded": 144}
_EVENT_INFO = "service_msgs/msg/ServiceEventInfo"

Description = dict[str, Any]


def type_hash(type_: type[Any]) -> str:
    """``RIHS01_<64 hex digits>``, the hash ROS 2 gives ``type_`` (a message, service or action class).

    Raises TypeError for a class that is not a generated interface type.
    """
    text = json.dumps(type_description(type_), ensure_ascii=True, separators=(", ", ": "))
    return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()


def type_description(type_: type[Any]) -> Description:
    """The hashed form of ``type_``'s description: ``type_description`` and ``referenced_type_descriptions``.

    Field dicts hold ``name`` and ``type`` (``type_id``, ``capacity``,
    ``string_capacity``, ``nested_type_name``), as ROS hashes them.
    """
    known: dict[str, Description] = {}
    top = _describe(type_, known)
    referenced: set[str] = set()
    waiting = _nested_names(top)
    while waiting:
        name = waiting.pop()
        if name not in referenced:
            referenced.add(name)
            waiting += _nested_names(known[name])
    return {"type_description": top, "referenced_type_descriptions": [known[name] for name in sorted(referenced)]}


def _nested_names(description: Description) -> list[str]:
    return [f["type"]["nested_type_name"] for f in description["fields"] if f["type"]["nested_type_name"]]


def _describe(type_: type[Any], known: dict[str, Description]) -> Description:
    """``type_``'s own description; those of every type it uses go into ``known``."""
    if hasattr(type_, "Goal"):
        impl = type_.Impl
        parts = [
            ("goal", type_.Goal),
            ("result", type_.Result),
            ("feedback", type_.Feedback),
            ("send_goal_service", impl.SendGoalService),
            ("get_result_service", impl.GetResultService),
            ("feedback_message", impl.FeedbackMessage),
        ]
        return _composite(type_.__ros_type__, parts, known)
    if hasattr(type_, "Request"):
        return _service(type_, known)
    return _message(layout(type_), known)


def _composite(name: str, parts: list[tuple[str, type[Any]]], known: dict[str, Description]) -> Description:
    """A type whose fields are whole interfaces (a service's or an action's own description)."""
    fields = []
    for field_name, part in parts:
        _describe(part, known)
        fields.append(_field(field_name, 1, 0, 0, part.__ros_type__))
    known[name] = {"type_name": name, "fields": fields}
    return known[name]


def _service(service: type[Any], known: dict[str, Description]) -> Description:
    from interfaces.service_msgs.msg import ServiceEventInfo  # the shipped type every service's event uses

    name = service.__ros_type__
    event = f"{name}_Event"
    request, response = service.Request.__ros_type__, service.Response.__ros_type__
    bounded_nested = FIELD_TYPE_IDS["nested"] + _ARRAY_OFFSETS["bounded"]
    known[event] = {
        "type_name": event,
        "fields": [
            _field("info", FIELD_TYPE_IDS["nested"], 0, 0, _message(layout(ServiceEventInfo), known)["type_name"]),
            _field("request", bounded_nested, 1, 0, request),
            _field("response", bounded_nested, 1, 0, response),
        ],
    }
    _message(layout(service.Request), known)
    _message(layout(service.Response), known)
    fields = [
        _field("request_message", 1, 0, 0, request),
        _field("response_message", 1, 0, 0, response),
        _field("event_message", 1, 0, 0, event),
    ]
    known[name] = {"type_name": name, "fields": fields}
    return known[name]


def _message(lay: MessageLayout, known: dict[str, Description]) -> Description:
    if lay.ros_type not in known:
        known[lay.ros_type] = {
            "type_name": lay.ros_type,
            "fields": [_field(f.name, *_field_type(f.type)) for f in lay.fields],
        }
        for field in lay.fields:
            if field.nested is not None:
                _message(field.nested, known)
    return known[lay.ros_type]


def _field_type(type_: FieldType) -> tuple[int, int, int, str]:
    """type_id, capacity, string_capacity and nested_type_name of a field's type."""
    if type_.is_nested:
        single = FIELD_TYPE_IDS["nested"]
    elif type_.string_bound is not None:
        single = FIELD_TYPE_IDS[f"bounded {type_.base}"]
    else:
        single = FIELD_TYPE_IDS[type_.base]
    capacity = type_.size if type_.array in ("fixed", "bounded") else 0
    nested = type_.ros_type if type_.is_nested else ""
    return single + _ARRAY_OFFSETS[type_.array], capacity or 0, type_.string_bound or 0, nested


def _field(name: str, type_id: int, capacity: int, string_capacity: int, nested: str) -> Description:
    return {
        "name": name,
        "type": {
            "type_id": type_id,
            "capacity": capacity,
            "string_capacity": string_capacity,
            "nested_type_name": nested,
        },
    }
