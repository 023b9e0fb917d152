"""Every exception actors raises, in one place.

    ActorsError                      base of everything below
    ├── InterfaceError               a .msg/.srv/type problem
    │   ├── IdlError                 a syntax or type error at file:line
    │   ├── UnknownInterfaceError    no such type (``pkg/msg/Name``)
    │   └── MessageValidationError   a value does not fit its type (names the field path)
    │       └── CdrError             bytes that are not CDR of the type, or a value CDR cannot carry
    ├── InvalidNameError             a node, topic or service name breaks the ROS rules
    │   ├── InvalidNodeNameException     (rclpy's names, for the same errors)
    │   ├── InvalidNamespaceException
    │   ├── InvalidTopicNameException
    │   └── InvalidServiceNameException
    ├── TopicTypeError               publisher and subscription disagree on a topic's type
    ├── MessageRefused               a subscription callback turns a message away (dropped, counted)
    ├── InvalidQoSProfileException   a QoSProfile without a history or depth (rclpy's name)
    ├── GraphFileError               graph.toml is malformed (names file and key path)
    ├── RosArgsError                 a --ros-args argument or a parameter file is malformed
    ├── PackageError                 no such package or executable, or its setup files cannot be read
    ├── LaunchFileError              a launch file is malformed or fails (names file and line)
    ├── WorldError                   a robot without a world, a start pose that does not fit
    │   └── WorldFileError           a world file is malformed (names file and key path)
    ├── ServiceError                 a service call failed on the server's side
    ├── ActionError                  a goal cannot do what was asked (rejected, invalid transition)
    ├── ParameterError               a parameter cannot be declared, read or set (rclpy: ParameterException)
    │   ├── ParameterNotDeclaredException        used without being declared
    │   ├── ParameterAlreadyDeclaredException    declared twice
    │   ├── InvalidParameterException            a name no parameter may have
    │   ├── InvalidParameterTypeException        a value of another type than declared
    │   ├── InvalidParameterValueException       refused by its descriptor or an on-set callback
    │   ├── ParameterImmutableException          read-only
    │   └── ParameterUninitializedException      declared with a type but never given a value
    ├── ControlError                 the command line cannot reach or use a running graph
    ├── TransportError               a transport cannot start or is misconfigured (names the setting)
    ├── BagError                     a bag (MCAP) cannot be read or written (names file and byte)
    ├── TransformException           a tf2 lookup failed (tf2's names and messages)
    │   ├── LookupException              a frame nobody has published
    │   ├── ConnectivityException        the frames are in two unconnected trees
    │   ├── ExtrapolationException       a time outside a frame's data
    │   ├── InvalidArgumentException     an empty frame id, or one starting with '/'
    │   └── TimeoutException             a wait for a transform ran out
    ├── VirtualTimeDeadlock          virtual time has nothing left to wait for
    ├── ScriptEnded                  a graded script ended by itself before its test was done
    └── Escalation                   the supervisor gave up: too many restarts

The classes named ``...Exception`` carry rclpy's names (``rclpy.exceptions``), so
code written for rclpy catches what it expects; ``ParameterException`` is another
name for ``ParameterError``.

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
    "InvalidNodeNameException",
    "InvalidNamespaceException",
    "InvalidTopicNameException",
    "InvalidServiceNameException",
    "TopicTypeError",
    "MessageRefused",
    "InvalidQoSProfileException",
    "GraphFileError",
    "RosArgsError",
    "PackageError",
    "LaunchFileError",
    "WorldError",
    "WorldFileError",
    "ServiceError",
    "ActionError",
    "ParameterError",
    "ParameterException",
    "ParameterNotDeclaredException",
    "ParameterAlreadyDeclaredException",
    "InvalidParameterException",
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "ParameterImmutableException",
    "ParameterUninitializedException",
    "ControlError",
    "TransportError",
    "BagError",
    "TransformException",
    "LookupException",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "TimeoutException",
    "VirtualTimeDeadlock",
    "ScriptEnded",
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


class InvalidNodeNameException(InvalidNameError):
    """A node name breaks the ROS naming rules."""


class InvalidNamespaceException(InvalidNameError):
    """A namespace breaks the ROS naming rules."""


class InvalidTopicNameException(InvalidNameError):
    """A topic name breaks the ROS naming rules."""


class InvalidServiceNameException(InvalidNameError):
    """A service name breaks the ROS naming rules."""


class TopicTypeError(ActorsError, TypeError):
    """An endpoint's message type differs from the type already used on the topic."""


class MessageRefused(ActorsError):
    """Raised by a subscription callback to refuse the message it was given.

    The message is dropped and counted per reason (``doctor`` and ``topic info``
    show the counts); it is logged once per publisher and reason, at most a few
    lines per period; the node keeps running.  This is a node's input boundary:
    raise it for a message the node cannot act on (a non-finite command, a
    value out of range), and let a real bug raise anything else, which crashes
    the node for its supervisor to restart.  ``reason`` should not contain the
    message's values: refusals are counted and logged per distinct reason.
    Raised elsewhere (a timer, a service handler) it is an ordinary error.
    """

    def __init__(self, reason: str) -> None:
        self.reason = reason
        super().__init__(reason)


class InvalidQoSProfileException(ActorsError, ValueError):
    """A QoSProfile was made without a history or a depth, or KEEP_LAST without a depth."""


class GraphFileError(ActorsError):
    """A graph file is malformed; the text names the file and the key path."""


class RosArgsError(ActorsError, ValueError):
    """A ``--ros-args`` argument or a ROS parameter file is malformed; the text names which."""


class PackageError(ActorsError, LookupError):
    """No such package or executable in the workspace, or a package's setup files cannot be read."""


class LaunchFileError(ActorsError):
    """A launch file is malformed or fails while it is read: the message names file and line."""


class WorldError(ActorsError):
    """The simulated world cannot do what was asked (no World node, a robot that does not fit)."""


class WorldFileError(WorldError):
    """A world file is malformed; the text names the file and the key path."""


class ServiceError(ActorsError):
    """A service call failed: the server raised, or the call cannot be made."""


class ActionError(ActorsError):
    """An action goal cannot do what was asked: it was rejected, or the transition is not allowed."""


class ParameterError(ActorsError):
    """A parameter cannot be declared, read or set; the text names the parameter and node."""


ParameterException = ParameterError


class ParameterNotDeclaredException(ParameterError, LookupError):
    """A parameter was read, set or described without being declared."""


class ParameterAlreadyDeclaredException(ParameterError):
    """A parameter was declared a second time."""


class InvalidParameterException(ParameterError, ValueError):
    """A parameter name breaks the rules (empty, or with empty parts between dots)."""


class InvalidParameterTypeException(ParameterError, TypeError):
    """A parameter was given a value of another type than the one it was declared with."""


class InvalidParameterValueException(ParameterError, ValueError):
    """A value was refused by the parameter's descriptor (range) or by an on-set callback."""


class ParameterImmutableException(ParameterError):
    """A read-only parameter was to be changed or undeclared."""


class ParameterUninitializedException(ParameterError):
    """A parameter declared with only a type was read before it was given a value."""


class ControlError(ActorsError):
    """The command line cannot reach a running graph, or what it asked for is unknown."""


class TransportError(ActorsError):
    """A transport cannot start: its package is missing, a setting is wrong, the network refuses."""


class BagError(ActorsError):
    """A bag (MCAP file) cannot be read or written; the message names the file and byte offset."""


class TransformException(ActorsError):
    """A tf2 lookup failed; the subclasses carry tf2's (and tf2_ros's) names."""


class LookupException(TransformException):
    """A frame that no transform has named."""


class ConnectivityException(TransformException):
    """The two frames are in trees that no transform joins."""


class ExtrapolationException(TransformException):
    """A frame on the way has no data at the time asked (into the future, the past, or at all)."""


class InvalidArgumentException(TransformException):
    """A frame id that tf2 refuses: empty, or starting with '/'."""


class TimeoutException(TransformException):
    """A wait for a transform ran out."""


class VirtualTimeDeadlock(ActorsError):
    """Under virtual time every task waits and nothing could ever wake one."""


class ScriptEnded(ActorsError):
    """A student's script ended by itself (returned or called ``sys.exit``) before a test that then failed."""


class Escalation(ActorsError):
    """The supervisor exceeded its restart intensity and gave up."""
