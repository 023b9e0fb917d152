"""actors: ROS 2's programming model as a pure-Python asyncio runtime.

The names below load on first use (PEP 562): ``python -m actors.run`` and the
``actors`` command import this package before anything else, and they must be
able to take a signal before the runtime's modules load, the slow part of
their start-up.
"""

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from actors.system._exports import *  # noqa: F403

__all__ = [
    "ActionClient",
    "ActionError",
    "ActionServer",
    "ActorsError",
    "AsyncParameterClient",
    "CancelResponse",
    "ClientGoalHandle",
    "GoalResponse",
    "ServerGoalHandle",
    "Client",
    "Clock",
    "ClockType",
    "Duration",
    "DurabilityPolicy",
    "EndpointInfo",
    "Escalation",
    "GraphFileError",
    "GraphView",
    "HistoryPolicy",
    "InvalidNameError",
    "LoggingSeverity",
    "MessageRefused",
    "Node",
    "Parameter",
    "ParameterError",
    "ParameterType",
    "NodeInfo",
    "Publisher",
    "QoSProfile",
    "ROSClock",
    "Rate",
    "ReliabilityPolicy",
    "RestartType",
    "Runtime",
    "Service",
    "ServiceError",
    "Strategy",
    "Subscription",
    "SupervisorPolicy",
    "Time",
    "Timer",
    "TopicInfo",
    "TopicTypeError",
    "VirtualTimeDeadlock",
    "VirtualTimeLoop",
    "qos_profile_sensor_data",
    "qos_profile_system_default",
]


def __getattr__(name: str) -> Any:
    if name not in __all__:
        raise AttributeError(f"module 'actors' has no attribute {name!r}")
    from actors.system import _exports

    value = getattr(_exports, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
