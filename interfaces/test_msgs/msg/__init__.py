"""Generated from test_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Duration, Time

__all__ = [
    "Arrays",
    "BasicTypes",
    "BoundedPlainSequences",
    "BoundedSequences",
    "Builtins",
    "Constants",
    "Defaults",
    "Empty",
    "MultiNested",
    "Nested",
    "Strings",
    "UnboundedSequences",
    "WStrings",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_int16 = Annotated[int, msgspec.Meta(ge=-32768, le=32767)]
_uint16 = Annotated[int, msgspec.Meta(ge=0, le=65535)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]
_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class BasicTypes(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/BasicTypes``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/BasicTypes"
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


class Constants(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Constants``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Constants"
    __ros_definition__: ClassVar[str] = (
        "bool BOOL_CONST=true\n"
        "byte BYTE_CONST=50\n"
        "char CHAR_CONST=100\n"
        "float32 FLOAT32_CONST=1.125\n"
        "float64 FLOAT64_CONST=1.125\n"
        "int8 INT8_CONST=-50\n"
        "uint8 UINT8_CONST=200\n"
        "int16 INT16_CONST=-1000\n"
        "uint16 UINT16_CONST=2000\n"
        "int32 INT32_CONST=-30000\n"
        "uint32 UINT32_CONST=60000\n"
        "int64 INT64_CONST=-40000000\n"
        "uint64 UINT64_CONST=50000000\n"
    )
    BOOL_CONST: ClassVar[bool] = True
    BYTE_CONST: ClassVar[int] = 50
    CHAR_CONST: ClassVar[int] = 100
    FLOAT32_CONST: ClassVar[float] = 1.125
    FLOAT64_CONST: ClassVar[float] = 1.125
    INT8_CONST: ClassVar[int] = -50
    UINT8_CONST: ClassVar[int] = 200
    INT16_CONST: ClassVar[int] = -1000
    UINT16_CONST: ClassVar[int] = 2000
    INT32_CONST: ClassVar[int] = -30000
    UINT32_CONST: ClassVar[int] = 60000
    INT64_CONST: ClassVar[int] = -40000000
    UINT64_CONST: ClassVar[int] = 50000000


class Defaults(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Defaults``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Defaults"
    __ros_definition__: ClassVar[str] = (
        "bool bool_value true\n"
        "byte byte_value 50\n"
        "char char_value 100\n"
        "float32 float32_value 1.125\n"
        "float64 float64_value 1.125\n"
        "int8 int8_value -50\n"
        "uint8 uint8_value 200\n"
        "int16 int16_value -1000\n"
        "uint16 uint16_value 2000\n"
        "int32 int32_value -30000\n"
        "uint32 uint32_value 60000\n"
        "int64 int64_value -40000000\n"
        "uint64 uint64_value 50000000\n"
    )

    bool_value: bool = True
    byte_value: _uint8 = 50
    char_value: _uint8 = 100
    float32_value: float = 1.125
    float64_value: float = 1.125
    int8_value: _int8 = -50
    uint8_value: _uint8 = 200
    int16_value: _int16 = -1000
    uint16_value: _uint16 = 2000
    int32_value: _int32 = -30000
    uint32_value: _uint32 = 60000
    int64_value: _int64 = -40000000
    uint64_value: _uint64 = 50000000


class Arrays(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Arrays``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Arrays"
    __ros_definition__: ClassVar[str] = (
        "# Arrays of different types\n"
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
        "# Regression test: check alignment of basic field after an array field is correct\n"
        "int32 alignment_check\n"
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
    basic_types_values: Annotated[list[BasicTypes], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [BasicTypes() for _ in range(3)])
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
    alignment_check: _int32 = 0

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


class BoundedPlainSequences(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/BoundedPlainSequences``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/BoundedPlainSequences"
    __ros_definition__: ClassVar[str] = (
        "# Bounded sequences of different POD types\n"
        "bool[<=3] bool_values\n"
        "byte[<=3] byte_values\n"
        "char[<=3] char_values\n"
        "float32[<=3] float32_values\n"
        "float64[<=3] float64_values\n"
        "int8[<=3] int8_values\n"
        "uint8[<=3] uint8_values\n"
        "int16[<=3] int16_values\n"
        "uint16[<=3] uint16_values\n"
        "int32[<=3] int32_values\n"
        "uint32[<=3] uint32_values\n"
        "int64[<=3] int64_values\n"
        "uint64[<=3] uint64_values\n"
        "BasicTypes[<=3] basic_types_values\n"
        "Constants[<=3] constants_values\n"
        "Defaults[<=3] defaults_values\n"
        "bool[<=3] bool_values_default [false, true, false]\n"
        "byte[<=3] byte_values_default [0, 1, 255]\n"
        "char[<=3] char_values_default [0, 1, 127]\n"
        "float32[<=3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[<=3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[<=3] int8_values_default [0, 127, -128]\n"
        "uint8[<=3] uint8_values_default [0, 1, 255]\n"
        "int16[<=3] int16_values_default [0, 32767, -32768]\n"
        "uint16[<=3] uint16_values_default [0, 1, 65535]\n"
        "int32[<=3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[<=3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[<=3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[<=3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "# Regression test: check alignment of basic field after a sequence field is correct\n"
        "int32 alignment_check\n"
    )

    bool_values: Annotated[list[bool], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    byte_values: Annotated[bytes, msgspec.Meta(max_length=3)] = b""
    char_values: Annotated[MutableSequence[_uint8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("B"))
    float32_values: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("f"))
    float64_values: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("d"))
    int8_values: Annotated[MutableSequence[_int8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("b"))
    uint8_values: Annotated[bytes, msgspec.Meta(max_length=3)] = b""
    int16_values: Annotated[MutableSequence[_int16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("h"))
    uint16_values: Annotated[MutableSequence[_uint16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("H"))
    int32_values: Annotated[MutableSequence[_int32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("i"))
    uint32_values: Annotated[MutableSequence[_uint32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("I"))
    int64_values: Annotated[MutableSequence[_int64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("q"))
    uint64_values: Annotated[MutableSequence[_uint64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("Q"))
    basic_types_values: Annotated[list[BasicTypes], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    constants_values: Annotated[list[Constants], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    defaults_values: Annotated[list[Defaults], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    bool_values_default: Annotated[list[bool], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: [False, True, False])
    byte_values_default: Annotated[bytes, msgspec.Meta(max_length=3)] = b'\x00\x01\xff'
    char_values_default: Annotated[MutableSequence[_uint8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("B", [0, 1, 127]))
    float32_values_default: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("f", [1.125, 0.0, -1.125]))
    float64_values_default: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("d", [3.1415, 0.0, -3.1415]))
    int8_values_default: Annotated[MutableSequence[_int8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("b", [0, 127, -128]))
    uint8_values_default: Annotated[bytes, msgspec.Meta(max_length=3)] = b'\x00\x01\xff'
    int16_values_default: Annotated[MutableSequence[_int16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("h", [0, 32767, -32768]))
    uint16_values_default: Annotated[MutableSequence[_uint16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("H", [0, 1, 65535]))
    int32_values_default: Annotated[MutableSequence[_int32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("i", [0, 2147483647, -2147483648]))
    uint32_values_default: Annotated[MutableSequence[_uint32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("I", [0, 1, 4294967295]))
    int64_values_default: Annotated[MutableSequence[_int64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("q", [0, 9223372036854775807, -9223372036854775808]))
    uint64_values_default: Annotated[MutableSequence[_uint64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("Q", [0, 1, 18446744073709551615]))
    alignment_check: _int32 = 0

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


class BoundedSequences(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/BoundedSequences``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/BoundedSequences"
    __ros_definition__: ClassVar[str] = (
        "# Bounded sequences of different types\n"
        "bool[<=3] bool_values\n"
        "byte[<=3] byte_values\n"
        "char[<=3] char_values\n"
        "float32[<=3] float32_values\n"
        "float64[<=3] float64_values\n"
        "int8[<=3] int8_values\n"
        "uint8[<=3] uint8_values\n"
        "int16[<=3] int16_values\n"
        "uint16[<=3] uint16_values\n"
        "int32[<=3] int32_values\n"
        "uint32[<=3] uint32_values\n"
        "int64[<=3] int64_values\n"
        "uint64[<=3] uint64_values\n"
        "string[<=3] string_values\n"
        "BasicTypes[<=3] basic_types_values\n"
        "Constants[<=3] constants_values\n"
        "Defaults[<=3] defaults_values\n"
        "bool[<=3] bool_values_default [false, true, false]\n"
        "byte[<=3] byte_values_default [0, 1, 255]\n"
        "char[<=3] char_values_default [0, 1, 127]\n"
        "float32[<=3] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[<=3] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[<=3] int8_values_default [0, 127, -128]\n"
        "uint8[<=3] uint8_values_default [0, 1, 255]\n"
        "int16[<=3] int16_values_default [0, 32767, -32768]\n"
        "uint16[<=3] uint16_values_default [0, 1, 65535]\n"
        "int32[<=3] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[<=3] uint32_values_default [0, 1, 4294967295]\n"
        "int64[<=3] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[<=3] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[<=3] string_values_default [\"\", \"max value\", \"min value\"]\n"
        "# Regression test: check alignment of basic field after a sequence field is correct\n"
        "int32 alignment_check\n"
    )

    bool_values: Annotated[list[bool], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    byte_values: Annotated[bytes, msgspec.Meta(max_length=3)] = b""
    char_values: Annotated[MutableSequence[_uint8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("B"))
    float32_values: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("f"))
    float64_values: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("d"))
    int8_values: Annotated[MutableSequence[_int8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("b"))
    uint8_values: Annotated[bytes, msgspec.Meta(max_length=3)] = b""
    int16_values: Annotated[MutableSequence[_int16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("h"))
    uint16_values: Annotated[MutableSequence[_uint16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("H"))
    int32_values: Annotated[MutableSequence[_int32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("i"))
    uint32_values: Annotated[MutableSequence[_uint32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("I"))
    int64_values: Annotated[MutableSequence[_int64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("q"))
    uint64_values: Annotated[MutableSequence[_uint64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("Q"))
    string_values: Annotated[list[str], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    basic_types_values: Annotated[list[BasicTypes], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    constants_values: Annotated[list[Constants], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    defaults_values: Annotated[list[Defaults], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    bool_values_default: Annotated[list[bool], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: [False, True, False])
    byte_values_default: Annotated[bytes, msgspec.Meta(max_length=3)] = b'\x00\x01\xff'
    char_values_default: Annotated[MutableSequence[_uint8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("B", [0, 1, 127]))
    float32_values_default: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("f", [1.125, 0.0, -1.125]))
    float64_values_default: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("d", [3.1415, 0.0, -3.1415]))
    int8_values_default: Annotated[MutableSequence[_int8], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("b", [0, 127, -128]))
    uint8_values_default: Annotated[bytes, msgspec.Meta(max_length=3)] = b'\x00\x01\xff'
    int16_values_default: Annotated[MutableSequence[_int16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("h", [0, 32767, -32768]))
    uint16_values_default: Annotated[MutableSequence[_uint16], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("H", [0, 1, 65535]))
    int32_values_default: Annotated[MutableSequence[_int32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("i", [0, 2147483647, -2147483648]))
    uint32_values_default: Annotated[MutableSequence[_uint32], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("I", [0, 1, 4294967295]))
    int64_values_default: Annotated[MutableSequence[_int64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("q", [0, 9223372036854775807, -9223372036854775808]))
    uint64_values_default: Annotated[MutableSequence[_uint64], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("Q", [0, 1, 18446744073709551615]))
    string_values_default: Annotated[list[str], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: ["", "max value", "min value"])
    alignment_check: _int32 = 0

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


class Builtins(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Builtins``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Builtins"
    __ros_definition__: ClassVar[str] = (
        "builtin_interfaces/Duration duration_value\n"
        "builtin_interfaces/Time time_value\n"
    )

    duration_value: Duration = msgspec.field(default_factory=Duration)
    time_value: Time = msgspec.field(default_factory=Time)


class Empty(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Empty``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Empty"
    __ros_definition__: ClassVar[str] = ""


class UnboundedSequences(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/UnboundedSequences``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/UnboundedSequences"
    __ros_definition__: ClassVar[str] = (
        "# Unbounded sequences of different types\n"
        "bool[] bool_values\n"
        "byte[] byte_values\n"
        "char[] char_values\n"
        "float32[] float32_values\n"
        "float64[] float64_values\n"
        "int8[] int8_values\n"
        "uint8[] uint8_values\n"
        "int16[] int16_values\n"
        "uint16[] uint16_values\n"
        "int32[] int32_values\n"
        "uint32[] uint32_values\n"
        "int64[] int64_values\n"
        "uint64[] uint64_values\n"
        "string[] string_values\n"
        "BasicTypes[] basic_types_values\n"
        "Constants[] constants_values\n"
        "Defaults[] defaults_values\n"
        "bool[] bool_values_default [false, true, false]\n"
        "byte[] byte_values_default [0, 1, 255]\n"
        "char[] char_values_default [0, 1, 127]\n"
        "float32[] float32_values_default [1.125, 0.0, -1.125]\n"
        "float64[] float64_values_default [3.1415, 0.0, -3.1415]\n"
        "int8[] int8_values_default [0, 127, -128]\n"
        "uint8[] uint8_values_default [0, 1, 255]\n"
        "int16[] int16_values_default [0, 32767, -32768]\n"
        "uint16[] uint16_values_default [0, 1, 65535]\n"
        "int32[] int32_values_default [0, 2147483647, -2147483648]\n"
        "uint32[] uint32_values_default [0, 1, 4294967295]\n"
        "int64[] int64_values_default [0, 9223372036854775807, -9223372036854775808]\n"
        "uint64[] uint64_values_default [0, 1, 18446744073709551615]\n"
        "string[] string_values_default [\"\", \"max value\", \"min value\"]\n"
        "# Regression test: check alignment of basic field after a sequence field is correct\n"
        "int32 alignment_check\n"
    )

    bool_values: list[bool] = msgspec.field(default_factory=list)
    byte_values: bytes = b""
    char_values: MutableSequence[_uint8] = msgspec.field(default_factory=lambda: array("B"))
    float32_values: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))
    float64_values: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    int8_values: MutableSequence[_int8] = msgspec.field(default_factory=lambda: array("b"))
    uint8_values: bytes = b""
    int16_values: MutableSequence[_int16] = msgspec.field(default_factory=lambda: array("h"))
    uint16_values: MutableSequence[_uint16] = msgspec.field(default_factory=lambda: array("H"))
    int32_values: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i"))
    uint32_values: MutableSequence[_uint32] = msgspec.field(default_factory=lambda: array("I"))
    int64_values: MutableSequence[_int64] = msgspec.field(default_factory=lambda: array("q"))
    uint64_values: MutableSequence[_uint64] = msgspec.field(default_factory=lambda: array("Q"))
    string_values: list[str] = msgspec.field(default_factory=list)
    basic_types_values: list[BasicTypes] = msgspec.field(default_factory=list)
    constants_values: list[Constants] = msgspec.field(default_factory=list)
    defaults_values: list[Defaults] = msgspec.field(default_factory=list)
    bool_values_default: list[bool] = msgspec.field(default_factory=lambda: [False, True, False])
    byte_values_default: bytes = b'\x00\x01\xff'
    char_values_default: MutableSequence[_uint8] = msgspec.field(default_factory=lambda: array("B", [0, 1, 127]))
    float32_values_default: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f", [1.125, 0.0, -1.125]))
    float64_values_default: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d", [3.1415, 0.0, -3.1415]))
    int8_values_default: MutableSequence[_int8] = msgspec.field(default_factory=lambda: array("b", [0, 127, -128]))
    uint8_values_default: bytes = b'\x00\x01\xff'
    int16_values_default: MutableSequence[_int16] = msgspec.field(default_factory=lambda: array("h", [0, 32767, -32768]))
    uint16_values_default: MutableSequence[_uint16] = msgspec.field(default_factory=lambda: array("H", [0, 1, 65535]))
    int32_values_default: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i", [0, 2147483647, -2147483648]))
    uint32_values_default: MutableSequence[_uint32] = msgspec.field(default_factory=lambda: array("I", [0, 1, 4294967295]))
    int64_values_default: MutableSequence[_int64] = msgspec.field(default_factory=lambda: array("q", [0, 9223372036854775807, -9223372036854775808]))
    uint64_values_default: MutableSequence[_uint64] = msgspec.field(default_factory=lambda: array("Q", [0, 1, 18446744073709551615]))
    string_values_default: list[str] = msgspec.field(default_factory=lambda: ["", "max value", "min value"])
    alignment_check: _int32 = 0

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


class MultiNested(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/MultiNested``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/MultiNested"
    __ros_definition__: ClassVar[str] = (
        "# Mulitple levels of nested messages\n"
        "Arrays[3] array_of_arrays\n"
        "BoundedSequences[3] array_of_bounded_sequences\n"
        "UnboundedSequences[3] array_of_unbounded_sequences\n"
        "Arrays[<=3] bounded_sequence_of_arrays\n"
        "BoundedSequences[<=3] bounded_sequence_of_bounded_sequences\n"
        "UnboundedSequences[<=3] bounded_sequence_of_unbounded_sequences\n"
        "Arrays[] unbounded_sequence_of_arrays\n"
        "BoundedSequences[] unbounded_sequence_of_bounded_sequences\n"
        "UnboundedSequences[] unbounded_sequence_of_unbounded_sequences\n"
    )

    array_of_arrays: Annotated[list[Arrays], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [Arrays() for _ in range(3)])
    array_of_bounded_sequences: Annotated[list[BoundedSequences], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [BoundedSequences() for _ in range(3)])
    array_of_unbounded_sequences: Annotated[list[UnboundedSequences], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [UnboundedSequences() for _ in range(3)])
    bounded_sequence_of_arrays: Annotated[list[Arrays], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    bounded_sequence_of_bounded_sequences: Annotated[list[BoundedSequences], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    bounded_sequence_of_unbounded_sequences: Annotated[list[UnboundedSequences], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    unbounded_sequence_of_arrays: list[Arrays] = msgspec.field(default_factory=list)
    unbounded_sequence_of_bounded_sequences: list[BoundedSequences] = msgspec.field(default_factory=list)
    unbounded_sequence_of_unbounded_sequences: list[UnboundedSequences] = msgspec.field(default_factory=list)


class Nested(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Nested``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Nested"
    __ros_definition__: ClassVar[str] = (
        "BasicTypes basic_types_value\n"
    )

    basic_types_value: BasicTypes = msgspec.field(default_factory=BasicTypes)


class Strings(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/Strings``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/Strings"
    __ros_definition__: ClassVar[str] = (
        "string string_value\n"
        "string string_value_default1 \"Hello world!\"\n"
        "string string_value_default2 \"Hello'world!\"\n"
        "string string_value_default3 'Hello\"world!'\n"
        "string string_value_default4 'Hello\\'world!'\n"
        "string string_value_default5 \"Hello\\\"world!\"\n"
        "string STRING_CONST=\"Hello world!\"\n"
        "string<=22 bounded_string_value\n"
        "string<=22 bounded_string_value_default1 \"Hello world!\"\n"
        "string<=22 bounded_string_value_default2 \"Hello'world!\"\n"
        "string<=22 bounded_string_value_default3 'Hello\"world!'\n"
        "string<=22 bounded_string_value_default4 'Hello\\'world!'\n"
        "string<=22 bounded_string_value_default5 \"Hello\\\"world!\"\n"
    )
    STRING_CONST: ClassVar[str] = "Hello world!"

    string_value: str = ""
    string_value_default1: str = "Hello world!"
    string_value_default2: str = "Hello'world!"
    string_value_default3: str = "Hello\"world!"
    string_value_default4: str = "Hello'world!"
    string_value_default5: str = "Hello\"world!"
    bounded_string_value: Annotated[str, msgspec.Meta(max_length=22)] = ""
    bounded_string_value_default1: Annotated[str, msgspec.Meta(max_length=22)] = "Hello world!"
    bounded_string_value_default2: Annotated[str, msgspec.Meta(max_length=22)] = "Hello'world!"
    bounded_string_value_default3: Annotated[str, msgspec.Meta(max_length=22)] = "Hello\"world!"
    bounded_string_value_default4: Annotated[str, msgspec.Meta(max_length=22)] = "Hello'world!"
    bounded_string_value_default5: Annotated[str, msgspec.Meta(max_length=22)] = "Hello\"world!"


class WStrings(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``test_msgs/msg/WStrings``."""

    __ros_type__: ClassVar[str] = "test_msgs/msg/WStrings"
    __ros_definition__: ClassVar[str] = (
        "wstring wstring_value\n"
        "wstring wstring_value_default1 \"Hello world!\"\n"
        "wstring wstring_value_default2 \"Hellö wörld!\"\n"
        "wstring wstring_value_default3 \"ハローワールド\"\n"
        "#wstring WSTRING_CONST=\"Hello world!\"\n"
        "#wstring<=22 bounded_wstring_value\n"
        "#wstring<=22 bounded_wstring_value_default1 \"Hello world!\"\n"
        "wstring[3] array_of_wstrings\n"
        "wstring[<=3] bounded_sequence_of_wstrings\n"
        "wstring[] unbounded_sequence_of_wstrings\n"
    )

    wstring_value: str = ""
    wstring_value_default1: str = "Hello world!"
    wstring_value_default2: str = "Hellö wörld!"
    wstring_value_default3: str = "ハローワールド"
    array_of_wstrings: Annotated[list[str], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: [""] * 3)
    bounded_sequence_of_wstrings: Annotated[list[str], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=list)
    unbounded_sequence_of_wstrings: list[str] = msgspec.field(default_factory=list)
