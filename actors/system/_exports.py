"""What ``actors`` re-exports, loaded on the first use of one of its names (see actors/__init__.py)."""

from actors.core.loops import VirtualTimeLoop
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
from actors.ros.actions import (
    ActionClient,
    ActionServer,
    CancelResponse,
    ClientGoalHandle,
    GoalResponse,
    ServerGoalHandle,
)
from actors.ros.log import LoggingSeverity
from actors.ros.node import Node
from actors.ros.param_client import AsyncParameterClient
from actors.ros.parameter_store import Parameter, ParameterType
from actors.ros.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
    qos_profile_system_default,
)
from actors.ros.time import Clock, ClockType, Duration, Rate, ROSClock, Time
from actors.ros.timers import Timer
from actors.ros.topics import Publisher, Subscription
from actors.runtime import Runtime
from actors.services import Client, Service
from actors.system.introspection import EndpointInfo, GraphView, NodeInfo, TopicInfo
from actors.system.supervisor import RestartType, Strategy, SupervisorPolicy
