"""The field layout of a generated message class: exact ROS field types and nested layouts, cached.

A generated struct's annotations say ``int`` for every integer width and
``list`` for every kind of array; the wire format and the type hash need the
ROS types themselves (``int32`` or ``int64``, ``float64[9]``,
``string<=10``).  :func:`layout` reads them once per class from the class's
``__ros_definition__`` (the raw ``.msg`` text) and pairs each field with the
layout of its nested class, taken from the struct's own annotations, so a
user's root that shadows a shipped package nests its own classes.

A message without fields gets rosidl's one-byte placeholder field
``structure_needs_at_least_one_member`` (uint8): ROS puts it on the wire and
into the type description, though the Python class has no such attribute.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TypeVar

import msgspec.inspect as mi

from actors.errors import InterfaceError
from actors.messages.idl import Field, FieldType, MessageSpec, parse_message

__all__ = ["FieldLayout", "MessageLayout", "PLACEHOLDER", "layout"]

if TYPE_CHECKING:
    _F = TypeVar("_F", bound=Callable[..., Any])

    # functools.cache, as mypy sees it: the function's own signature.  typeshed's wrapper takes
    # Hashable arguments, and mypy counts no class object (type[T]) as Hashable.
    def _cache(function: _F) -> _F: ...
else:
    _cache = functools.cache

#: The field rosidl adds to a message that has none.
PLACEHOLDER = Field("structure_needs_at_least_one_member", FieldType("uint8"), None, 0)


@dataclass(frozen=True, slots=True)
class FieldLayout:
    """One field: its name, its ROS type, and for a message-typed field the element's layout."""

    name: str
    type: FieldType
    nested: MessageLayout | None


@dataclass(frozen=True, slots=True)
class MessageLayout:
    """A message class with its ROS name, parsed definition and fields in wire order.

    ``placeholder`` is True for a message without fields: its only field is
    :data:`PLACEHOLDER`, which the class itself does not have.
    """

    cls: type
    ros_type: str
    spec: MessageSpec
    fields: tuple[FieldLayout, ...]
    placeholder: bool


@_cache
def layout(cls: type) -> MessageLayout:
    """The layout of a generated message class (a ``Request``/``Response`` or action part too).

    Raises TypeError for a class that is not a generated message, and
    InterfaceError when its annotations disagree with its definition (a
    hand-edited module).
    """
    ros_type = getattr(cls, "__ros_type__", None)
    definition = getattr(cls, "__ros_definition__", None)
    if not isinstance(ros_type, str) or not isinstance(definition, str) or ros_type.count("/") != 2:
        raise TypeError(f"{cls!r} is not a generated message type")
    try:
        info = mi.type_info(cls)
    except (TypeError, ValueError):
        info = None
    if not isinstance(info, mi.StructType):
        raise TypeError(f"{cls!r} is not a generated message type (a service or action has no layout of its own)")
    pkg, kind, name = ros_type.split("/")
    spec = parse_message(definition, path=ros_type, pkg=pkg, name=name, kind=kind)
    annotations = {field.name: field.type for field in info.fields}
    if [field.name for field in spec.fields] != list(annotations):
        raise InterfaceError(f"{ros_type}: the class's fields differ from its definition")
    fields = tuple(
        FieldLayout(
            field.name, field.type, _nested(annotations[field.name], ros_type) if field.type.is_nested else None
        )
        for field in spec.fields
    )
    if not fields:
        return MessageLayout(cls, ros_type, spec, (FieldLayout(PLACEHOLDER.name, PLACEHOLDER.type, None),), True)
    return MessageLayout(cls, ros_type, spec, fields, False)


def _nested(info: mi.Type, owner: str) -> MessageLayout:
    element = info.item_type if isinstance(info, mi.ListType) else info
    if not isinstance(element, mi.StructType):
        raise InterfaceError(f"{owner}: a message-typed field is annotated {info!r}")
    return layout(element.cls)
