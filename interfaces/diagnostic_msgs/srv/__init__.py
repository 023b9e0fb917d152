"""Generated from diagnostic_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.diagnostic_msgs.msg import DiagnosticStatus
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "AddDiagnostics",
    "AddDiagnostics_Event",
    "AddDiagnostics_Request",
    "AddDiagnostics_Response",
    "SelfTest",
    "SelfTest_Event",
    "SelfTest_Request",
    "SelfTest_Response",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class AddDiagnostics_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/AddDiagnostics_Request``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/AddDiagnostics_Request"
    __ros_definition__: ClassVar[str] = (
        "# This service is used as part of the process for loading analyzers at runtime,\n"
        "# and should be used by a loader script or program, not as a standalone service.\n"
        "# Information about dynamic addition of analyzers can be found at\n"
        "# http://wiki.ros.org/diagnostics/Tutorials/Adding%20Analyzers%20at%20Runtime\n"
        "\n"
        "# The load_namespace parameter defines the namespace where parameters for the\n"
        "# initialization of analyzers in the diagnostic aggregator have been loaded. The\n"
        "# value should be a global name (i.e. /my/name/space), not a relative\n"
        "# (my/name/space) or private (~my/name/space) name. Analyzers will not be added\n"
        "# if a non-global name is used. The call will also fail if the namespace\n"
        "# contains parameters that follow a namespace structure that does not conform to\n"
        "# that expected by the analyzer definitions. See\n"
        "# http://wiki.ros.org/diagnostics/Tutorials/Configuring%20Diagnostic%20Aggregators\n"
        "# and http://wiki.ros.org/diagnostics/Tutorials/Using%20the%20GenericAnalyzer\n"
        "# for examples of the structure of yaml files which are expected to have been\n"
        "# loaded into the namespace.\n"
        "string load_namespace\n"
    )

    load_namespace: str = ""


class AddDiagnostics_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/AddDiagnostics_Response``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/AddDiagnostics_Response"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# True if diagnostic aggregator was updated with new diagnostics, False\n"
        "# otherwise. A false return value means that either there is a bond in the\n"
        "# aggregator which already used the requested namespace, or the initialization\n"
        "# of analyzers failed.\n"
        "bool success\n"
        "\n"
        "# Message with additional information about the success or failure\n"
        "string message\n"
    )

    success: bool = False
    message: str = ""


class AddDiagnostics_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/AddDiagnostics_Event``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/AddDiagnostics_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "diagnostic_msgs/srv/AddDiagnostics_Request[<=1] request\n"
        "diagnostic_msgs/srv/AddDiagnostics_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[AddDiagnostics_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[AddDiagnostics_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class AddDiagnostics:
    """``diagnostic_msgs/srv/AddDiagnostics``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/AddDiagnostics"
    __ros_definition__: ClassVar[str] = (
        "# This service is used as part of the process for loading analyzers at runtime,\n"
        "# and should be used by a loader script or program, not as a standalone service.\n"
        "# Information about dynamic addition of analyzers can be found at\n"
        "# http://wiki.ros.org/diagnostics/Tutorials/Adding%20Analyzers%20at%20Runtime\n"
        "\n"
        "# The load_namespace parameter defines the namespace where parameters for the\n"
        "# initialization of analyzers in the diagnostic aggregator have been loaded. The\n"
        "# value should be a global name (i.e. /my/name/space), not a relative\n"
        "# (my/name/space) or private (~my/name/space) name. Analyzers will not be added\n"
        "# if a non-global name is used. The call will also fail if the namespace\n"
        "# contains parameters that follow a namespace structure that does not conform to\n"
        "# that expected by the analyzer definitions. See\n"
        "# http://wiki.ros.org/diagnostics/Tutorials/Configuring%20Diagnostic%20Aggregators\n"
        "# and http://wiki.ros.org/diagnostics/Tutorials/Using%20the%20GenericAnalyzer\n"
        "# for examples of the structure of yaml files which are expected to have been\n"
        "# loaded into the namespace.\n"
        "string load_namespace\n"
        "---\n"
        "\n"
        "# True if diagnostic aggregator was updated with new diagnostics, False\n"
        "# otherwise. A false return value means that either there is a bond in the\n"
        "# aggregator which already used the requested namespace, or the initialization\n"
        "# of analyzers failed.\n"
        "bool success\n"
        "\n"
        "# Message with additional information about the success or failure\n"
        "string message\n"
    )
    Request = AddDiagnostics_Request
    Response = AddDiagnostics_Response
    Event = AddDiagnostics_Event


class SelfTest_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/SelfTest_Request``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/SelfTest_Request"
    __ros_definition__: ClassVar[str] = ""


class SelfTest_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/SelfTest_Response``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/SelfTest_Response"
    __ros_definition__: ClassVar[str] = (
        "string id\n"
        "byte passed\n"
        "DiagnosticStatus[] status\n"
    )

    id: str = ""
    passed: _uint8 = 0
    status: list[DiagnosticStatus] = msgspec.field(default_factory=list)


class SelfTest_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/srv/SelfTest_Event``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/SelfTest_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "diagnostic_msgs/srv/SelfTest_Request[<=1] request\n"
        "diagnostic_msgs/srv/SelfTest_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SelfTest_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SelfTest_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SelfTest:
    """``diagnostic_msgs/srv/SelfTest``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/srv/SelfTest"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "string id\n"
        "byte passed\n"
        "DiagnosticStatus[] status\n"
    )
    Request = SelfTest_Request
    Response = SelfTest_Response
    Event = SelfTest_Event
