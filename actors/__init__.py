"""actors: ROS 2's programming model as a pure-Python asyncio runtime."""

from actors.actions import (
    ActionClient,
    ActionServer,
    CancelResponse,
    ClientGoalHandle,
    GoalResponse,
    ServerGoalHandle,
)
from actors.clock import Clock, ClockType, Duration, Rate, ROSClock, Time, VirtualTimeLoop
from actors.errors import (
    ActionError,
    ActorsError,
    Escalation,
    GraphFileError,
    InvalidNameError,
    MessageRefused,
    ParameterError,
    ServiceError,
    TopicTypeError,
    VirtualTimeDeadlock,
)
from actors.introspection import EndpointInfo, GraphView, NodeInfo, TopicInfo
from actors.log import LoggingSeverity
from actors.node import Node
from actors.param_client import AsyncParameterClient
from actors.params import Parameter, ParameterType
from actors.runtime import Runtime
from actors.services import Client, Service
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
