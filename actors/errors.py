"""Every exception actors raises, in one place.

    ActorsError                      base of everything below
    ├── InterfaceError               a .msg/.srv/type problem
    │   ├── IdlError                 a syntax or type error at file:line
    │   ├── UnknownInterfaceError    no such type (``pkg/msg/Name``)
    │   └── MessageValidationError   a value does not fit its type (names the field path)
    │       └── CdrError             bytes that are not CDR of the type, or a value CDR cannot carry
    ├── InvalidNameError             a node, topic or service name breaks the ROS rules
    ├── TopicTypeError               publisher and subscription disagree on a topic's type
    ├── GraphFileError               graph.toml is malformed (names file and key path)
    ├── RosArgsError                 a --ros-args argument or a parameter file is malformed
    ├── WorldError                   a robot without a world, a start pose that does not fit
    │   └── WorldFileError           a world file is malformed (names file and key path)
    ├── ServiceError                 a service call failed on the server's side
    ├── ActionError                  a goal cannot do what was asked (rejected, invalid transition)
    ├── ParameterError               a parameter is undeclared, or already declared
    ├── ControlError                 the command line cannot reach or use a running graph
    ├── VirtualTimeDeadlock          virtual time has nothing left to wait for
    └── Escalation                   the supervisor gave up: too many restarts

A ``TypeError`` (not an ActorsError) is raised for a message of the wrong type,
as Python itself would, and ``TimeoutError`` for a call that timed out.
"""

from __future__ import annotations

__all__ = [
    "ActorsError",
    "InterfaceError",
    "IdlError",
    "UnknownInterfaceError",
    "MessageValidationError",
    "CdrError",
    "InvalidNameError",
    "TopicTypeError",
    "GraphFileError",
    "RosArgsError",
    "WorldError",
    "WorldFileError",
    "ServiceError",
    "ActionError",
    "ParameterError",
    "ControlError",
    "VirtualTimeDeadlock",
    "Escalation",
]


class ActorsError(Exception):
    """Base class of every error actors raises on purpose."""


class InterfaceError(ActorsError):
    """A problem with an interface definition or a message type."""


class IdlError(InterfaceError):
    """A syntax or type error in a .msg/.srv file, located at ``path:line``."""

    def __init__(self, path: str, line: int, problem: str) -> None:
        self.path = path
        self.line = line
        self.problem = problem
        super().__init__(f"{path}:{line}: {problem}")


class UnknownInterfaceError(InterfaceError, LookupError):
    """No interface type with this ROS name is known."""


class MessageValidationError(InterfaceError, ValueError):
    """A value does not fit its message type; the text names the field path."""


class CdrError(MessageValidationError):
    """CDR bytes that do not decode as their type (truncated, malformed), or a value CDR cannot carry.

    The text names the type and the field path (``$.header.frame_id``,
    ``$.points[3].x``).
    """


class InvalidNameError(ActorsError, ValueError):
    """A node, namespace, topic or service name breaks the ROS naming rules."""


class TopicTypeError(ActorsError, TypeError):
    """An endpoint's message type differs from the type already used on the topic."""


class GraphFileError(ActorsError):
    """A graph file is malformed; the text names the file and the key path."""


class RosArgsError(ActorsError, ValueError):
    """A ``--ros-args`` argument or a ROS parameter file is malformed; the text names which."""


class WorldError(ActorsError):
    """The simulated world cannot do what was asked (no World node, a robot that does not fit)."""


class WorldFileError(WorldError):
    """A world file is malformed; the text names the file and the key path."""


class ServiceError(ActorsError):
    """A service call failed: the server raised, or the call cannot be made."""


class ActionError(ActorsError):
    """An action goal cannot do what was asked: it was rejected, or the transition is not allowed."""


class ParameterError(ActorsError):
    """A parameter was used without being declared, or declared twice."""


class ControlError(ActorsError):
    """The command line cannot reach a running graph, or what it asked for is unknown."""


class VirtualTimeDeadlock(ActorsError):
    """Under virtual time every task waits and nothing could ever wake one."""


class Escalation(ActorsError):
    """The supervisor exceeded its restart intensity and gave up."""
