"""Generated from example_interfaces/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held

__all__ = [
    "Bool",
    "Byte",
    "ByteMultiArray",
    "Char",
    "Empty",
    "Float32",
    "Float32MultiArray",
    "Float64",
    "Float64MultiArray",
    "Int16",
    "Int16MultiArray",
    "Int32",
    "Int32MultiArray",
    "Int64",
    "Int64MultiArray",
    "Int8",
    "Int8MultiArray",
    "MultiArrayDimension",
    "MultiArrayLayout",
    "String",
    "UInt16",
    "UInt16MultiArray",
    "UInt32",
    "UInt32MultiArray",
    "UInt64",
    "UInt64MultiArray",
    "UInt8",
    "UInt8MultiArray",
    "WString",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_int16 = Annotated[int, msgspec.Meta(ge=-32768, le=32767)]
_uint16 = Annotated[int, msgspec.Meta(ge=0, le=65535)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]
_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class Bool(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Bool``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Bool"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, bool.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "bool data\n"
    )

    data: bool = False


class Byte(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Byte``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Byte"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, byte.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "byte data\n"
    )

    data: _uint8 = 0


class MultiArrayDimension(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/MultiArrayDimension``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/MultiArrayDimension"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "string label   # label of given dimension\n"
        "uint32 size    # size of given dimension (in type units)\n"
        "uint32 stride  # stride of given dimension\n"
    )

    label: str = ""
    size: _uint32 = 0
    stride: _uint32 = 0


class MultiArrayLayout(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/MultiArrayLayout``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/MultiArrayLayout"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# The multiarray declares a generic multi-dimensional array of a\n"
        "# particular data type.  Dimensions are ordered from outer most\n"
        "# to inner most.\n"
        "#\n"
        "# Accessors should ALWAYS be written in terms of dimension stride\n"
        "# and specified outer-most dimension first.\n"
        "#\n"
        "# multiarray(i,j,k) = data[data_offset + dim_stride[1]*i + dim_stride[2]*j + k]\n"
        "#\n"
        "# A standard, 3-channel 640x480 image with interleaved color channels\n"
        "# would be specified as:\n"
        "#\n"
        "# dim[0].label  = \"height\"\n"
        "# dim[0].size   = 480\n"
        "# dim[0].stride = 3*640*480 = 921600  (note dim[0] stride is just size of image)\n"
        "# dim[1].label  = \"width\"\n"
        "# dim[1].size   = 640\n"
        "# dim[1].stride = 3*640 = 1920\n"
        "# dim[2].label  = \"channel\"\n"
        "# dim[2].size   = 3\n"
        "# dim[2].stride = 3\n"
        "#\n"
        "# multiarray(i,j,k) refers to the ith row, jth column, and kth channel.\n"
        "\n"
        "MultiArrayDimension[] dim # Array of dimension properties\n"
        "uint32 data_offset        # padding bytes at front of data\n"
    )

    dim: list[MultiArrayDimension] = msgspec.field(default_factory=list)
    data_offset: _uint32 = 0


class ByteMultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/ByteMultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/ByteMultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "byte[]            data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: bytes = b""


class Char(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Char``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Char"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, char.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "char data\n"
    )

    data: _uint8 = 0


class Empty(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Empty``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Empty"
    __ros_definition__: ClassVar[str] = (
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
    )


class Float32(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Float32``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Float32"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, float32.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "float32 data\n"
    )

    data: float = 0.0


class Float32MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Float32MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Float32MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "float32[]         data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "f":
            self.data = held(self.data, "f")


class Float64(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Float64``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Float64"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, float64.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "float64 data\n"
    )

    data: float = 0.0


class Float64MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Float64MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Float64MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "float64[]         data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "d":
            self.data = held(self.data, "d")


class Int16(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int16``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int16"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, int16.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "int16 data\n"
    )

    data: _int16 = 0


class Int16MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int16MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int16MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "int16[]           data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_int16] = msgspec.field(default_factory=lambda: array("h"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "h":
            self.data = held(self.data, "h")


class Int32(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int32``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int32"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, int32.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "int32 data\n"
    )

    data: _int32 = 0


class Int32MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int32MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int32MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "int32[]           data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "i":
            self.data = held(self.data, "i")


class Int64(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int64``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int64"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, int64.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "int64 data\n"
    )

    data: _int64 = 0


class Int64MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int64MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int64MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "int64[]           data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_int64] = msgspec.field(default_factory=lambda: array("q"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "q":
            self.data = held(self.data, "q")


class Int8(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int8``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int8"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, in8.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "int8 data\n"
    )

    data: _int8 = 0


class Int8MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/Int8MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/Int8MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "int8[]            data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_int8] = msgspec.field(default_factory=lambda: array("b"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "b":
            self.data = held(self.data, "b")


class String(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/String``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/String"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, string.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "string data\n"
    )

    data: str = ""


class UInt16(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt16``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt16"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, uint16.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "uint16 data\n"
    )

    data: _uint16 = 0


class UInt16MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt16MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt16MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "uint16[]            data        # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_uint16] = msgspec.field(default_factory=lambda: array("H"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "H":
            self.data = held(self.data, "H")


class UInt32(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt32``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt32"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, uint32.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "uint32 data\n"
    )

    data: _uint32 = 0


class UInt32MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt32MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt32MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "uint32[]          data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_uint32] = msgspec.field(default_factory=lambda: array("I"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "I":
            self.data = held(self.data, "I")


class UInt64(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt64``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt64"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, unint64.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "uint64 data\n"
    )

    data: _uint64 = 0


class UInt64MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt64MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt64MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "uint64[]          data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: MutableSequence[_uint64] = msgspec.field(default_factory=lambda: array("Q"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "Q":
            self.data = held(self.data, "Q")


class UInt8(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt8``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt8"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, uint8.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "uint8 data\n"
    )

    data: _uint8 = 0


class UInt8MultiArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/UInt8MultiArray``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/UInt8MultiArray"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of using complex datatypes.\n"
        "# It is not recommended to use directly.\n"
        "# To use a similar datastruct please define a custom message with appropriate semantic meaning.\n"
        "\n"
        "# Please look at the MultiArrayLayout message definition for\n"
        "# documentation on all multiarrays.\n"
        "\n"
        "MultiArrayLayout  layout        # specification of data layout\n"
        "uint8[]           data          # array of data\n"
    )

    layout: MultiArrayLayout = msgspec.field(default_factory=MultiArrayLayout)
    data: bytes = b""


class WString(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/msg/WString``."""

    __ros_type__: ClassVar[str] = "example_interfaces/msg/WString"
    __ros_definition__: ClassVar[str] = (
        "# This is an example message of using a primitive datatype, wstring.\n"
        "# If you want to test with this that's fine, but if you are deploying\n"
        "# it into a system you should create a semantically meaningful message type.\n"
        "# If you want to embed it in another message, use the primitive data type instead.\n"
        "wstring data\n"
    )

    data: str = ""
