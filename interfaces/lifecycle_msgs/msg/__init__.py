"""Generated from lifecycle_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "State",
    "Transition",
    "TransitionDescription",
    "TransitionEvent",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class State(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/msg/State``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/msg/State"
    __ros_definition__: ClassVar[str] = (
        "# Primary state definitions as depicted in:\n"
        "# http://design.ros2.org/articles/node_lifecycle.html\n"
        "\n"
        "# These are the primary states. State changes can only be requested when the\n"
        "# node is in one of these states.\n"
        "\n"
        "# Indicates state has not yet been set.\n"
        "uint8 PRIMARY_STATE_UNKNOWN = 0\n"
        "\n"
        "# This is the life cycle state the node is in immediately after being\n"
        "# instantiated.\n"
        "uint8 PRIMARY_STATE_UNCONFIGURED = 1\n"
        "\n"
        "# This state represents a node that is not currently performing any processing.\n"
        "uint8 PRIMARY_STATE_INACTIVE = 2\n"
        "\n"
        "# This is the main state of the node's life cycle. While in this state, the node\n"
        "# performs any processing, responds to service requests, reads and processes\n"
        "# data, produces output, etc.\n"
        "uint8 PRIMARY_STATE_ACTIVE = 3\n"
        "\n"
        "# The finalized state is the state in which the node ends immediately before\n"
        "# being destroyed.\n"
        "uint8 PRIMARY_STATE_FINALIZED = 4\n"
        "\n"
        "# Temporary intermediate states. When a transition is requested, the node\n"
        "# changes its state into one of these states.\n"
        "\n"
        "# In this transition state the node's onConfigure callback will be called to\n"
        "# allow the node to load its configuration and conduct any required setup.\n"
        "uint8 TRANSITION_STATE_CONFIGURING = 10\n"
        "\n"
        "# In this transition state the node's callback onCleanup will be called to clear\n"
        "# all state and return the node to a functionally equivalent state as when\n"
        "# first created.\n"
        "uint8 TRANSITION_STATE_CLEANINGUP = 11\n"
        "\n"
        "# In this transition state the callback onShutdown will be executed to do any\n"
        "# cleanup necessary before destruction.\n"
        "uint8 TRANSITION_STATE_SHUTTINGDOWN = 12\n"
        "\n"
        "# In this transition state the callback onActivate will be executed to do any\n"
        "# final preparations to start executing.\n"
        "uint8 TRANSITION_STATE_ACTIVATING = 13\n"
        "\n"
        "# In this transition state the callback onDeactivate will be executed to do any\n"
        "# cleanup to start executing, and reverse the onActivate changes.\n"
        "uint8 TRANSITION_STATE_DEACTIVATING = 14\n"
        "\n"
        "# This transition state is where any error may be cleaned up.\n"
        "uint8 TRANSITION_STATE_ERRORPROCESSING = 15\n"
        "\n"
        "# The state id value from the above definitions.\n"
        "uint8 id\n"
        "\n"
        "# A text label of the state.\n"
        "string label\n"
    )
    PRIMARY_STATE_UNKNOWN: ClassVar[int] = 0
    PRIMARY_STATE_UNCONFIGURED: ClassVar[int] = 1
    PRIMARY_STATE_INACTIVE: ClassVar[int] = 2
    PRIMARY_STATE_ACTIVE: ClassVar[int] = 3
    PRIMARY_STATE_FINALIZED: ClassVar[int] = 4
    TRANSITION_STATE_CONFIGURING: ClassVar[int] = 10
    TRANSITION_STATE_CLEANINGUP: ClassVar[int] = 11
    TRANSITION_STATE_SHUTTINGDOWN: ClassVar[int] = 12
    TRANSITION_STATE_ACTIVATING: ClassVar[int] = 13
    TRANSITION_STATE_DEACTIVATING: ClassVar[int] = 14
    TRANSITION_STATE_ERRORPROCESSING: ClassVar[int] = 15

    id: _uint8 = 0
    label: str = ""


class Transition(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/msg/Transition``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/msg/Transition"
    __ros_definition__: ClassVar[str] = (
        "# Default values for transitions as described in:\n"
        "# http://design.ros2.org/articles/node_lifecycle.html\n"
        "\n"
        "# Reserved [0-9], publicly available transitions.\n"
        "# When a node is in one of these primary states, these transitions can be\n"
        "# invoked.\n"
        "\n"
        "# This transition will instantiate the node, but will not run any code beyond\n"
        "# the constructor.\n"
        "uint8 TRANSITION_CREATE = 0\n"
        "\n"
        "# The node's onConfigure callback will be called to allow the node to load its\n"
        "# configuration and conduct any required setup.\n"
        "uint8 TRANSITION_CONFIGURE = 1\n"
        "\n"
        "# The node's callback onCleanup will be called in this transition to allow the\n"
        "# node to load its configuration and conduct any required setup.\n"
        "uint8 TRANSITION_CLEANUP = 2\n"
        "\n"
        "# The node's callback onActivate will be executed to do any final preparations\n"
        "# to start executing.\n"
        "uint8 TRANSITION_ACTIVATE = 3\n"
        "\n"
        "# The node's callback onDeactivate will be executed to do any cleanup to start\n"
        "# executing, and reverse the onActivate changes.\n"
        "uint8 TRANSITION_DEACTIVATE = 4\n"
        "\n"
        "# This signals shutdown during an unconfigured state, the node's callback\n"
        "# onShutdown will be executed to do any cleanup necessary before destruction.\n"
        "uint8 TRANSITION_UNCONFIGURED_SHUTDOWN  = 5\n"
        "\n"
        "# This signals shutdown during an inactive state, the node's callback onShutdown\n"
        "# will be executed to do any cleanup necessary before destruction.\n"
        "uint8 TRANSITION_INACTIVE_SHUTDOWN = 6\n"
        "\n"
        "# This signals shutdown during an active state, the node's callback onShutdown\n"
        "# will be executed to do any cleanup necessary before destruction.\n"
        "uint8 TRANSITION_ACTIVE_SHUTDOWN = 7\n"
        "\n"
        "# This transition will simply cause the deallocation of the node.\n"
        "uint8 TRANSITION_DESTROY = 8\n"
        "\n"
        "# Reserved [10-69], private transitions\n"
        "# These transitions are not publicly available and cannot be invoked by a user.\n"
        "# The following transitions are implicitly invoked based on the callback\n"
        "# feedback of the intermediate transition states.\n"
        "uint8 TRANSITION_ON_CONFIGURE_SUCCESS = 10\n"
        "uint8 TRANSITION_ON_CONFIGURE_FAILURE = 11\n"
        "uint8 TRANSITION_ON_CONFIGURE_ERROR = 12\n"
        "\n"
        "uint8 TRANSITION_ON_CLEANUP_SUCCESS = 20\n"
        "uint8 TRANSITION_ON_CLEANUP_FAILURE = 21\n"
        "uint8 TRANSITION_ON_CLEANUP_ERROR = 22\n"
        "\n"
        "uint8 TRANSITION_ON_ACTIVATE_SUCCESS = 30\n"
        "uint8 TRANSITION_ON_ACTIVATE_FAILURE = 31\n"
        "uint8 TRANSITION_ON_ACTIVATE_ERROR = 32\n"
        "\n"
        "uint8 TRANSITION_ON_DEACTIVATE_SUCCESS = 40\n"
        "uint8 TRANSITION_ON_DEACTIVATE_FAILURE = 41\n"
        "uint8 TRANSITION_ON_DEACTIVATE_ERROR = 42\n"
        "\n"
        "uint8 TRANSITION_ON_SHUTDOWN_SUCCESS = 50\n"
        "uint8 TRANSITION_ON_SHUTDOWN_FAILURE = 51\n"
        "uint8 TRANSITION_ON_SHUTDOWN_ERROR = 52\n"
        "\n"
        "uint8 TRANSITION_ON_ERROR_SUCCESS = 60\n"
        "uint8 TRANSITION_ON_ERROR_FAILURE = 61\n"
        "uint8 TRANSITION_ON_ERROR_ERROR = 62\n"
        "\n"
        "# Reserved [90-99]. Transition callback success values.\n"
        "# These return values ought to be set as a return value for each callback.\n"
        "# Depending on which return value, the transition will be executed correctly or\n"
        "# fallback/error callbacks will be triggered.\n"
        "\n"
        "# The transition callback successfully performed its required functionality.\n"
        "uint8 TRANSITION_CALLBACK_SUCCESS = 97\n"
        "\n"
        "# The transition callback failed to perform its required functionality.\n"
        "uint8 TRANSITION_CALLBACK_FAILURE = 98\n"
        "\n"
        "# The transition callback encountered an error that requires special cleanup, if\n"
        "# possible.\n"
        "uint8 TRANSITION_CALLBACK_ERROR = 99\n"
        "\n"
        "##\n"
        "## Fields\n"
        "##\n"
        "\n"
        "# The transition id from above definitions.\n"
        "uint8 id\n"
        "\n"
        "# A text label of the transition.\n"
        "string label\n"
    )
    TRANSITION_CREATE: ClassVar[int] = 0
    TRANSITION_CONFIGURE: ClassVar[int] = 1
    TRANSITION_CLEANUP: ClassVar[int] = 2
    TRANSITION_ACTIVATE: ClassVar[int] = 3
    TRANSITION_DEACTIVATE: ClassVar[int] = 4
    TRANSITION_UNCONFIGURED_SHUTDOWN: ClassVar[int] = 5
    TRANSITION_INACTIVE_SHUTDOWN: ClassVar[int] = 6
    TRANSITION_ACTIVE_SHUTDOWN: ClassVar[int] = 7
    TRANSITION_DESTROY: ClassVar[int] = 8
    TRANSITION_ON_CONFIGURE_SUCCESS: ClassVar[int] = 10
    TRANSITION_ON_CONFIGURE_FAILURE: ClassVar[int] = 11
    TRANSITION_ON_CONFIGURE_ERROR: ClassVar[int] = 12
    TRANSITION_ON_CLEANUP_SUCCESS: ClassVar[int] = 20
    TRANSITION_ON_CLEANUP_FAILURE: ClassVar[int] = 21
    TRANSITION_ON_CLEANUP_ERROR: ClassVar[int] = 22
    TRANSITION_ON_ACTIVATE_SUCCESS: ClassVar[int] = 30
    TRANSITION_ON_ACTIVATE_FAILURE: ClassVar[int] = 31
    TRANSITION_ON_ACTIVATE_ERROR: ClassVar[int] = 32
    TRANSITION_ON_DEACTIVATE_SUCCESS: ClassVar[int] = 40
    TRANSITION_ON_DEACTIVATE_FAILURE: ClassVar[int] = 41
    TRANSITION_ON_DEACTIVATE_ERROR: ClassVar[int] = 42
    TRANSITION_ON_SHUTDOWN_SUCCESS: ClassVar[int] = 50
    TRANSITION_ON_SHUTDOWN_FAILURE: ClassVar[int] = 51
    TRANSITION_ON_SHUTDOWN_ERROR: ClassVar[int] = 52
    TRANSITION_ON_ERROR_SUCCESS: ClassVar[int] = 60
    TRANSITION_ON_ERROR_FAILURE: ClassVar[int] = 61
    TRANSITION_ON_ERROR_ERROR: ClassVar[int] = 62
    TRANSITION_CALLBACK_SUCCESS: ClassVar[int] = 97
    TRANSITION_CALLBACK_FAILURE: ClassVar[int] = 98
    TRANSITION_CALLBACK_ERROR: ClassVar[int] = 99

    id: _uint8 = 0
    label: str = ""


class TransitionDescription(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/msg/TransitionDescription``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/msg/TransitionDescription"
    __ros_definition__: ClassVar[str] = (
        "# The transition id and label of this description.\n"
        "Transition transition\n"
        "\n"
        "# The current state from which this transition transitions.\n"
        "State start_state\n"
        "\n"
        "# The desired target state of this transition.\n"
        "State goal_state\n"
    )

    transition: Transition = msgspec.field(default_factory=Transition)
    start_state: State = msgspec.field(default_factory=State)
    goal_state: State = msgspec.field(default_factory=State)


class TransitionEvent(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``lifecycle_msgs/msg/TransitionEvent``."""

    __ros_type__: ClassVar[str] = "lifecycle_msgs/msg/TransitionEvent"
    __ros_definition__: ClassVar[str] = (
        "# The time point at which this event occurred.\n"
        "uint64 timestamp\n"
        "\n"
        "# The id and label of this transition event.\n"
        "Transition transition\n"
        "\n"
        "# The starting state from which this event transitioned.\n"
        "State start_state\n"
        "\n"
        "# The end state of this transition event.\n"
        "State goal_state\n"
    )

    timestamp: _uint64 = 0
    transition: Transition = msgspec.field(default_factory=Transition)
    start_state: State = msgspec.field(default_factory=State)
    goal_state: State = msgspec.field(default_factory=State)
