"""``rclpy.exceptions``: the errors rclpy code catches, most of them actors' own."""

from __future__ import annotations

from actors.errors import (
    InvalidNameError,
    InvalidNamespaceException,
    InvalidNodeNameException,
    InvalidParameterException,
    InvalidParameterTypeException,
    InvalidParameterValueException,
    InvalidServiceNameException,
    InvalidTopicNameException,
    ParameterAlreadyDeclaredException,
    ParameterException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
    RosArgsError,
)

__all__ = [
    "InvalidHandle",
    "NotInitializedException",
    "ROSInterruptException",
    "NameValidationException",
    "InvalidNodeNameException",
    "InvalidNamespaceException",
    "InvalidTopicNameException",
    "InvalidServiceNameException",
    "InvalidROSArgsException",
    "ParameterException",
    "ParameterNotDeclaredException",
    "ParameterAlreadyDeclaredException",
    "InvalidParameterException",
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "ParameterImmutableException",
    "ParameterUninitializedException",
    "TimerCancelledError",
    "NoTypeSupportImportedException",
]

NameValidationException = InvalidNameError
InvalidROSArgsException = RosArgsError


class InvalidHandle(Exception):
    """An entity was used after it was destroyed."""


class NotInitializedException(Exception):
    """``rclpy.init()`` was not called (or the context was shut down) before this call."""

    def __init__(self, msg: str = "rclpy.init() has not been called", *args: object) -> None:
        super().__init__(msg, *args)


class NoTypeSupportImportedException(Exception):
    """A message or service class has no type support (``type_support.check_for_type_support``)."""

    def __init__(self) -> None:
        super().__init__("no type_support imported")


class ROSInterruptException(Exception):
    """The context was shut down while the call waited (``Rate.sleep``)."""

    def __init__(self, msg: str = "rclpy.shutdown() has been called", *args: object) -> None:
        super().__init__(msg, *args)


class TimerCancelledError(Exception):
    """A canceled timer was called."""
