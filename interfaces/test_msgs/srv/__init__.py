"""Generated from test_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.test_msgs.msg import BasicTypes as test_msgs_BasicTypes, Constants, Defaults

__all__ = [
    "Arrays",
    "Arrays_Event",
    "Arrays_Request",
    "Arrays_Response",
    "BasicTypes",
    "BasicTypes_Event",
    "BasicTypes_Request",
    "BasicTypes_Response",
    "Empty",
    "Empty_Event",
    "Empty_Request",
    "Empty_Response",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_int16 = Annotated[int, msgspec.Meta(ge=-32768, le=32767)]
_uint16 = Annotated[int, msgspec.Meta(ge=0, le=65535)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]
_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class Arrays_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Arrays_Request``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Arrays_Request"
    __ros_definition__: ClassVar[str] = (
        "bool[3] bool_values\n"
        "byte[3] byte_values\n"
        "char[3] char_values\n"
        "float32[3] float32_values\n"
        "float64[3] float64_values\n"
        "int8[3] int8_values\n"
        "uint8[3] uint8_values\n"
        "int16[3] int16_values\n"
        "uint16[3] uint16_values\n"
        "int32[3] int32_values\n"
        "uint32[3] uint32_values\n"
        "int64[3] int64_values\n"
        "uint64[3] uint64_values\n"
        "string[3] string_values\n"
        "BasicTypes[3] basic_types_values\n"
        "Constants[3] constants_values\n"
        "Defaults[3] defaults_values\n"
        "bool[3] bool_values_default [false, true, false]\n"
        "byte[3] byte_values_default [0, 1, 255]\n"
        "char[3] char_values_default [0, 1, 127]\n"
        "float32[3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[3] int8_values_default [0, 127, -128]\n"
        "uint8[3] uint8_values_default [0, 1, 255]\n"
        "int16[3] int16_values_default [0, 32767, -32768]\n"
        "uint16[3] uint16_values_default [0, 1, 65535]\n"
        "int32[3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[3] string_values_default [\"\", \"max value\", \"min value\"]\n"
    )

    bool_values: Annotated[list[bool], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [False] * 3)
    byte_values: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = bytes(3)
    char_values: Annotated[MutableSequence[_uint8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("B", bytes(3)))
    float32_values: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("f", bytes(12)))
    float64_values: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("d", bytes(24)))
    int8_values: Annotated[MutableSequence[_int8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("b", bytes(3)))
    uint8_values: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = bytes(3)
    int16_values: Annotated[MutableSequence[_int16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("h", bytes(6)))
    uint16_values: Annotated[MutableSequence[_uint16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("H", bytes(6)))
    int32_values: Annotated[MutableSequence[_int32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("i", bytes(12)))
    uint32_values: Annotated[MutableSequence[_uint32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("I", bytes(12)))
    int64_values: Annotated[MutableSequence[_int64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("q", bytes(24)))
    uint64_values: Annotated[MutableSequence[_uint64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("Q", bytes(24)))
    string_values: Annotated[list[str], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [""] * 3)
    basic_types_values: Annotated[list[test_msgs_BasicTypes], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [test_msgs_BasicTypes() for _ in range(3)])
    constants_values: Annotated[list[Constants], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [Constants() for _ in range(3)])
    defaults_values: Annotated[list[Defaults], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [Defaults() for _ in range(3)])
    bool_values_default: Annotated[list[bool], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [False, True, False])
    byte_values_default: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = b'\x00\x01\xff'
    char_values_default: Annotated[MutableSequence[_uint8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("B", [0, 1, 127]))
    float32_values_default: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("f", [1.125, 0.0, -1.125]))
    float64_values_default: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("d", [3.1415, 0.0, -3.1415]))
    int8_values_default: Annotated[MutableSequence[_int8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("b", [0, 127, -128]))
    uint8_values_default: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = b'\x00\x01\xff'
    int16_values_default: Annotated[MutableSequence[_int16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("h", [0, 32767, -32768]))
    uint16_values_default: Annotated[MutableSequence[_uint16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("H", [0, 1, 65535]))
    int32_values_default: Annotated[MutableSequence[_int32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("i", [0, 2147483647, -2147483648]))
    uint32_values_default: Annotated[MutableSequence[_uint32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("I", [0, 1, 4294967295]))
    int64_values_default: Annotated[MutableSequence[_int64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("q", [0, 9223372036854775807, -9223372036854775808]))
    uint64_values_default: Annotated[MutableSequence[_uint64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("Q", [0, 1, 18446744073709551615]))
    string_values_default: Annotated[list[str], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: ["", "max value", "min value"])

    def __post_init__(self) -> None:
        if type(self.char_values) is not array or self.char_values.typecode != "B":
            self.char_values = held(self.char_values, "B")
        if type(self.float32_values) is not array or self.float32_values.typecode != "f":
            self.float32_values = held(self.float32_values, "f")
        if type(self.float64_values) is not array or self.float64_values.typecode != "d":
            self.float64_values = held(self.float64_values, "d")
        if type(self.int8_values) is not array or self.int8_values.typecode != "b":
            self.int8_values = held(self.int8_values, "b")
        if type(self.int16_values) is not array or self.int16_values.typecode != "h":
            self.int16_values = held(self.int16_values, "h")
        if type(self.uint16_values) is not array or self.uint16_values.typecode != "H":
            self.uint16_values = held(self.uint16_values, "H")
        if type(self.int32_values) is not array or self.int32_values.typecode != "i":
            self.int32_values = held(self.int32_values, "i")
        if type(self.uint32_values) is not array or self.uint32_values.typecode != "I":
            self.uint32_values = held(self.uint32_values, "I")
        if type(self.int64_values) is not array or self.int64_values.typecode != "q":
            self.int64_values = held(self.int64_values, "q")
        if type(self.uint64_values) is not array or self.uint64_values.typecode != "Q":
            self.uint64_values = held(self.uint64_values, "Q")
        if type(self.char_values_default) is not array or self.char_values_default.typecode != "B":
            self.char_values_default = held(self.char_values_default, "B")
        if type(self.float32_values_default) is not array or self.float32_values_default.typecode != "f":
            self.float32_values_default = held(self.float32_values_default, "f")
        if type(self.float64_values_default) is not array or self.float64_values_default.typecode != "d":
            self.float64_values_default = held(self.float64_values_default, "d")
        if type(self.int8_values_default) is not array or self.int8_values_default.typecode != "b":
            self.int8_values_default = held(self.int8_values_default, "b")
        if type(self.int16_values_default) is not array or self.int16_values_default.typecode != "h":
            self.int16_values_default = held(self.int16_values_default, "h")
        if type(self.uint16_values_default) is not array or self.uint16_values_default.typecode != "H":
            self.uint16_values_default = held(self.uint16_values_default, "H")
        if type(self.int32_values_default) is not array or self.int32_values_default.typecode != "i":
            self.int32_values_default = held(self.int32_values_default, "i")
        if type(self.uint32_values_default) is not array or self.uint32_values_default.typecode != "I":
            self.uint32_values_default = held(self.uint32_values_default, "I")
        if type(self.int64_values_default) is not array or self.int64_values_default.typecode != "q":
            self.int64_values_default = held(self.int64_values_default, "q")
        if type(self.uint64_values_default) is not array or self.uint64_values_default.typecode != "Q":
            self.uint64_values_default = held(self.uint64_values_default, "Q")


class Arrays_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Arrays_Response``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Arrays_Response"
    __ros_definition__: ClassVar[str] = (
        "bool[3] bool_values\n"
        "byte[3] byte_values\n"
        "char[3] char_values\n"
        "float32[3] float32_values\n"
        "float64[3] float64_values\n"
        "int8[3] int8_values\n"
        "uint8[3] uint8_values\n"
        "int16[3] int16_values\n"
        "uint16[3] uint16_values\n"
        "int32[3] int32_values\n"
        "uint32[3] uint32_values\n"
        "int64[3] int64_values\n"
        "uint64[3] uint64_values\n"
        "string[3] string_values\n"
        "BasicTypes[3] basic_types_values\n"
        "Constants[3] constants_values\n"
        "Defaults[3] defaults_values\n"
        "bool[3] bool_values_default [false, true, false]\n"
        "byte[3] byte_values_default [0, 1, 255]\n"
        "char[3] char_values_default [0, 1, 127]\n"
        "float32[3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[3] int8_values_default [0, 127, -128]\n"
        "uint8[3] uint8_values_default [0, 1, 255]\n"
        "int16[3] int16_values_default [0, 32767, -32768]\n"
        "uint16[3] uint16_values_default [0, 1, 65535]\n"
        "int32[3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[3] string_values_default [\"\", \"max value\", \"min value\"]\n"
    )

    bool_values: Annotated[list[bool], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [False] * 3)
    byte_values: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = bytes(3)
    char_values: Annotated[MutableSequence[_uint8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("B", bytes(3)))
    float32_values: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("f", bytes(12)))
    float64_values: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("d", bytes(24)))
    int8_values: Annotated[MutableSequence[_int8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("b", bytes(3)))
    uint8_values: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = bytes(3)
    int16_values: Annotated[MutableSequence[_int16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("h", bytes(6)))
    uint16_values: Annotated[MutableSequence[_uint16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("H", bytes(6)))
    int32_values: Annotated[MutableSequence[_int32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("i", bytes(12)))
    uint32_values: Annotated[MutableSequence[_uint32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("I", bytes(12)))
    int64_values: Annotated[MutableSequence[_int64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("q", bytes(24)))
    uint64_values: Annotated[MutableSequence[_uint64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("Q", bytes(24)))
    string_values: Annotated[list[str], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [""] * 3)
    basic_types_values: Annotated[list[test_msgs_BasicTypes], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [test_msgs_BasicTypes() for _ in range(3)])
    constants_values: Annotated[list[Constants], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [Constants() for _ in range(3)])
    defaults_values: Annotated[list[Defaults], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [Defaults() for _ in range(3)])
    bool_values_default: Annotated[list[bool], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [False, True, False])
    byte_values_default: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = b'\x00\x01\xff'
    char_values_default: Annotated[MutableSequence[_uint8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("B", [0, 1, 127]))
    float32_values_default: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("f", [1.125, 0.0, -1.125]))
    float64_values_default: Annotated[MutableSequence[float], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("d", [3.1415, 0.0, -3.1415]))
    int8_values_default: Annotated[MutableSequence[_int8], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("b", [0, 127, -128]))
    uint8_values_default: Annotated[bytes, msgspec.Meta(min_length=3, max_length=3)] = b'\x00\x01\xff'
    int16_values_default: Annotated[MutableSequence[_int16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("h", [0, 32767, -32768]))
    uint16_values_default: Annotated[MutableSequence[_uint16], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("H", [0, 1, 65535]))
    int32_values_default: Annotated[MutableSequence[_int32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("i", [0, 2147483647, -2147483648]))
    uint32_values_default: Annotated[MutableSequence[_uint32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("I", [0, 1, 4294967295]))
    int64_values_default: Annotated[MutableSequence[_int64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("q", [0, 9223372036854775807, -9223372036854775808]))
    uint64_values_default: Annotated[MutableSequence[_uint64], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("Q", [0, 1, 18446744073709551615]))
    string_values_default: Annotated[list[str], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: ["", "max value", "min value"])

    def __post_init__(self) -> None:
        if type(self.char_values) is not array or self.char_values.typecode != "B":
            self.char_values = held(self.char_values, "B")
        if type(self.float32_values) is not array or self.float32_values.typecode != "f":
            self.float32_values = held(self.float32_values, "f")
        if type(self.float64_values) is not array or self.float64_values.typecode != "d":
            self.float64_values = held(self.float64_values, "d")
        if type(self.int8_values) is not array or self.int8_values.typecode != "b":
            self.int8_values = held(self.int8_values, "b")
        if type(self.int16_values) is not array or self.int16_values.typecode != "h":
            self.int16_values = held(self.int16_values, "h")
        if type(self.uint16_values) is not array or self.uint16_values.typecode != "H":
            self.uint16_values = held(self.uint16_values, "H")
        if type(self.int32_values) is not array or self.int32_values.typecode != "i":
            self.int32_values = held(self.int32_values, "i")
        if type(self.uint32_values) is not array or self.uint32_values.typecode != "I":
            self.uint32_values = held(self.uint32_values, "I")
        if type(self.int64_values) is not array or self.int64_values.typecode != "q":
            self.int64_values = held(self.int64_values, "q")
        if type(self.uint64_values) is not array or self.uint64_values.typecode != "Q":
            self.uint64_values = held(self.uint64_values, "Q")
        if type(self.char_values_default) is not array or self.char_values_default.typecode != "B":
            self.char_values_default = held(self.char_values_default, "B")
        if type(self.float32_values_default) is not array or self.float32_values_default.typecode != "f":
            self.float32_values_default = held(self.float32_values_default, "f")
        if type(self.float64_values_default) is not array or self.float64_values_default.typecode != "d":
            self.float64_values_default = held(self.float64_values_default, "d")
        if type(self.int8_values_default) is not array or self.int8_values_default.typecode != "b":
            self.int8_values_default = held(self.int8_values_default, "b")
        if type(self.int16_values_default) is not array or self.int16_values_default.typecode != "h":
            self.int16_values_default = held(self.int16_values_default, "h")
        if type(self.uint16_values_default) is not array or self.uint16_values_default.typecode != "H":
            self.uint16_values_default = held(self.uint16_values_default, "H")
        if type(self.int32_values_default) is not array or self.int32_values_default.typecode != "i":
            self.int32_values_default = held(self.int32_values_default, "i")
        if type(self.uint32_values_default) is not array or self.uint32_values_default.typecode != "I":
            self.uint32_values_default = held(self.uint32_values_default, "I")
        if type(self.int64_values_default) is not array or self.int64_values_default.typecode != "q":
            self.int64_values_default = held(self.int64_values_default, "q")
        if type(self.uint64_values_default) is not array or self.uint64_values_default.typecode != "Q":
            self.uint64_values_default = held(self.uint64_values_default, "Q")


class Arrays_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Arrays_Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Arrays_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "test_msgs/srv/Arrays_Request[<=1] request\n"
        "test_msgs/srv/Arrays_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Arrays_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Arrays_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Arrays:
    """``test_msgs/srv/Arrays``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Arrays"
    __ros_definition__: ClassVar[str] = (
        "bool[3] bool_values\n"
        "byte[3] byte_values\n"
        "char[3] char_values\n"
        "float32[3] float32_values\n"
        "float64[3] float64_values\n"
        "int8[3] int8_values\n"
        "uint8[3] uint8_values\n"
        "int16[3] int16_values\n"
        "uint16[3] uint16_values\n"
        "int32[3] int32_values\n"
        "uint32[3] uint32_values\n"
        "int64[3] int64_values\n"
        "uint64[3] uint64_values\n"
        "string[3] string_values\n"
        "BasicTypes[3] basic_types_values\n"
        "Constants[3] constants_values\n"
        "Defaults[3] defaults_values\n"
        "bool[3] bool_values_default [false, true, false]\n"
        "byte[3] byte_values_default [0, 1, 255]\n"
        "char[3] char_values_default [0, 1, 127]\n"
        "float32[3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[3] int8_values_default [0, 127, -128]\n"
        "uint8[3] uint8_values_default [0, 1, 255]\n"
        "int16[3] int16_values_default [0, 32767, -32768]\n"
        "uint16[3] uint16_values_default [0, 1, 65535]\n"
        "int32[3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[3] string_values_default [\"\", \"max value\", \"min value\"]\n"
        "---\n"
        "bool[3] bool_values\n"
        "byte[3] byte_values\n"
        "char[3] char_values\n"
        "float32[3] float32_values\n"
        "float64[3] float64_values\n"
        "int8[3] int8_values\n"
        "uint8[3] uint8_values\n"
        "int16[3] int16_values\n"
        "uint16[3] uint16_values\n"
        "int32[3] int32_values\n"
        "uint32[3] uint32_values\n"
        "int64[3] int64_values\n"
        "uint64[3] uint64_values\n"
        "string[3] string_values\n"
        "BasicTypes[3] basic_types_values\n"
        "Constants[3] constants_values\n"
        "Defaults[3] defaults_values\n"
        "bool[3] bool_values_default [false, true, false]\n"
        "byte[3] byte_values_default [0, 1, 255]\n"
        "char[3] char_values_default [0, 1, 127]\n"
        "float32[3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[3] int8_values_default [0, 127, -128]\n"
        "uint8[3] uint8_values_default [0, 1, 255]\n"
        "int16[3] int16_values_default [0, 32767, -32768]\n"
        "uint16[3] uint16_values_default [0, 1, 65535]\n"
        "int32[3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[3] string_values_default [\"\", \"max value\", \"min value\"]\n"
    )
    Request = Arrays_Request
    Response = Arrays_Response
    Event = Arrays_Event


class BasicTypes_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/BasicTypes_Request``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/BasicTypes_Request"
    __ros_definition__: ClassVar[str] = (
        "bool bool_value\n"
        "byte byte_value\n"
        "char char_value\n"
        "float32 float32_value\n"
        "float64 float64_value\n"
        "int8 int8_value\n"
        "uint8 uint8_value\n"
        "int16 int16_value\n"
        "uint16 uint16_value\n"
        "int32 int32_value\n"
        "uint32 uint32_value\n"
        "int64 int64_value\n"
        "uint64 uint64_value\n"
        "string string_value\n"
    )

    bool_value: bool = False
    byte_value: _uint8 = 0
    char_value: _uint8 = 0
    float32_value: float = 0.0
    float64_value: float = 0.0
    int8_value: _int8 = 0
    uint8_value: _uint8 = 0
    int16_value: _int16 = 0
    uint16_value: _uint16 = 0
    int32_value: _int32 = 0
    uint32_value: _uint32 = 0
    int64_value: _int64 = 0
    uint64_value: _uint64 = 0
    string_value: str = ""


class BasicTypes_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/BasicTypes_Response``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/BasicTypes_Response"
    __ros_definition__: ClassVar[str] = (
        "bool bool_value\n"
        "byte byte_value\n"
        "char char_value\n"
        "float32 float32_value\n"
        "float64 float64_value\n"
        "int8 int8_value\n"
        "uint8 uint8_value\n"
        "int16 int16_value\n"
        "uint16 uint16_value\n"
        "int32 int32_value\n"
        "uint32 uint32_value\n"
        "int64 int64_value\n"
        "uint64 uint64_value\n"
        "string string_value\n"
    )

    bool_value: bool = False
    byte_value: _uint8 = 0
    char_value: _uint8 = 0
    float32_value: float = 0.0
    float64_value: float = 0.0
    int8_value: _int8 = 0
    uint8_value: _uint8 = 0
    int16_value: _int16 = 0
    uint16_value: _uint16 = 0
    int32_value: _int32 = 0
    uint32_value: _uint32 = 0
    int64_value: _int64 = 0
    uint64_value: _uint64 = 0
    string_value: str = ""


class BasicTypes_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/BasicTypes_Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/BasicTypes_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "test_msgs/srv/BasicTypes_Request[<=1] request\n"
        "test_msgs/srv/BasicTypes_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[BasicTypes_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[BasicTypes_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class BasicTypes:
    """``test_msgs/srv/BasicTypes``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/BasicTypes"
    __ros_definition__: ClassVar[str] = (
        "bool bool_value\n"
        "byte byte_value\n"
        "char char_value\n"
        "float32 float32_value\n"
        "float64 float64_value\n"
        "int8 int8_value\n"
        "uint8 uint8_value\n"
        "int16 int16_value\n"
        "uint16 uint16_value\n"
        "int32 int32_value\n"
        "uint32 uint32_value\n"
        "int64 int64_value\n"
        "uint64 uint64_value\n"
        "string string_value\n"
        "---\n"
        "bool bool_value\n"
        "byte byte_value\n"
        "char char_value\n"
        "float32 float32_value\n"
        "float64 float64_value\n"
        "int8 int8_value\n"
        "uint8 uint8_value\n"
        "int16 int16_value\n"
        "uint16 uint16_value\n"
        "int32 int32_value\n"
        "uint32 uint32_value\n"
        "int64 int64_value\n"
        "uint64 uint64_value\n"
        "string string_value\n"
    )
    Request = BasicTypes_Request
    Response = BasicTypes_Response
    Event = BasicTypes_Event


class Empty_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Empty_Request``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Empty_Request"
    __ros_definition__: ClassVar[str] = ""


class Empty_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Empty_Response``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Empty_Response"
    __ros_definition__: ClassVar[str] = ""


class Empty_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/srv/Empty_Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Empty_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "test_msgs/srv/Empty_Request[<=1] request\n"
        "test_msgs/srv/Empty_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Empty_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Empty_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Empty:
    """``test_msgs/srv/Empty``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "test_msgs/srv/Empty"
    __ros_definition__: ClassVar[str] = (
        "---\n"
    )
    Request = Empty_Request
    Response = Empty_Response
    Event = Empty_Event
