"""Generated from lifecycle_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.lifecycle_msgs.msg import State, Transition, TransitionDescription
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "ChangeState",
    "ChangeState_Event",
    "ChangeState_Request",
    "ChangeState_Response",
    "GetAvailableStates",
    "GetAvailableStates_Event",
    "GetAvailableStates_Request",
    "GetAvailableStates_Response",
    "GetAvailableTransitions",
    "GetAvailableTransitions_Event",
    "GetAvailableTransitions_Request",
    "GetAvailableTransitions_Response",
    "GetState",
    "GetState_Event",
    "GetState_Request",
    "GetState_Response",
]


class ChangeState_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/ChangeState_Request``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/ChangeState_Request"
    __ros_definition__: ClassVar[str] = (
        "# The requested transition.\n"
        "#\n"
        "# This change state service will fail if the transition is not possible.\n"
        "Transition transition\n"
    )

    transition: Transition = msgspec.field(default_factory=Transition)


class ChangeState_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/ChangeState_Response``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/ChangeState_Response"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# Indicates whether the service was able to initiate the state transition\n"
        "bool success\n"
    )

    success: bool = False


class ChangeState_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/ChangeState_Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/ChangeState_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "lifecycle_msgs/srv/ChangeState_Request[<=1] request\n"
        "lifecycle_msgs/srv/ChangeState_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[ChangeState_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[ChangeState_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class ChangeState:
    """``lifecycle_msgs/srv/ChangeState``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/ChangeState"
    __ros_definition__: ClassVar[str] = (
        "# The requested transition.\n"
        "#\n"
        "# This change state service will fail if the transition is not possible.\n"
        "Transition transition\n"
        "---\n"
        "\n"
        "# Indicates whether the service was able to initiate the state transition\n"
        "bool success\n"
    )
    Request = ChangeState_Request
    Response = ChangeState_Response
    Event = ChangeState_Event


class GetAvailableStates_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableStates_Request``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableStates_Request"
    __ros_definition__: ClassVar[str] = ""


class GetAvailableStates_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableStates_Response``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableStates_Response"
    __ros_definition__: ClassVar[str] = (
        "# Array of possible states that can be transitioned to.\n"
        "State[] available_states\n"
    )

    available_states: list[State] = msgspec.field(default_factory=list)


class GetAvailableStates_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableStates_Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableStates_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "lifecycle_msgs/srv/GetAvailableStates_Request[<=1] request\n"
        "lifecycle_msgs/srv/GetAvailableStates_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetAvailableStates_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetAvailableStates_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetAvailableStates:
    """``lifecycle_msgs/srv/GetAvailableStates``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableStates"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "# Array of possible states that can be transitioned to.\n"
        "State[] available_states\n"
    )
    Request = GetAvailableStates_Request
    Response = GetAvailableStates_Response
    Event = GetAvailableStates_Event


class GetAvailableTransitions_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableTransitions_Request``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableTransitions_Request"
    __ros_definition__: ClassVar[str] = ""


class GetAvailableTransitions_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableTransitions_Response``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableTransitions_Response"
    __ros_definition__: ClassVar[str] = (
        "# An array of the possible start_state-goal_state transitions\n"
        "TransitionDescription[] available_transitions\n"
    )

    available_transitions: list[TransitionDescription] = msgspec.field(default_factory=list)


class GetAvailableTransitions_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetAvailableTransitions_Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableTransitions_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "lifecycle_msgs/srv/GetAvailableTransitions_Request[<=1] request\n"
        "lifecycle_msgs/srv/GetAvailableTransitions_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetAvailableTransitions_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetAvailableTransitions_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetAvailableTransitions:
    """``lifecycle_msgs/srv/GetAvailableTransitions``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetAvailableTransitions"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "# An array of the possible start_state-goal_state transitions\n"
        "TransitionDescription[] available_transitions\n"
    )
    Request = GetAvailableTransitions_Request
    Response = GetAvailableTransitions_Response
    Event = GetAvailableTransitions_Event


class GetState_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetState_Request``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetState_Request"
    __ros_definition__: ClassVar[str] = ""


class GetState_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetState_Response``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetState_Response"
    __ros_definition__: ClassVar[str] = (
        "# The current state-machine state of the node.\n"
        "State current_state\n"
    )

    current_state: State = msgspec.field(default_factory=State)


class GetState_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/srv/GetState_Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetState_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "lifecycle_msgs/srv/GetState_Request[<=1] request\n"
        "lifecycle_msgs/srv/GetState_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetState_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetState_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetState:
    """``lifecycle_msgs/srv/GetState``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/srv/GetState"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "# The current state-machine state of the node.\n"
        "State current_state\n"
    )
    Request = GetState_Request
    Response = GetState_Response
    Event = GetState_Event
