"""A parameter's value and type, as rclpy.parameter: Parameter, Parameter.Type, and their messages."""

from __future__ import annotations

from array import array
from enum import IntEnum
from typing import Any

from actors.errors import ParameterError
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.msg import ParameterValue

__all__ = [
    "PARAMETER_SEPARATOR_STRING",
    "ParameterType",
    "Parameter",
    "value_to_msg",
    "value_from_msg",
    "TYPES",
    "WIDENED",
    "widen",
]

PARAMETER_SEPARATOR_STRING = "."


class ParameterType(IntEnum):
    """Parameter types, numbered as ``rcl_interfaces/msg/ParameterType`` (rclpy's ``Parameter.Type``)."""

    NOT_SET = 0
    BOOL = 1
    INTEGER = 2
    DOUBLE = 3
    STRING = 4
    BYTE_ARRAY = 5
    BOOL_ARRAY = 6
    INTEGER_ARRAY = 7
    DOUBLE_ARRAY = 8
    STRING_ARRAY = 9

    @classmethod
    def from_parameter_value(cls, value: Any) -> ParameterType:
        """The type of ``value``; TypeError for a value no parameter can hold.

        As in rclpy an empty list is a BYTE_ARRAY (declare ``Parameter.Type.X``
        to say which kind of empty list is meant), and a list mixing ints and
        floats is a DOUBLE_ARRAY.
        """
        if value is None:
            return cls.NOT_SET
        if isinstance(value, bool):
            return cls.BOOL
        if isinstance(value, int):
            return cls.INTEGER
        if isinstance(value, float):
            return cls.DOUBLE
        if isinstance(value, str):
            return cls.STRING
        if isinstance(value, (bytes, bytearray)):
            return cls.BYTE_ARRAY
        if isinstance(value, (list, tuple, array)):  # a message's array field holds an array.array
            kinds = {type(v) for v in value}
            if kinds <= {bytes}:
                return cls.BYTE_ARRAY
            if kinds <= {int, float} and float in kinds:
                return cls.DOUBLE_ARRAY
            if len(kinds) == 1 and (kind := kinds.pop()) in _ELEMENT:
                return _ELEMENT[kind]
        raise TypeError(
            f"a parameter holds bool, int, float, str, bytes or a list of one of bool/int/float/str; got {value!r}"
        )

    def check(self, value: Any) -> bool:
        """Whether ``value`` fits this type (an int fits DOUBLE, int lists fit DOUBLE_ARRAY)."""
        if self is ParameterType.NOT_SET:
            return value is None
        try:
            actual = ParameterType.from_parameter_value(value)
        except TypeError:
            return False
        return (
            actual is self
            or (actual, self) in WIDENED
            or (
                # An empty list fits every array type.
                self >= ParameterType.BYTE_ARRAY and isinstance(value, (list, tuple, array)) and not value
            )
        )


TYPES = tuple(ParameterType)  # by number: a tuple lookup costs far less than ParameterType(n)
_ELEMENT = {
    bool: ParameterType.BOOL_ARRAY,
    int: ParameterType.INTEGER_ARRAY,
    float: ParameterType.DOUBLE_ARRAY,
    str: ParameterType.STRING_ARRAY,
}
# (given, declared) pairs accepted by widening ints to floats.
WIDENED = {
    (ParameterType.INTEGER, ParameterType.DOUBLE),
    (ParameterType.INTEGER_ARRAY, ParameterType.DOUBLE_ARRAY),
}
# ParameterValue's field for each type.
_FIELDS = {
    ParameterType.BOOL: "bool_value",
    ParameterType.INTEGER: "integer_value",
    ParameterType.DOUBLE: "double_value",
    ParameterType.STRING: "string_value",
    ParameterType.BYTE_ARRAY: "byte_array_value",
    ParameterType.BOOL_ARRAY: "bool_array_value",
    ParameterType.INTEGER_ARRAY: "integer_array_value",
    ParameterType.DOUBLE_ARRAY: "double_array_value",
    ParameterType.STRING_ARRAY: "string_array_value",
}


def widen(value: Any, type_: ParameterType) -> Any:
    """``value`` as stored for ``type_``: ints become floats for DOUBLE and DOUBLE_ARRAY."""
    if type_ is ParameterType.DOUBLE and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    if type_ is ParameterType.DOUBLE_ARRAY and any(isinstance(v, int) for v in value):
        return [float(v) for v in value]
    return value


def value_to_msg(value: Any, type_: ParameterType | None = None) -> ParameterValue:
    """A Python value as ``rcl_interfaces/msg/ParameterValue``; TypeError for a value no parameter holds."""
    type_ = ParameterType.from_parameter_value(value) if type_ is None else type_
    if type_ is ParameterType.NOT_SET:
        return ParameterValue(type=0)
    if type_ is ParameterType.BYTE_ARRAY:
        value = value if isinstance(value, bytes) else b"".join(value)
    else:
        value = widen(value, type_)
        value = list(value) if isinstance(value, tuple) else value
    # Through the constructor, which stores a number list as the field's array (as a decoded message
    # holds it), so the message equals one built or received with the same value.
    return ParameterValue(type=int(type_), **{_FIELDS[type_]: value})


def value_from_msg(msg: ParameterValue) -> Any:
    """The Python value held by an ``rcl_interfaces/msg/ParameterValue``."""
    if msg.type == ParameterType.NOT_SET:
        return None
    try:
        return getattr(msg, _FIELDS[ParameterType(msg.type)])
    except ValueError:
        raise ParameterError(f"unknown parameter type number {msg.type}") from None


class Parameter:
    """A named parameter value, as ``rclpy.parameter.Parameter``: ``Parameter(name, type_, value)``.

    The type is inferred from the value when not given.  Raises TypeError when
    ``type_`` is not a ``Parameter.Type`` or the value fits no type, ValueError
    when the value does not fit ``type_`` (an int fits DOUBLE and is stored as a
    float).  A Parameter does not change once made.
    """

    Type = ParameterType
    __slots__ = ("_name", "_type", "_value")

    def __init__(self, name: str, type_: ParameterType | None = None, value: Any = None) -> None:
        if type_ is None:
            type_ = ParameterType.from_parameter_value(value)
        elif not isinstance(type_, ParameterType):
            raise TypeError(f"type_ must be a Parameter.Type, got {type_!r}")
        elif not type_.check(value):
            raise ValueError(f"parameter {name!r}: type {type_.name} and value {value!r} do not agree")
        self._name = name
        self._type = type_
        self._value = widen(value, type_)

    @property
    def name(self) -> str:
        """The parameter's name."""
        return self._name

    @property
    def type_(self) -> ParameterType:
        """The parameter's type."""
        return self._type

    @property
    def value(self) -> Any:
        """The parameter's value (None when NOT_SET)."""
        return self._value

    def __repr__(self) -> str:
        return f"Parameter({self._name!r}, {self._type.name}, {self._value!r})"

    def get_parameter_value(self) -> ParameterValue:
        """The value as ``rcl_interfaces/msg/ParameterValue`` (``.string_value`` etc.)."""
        return value_to_msg(self._value, self._type)

    def to_parameter_msg(self) -> ParameterMsg:
        """This parameter as ``rcl_interfaces/msg/Parameter``."""
        return ParameterMsg(name=self._name, value=self.get_parameter_value())

    @classmethod
    def from_parameter_msg(cls, msg: ParameterMsg) -> Parameter:
        """A Parameter from ``rcl_interfaces/msg/Parameter``."""
        return cls(msg.name, ParameterType(msg.value.type), value_from_msg(msg.value))
