"""actors: ROS 2's programming model as a pure-Python asyncio runtime."""

from actors.clock import Clock, Duration, Rate, Time, VirtualTimeLoop
from actors.errors import (
    ActorsError,
    Escalation,
    GraphFileError,
    InvalidNameError,
    ServiceError,
    TopicTypeError,
    VirtualTimeDeadlock,
)
from actors.introspection import EndpointInfo, GraphView, NodeInfo, TopicInfo
from actors.node import Node
from actors.runtime import Runtime
from actors.supervisor import RestartType, Strategy, SupervisorPolicy
from actors.timers import Timer
from actors.topics import (
    DurabilityPolicy,
    HistoryPolicy,
    Publisher,
    QoSProfile,
    ReliabilityPolicy,
    Subscription,
    qos_profile_sensor_data,
    qos_profile_system_default,
)

__all__ = [
    "ActorsError",
    "Clock",
    "Duration",
    "DurabilityPolicy",
    "EndpointInfo",
    "Escalation",
    "GraphFileError",
    "GraphView",
    "HistoryPolicy",
    "InvalidNameError",
    "Node",
    "NodeInfo",
    "Publisher",
    "QoSProfile",
    "Rate",
    "ReliabilityPolicy",
    "RestartType",
    "Runtime",
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
