"""Generated from type_description_interfaces/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "Field",
    "FieldType",
    "IndividualTypeDescription",
    "KeyValue",
    "TypeDescription",
    "TypeSource",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class FieldType(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/FieldType``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/FieldType"
    __ros_definition__: ClassVar[str] = (
        "# Represents the type of a field and related meta-data.\n"
        "\n"
        "# A constant for each type supported according to:\n"
        "#   http://design.ros2.org/articles/legacy_interface_definition.html\n"
        "# and:\n"
        "#   http://design.ros2.org/articles/idl_interface_definition.html\n"
        "# Order is loosely coupled to the order of appearance in the IDL 4.2 spec:\n"
        "#  https://www.omg.org/spec/IDL/4.2\n"
        "\n"
        "# Layout of constants across the 0-255 decimal values in the uint8:\n"
        "#\n"
        "# - 000    : Reserved for \"not set\"\n"
        "# - 001-048: Primitive types, strings, and reserved space for future primitive types\n"
        "# - 049-096: Fixed sized array of primitive and string types\n"
        "# - 097-144: Bounded Sequences of primitive and string types\n"
        "# - 145-192: Unbounded Sequences of primitive and string types\n"
        "# - 193-255: Reserved space for future array/sequence-like types\n"
        "\n"
        "uint8 FIELD_TYPE_NOT_SET = 0\n"
        "\n"
        "# Nested type defined in other .msg/.idl files.\n"
        "uint8 FIELD_TYPE_NESTED_TYPE = 1\n"
        "\n"
        "# Integer Types\n"
        "uint8 FIELD_TYPE_INT8 = 2\n"
        "uint8 FIELD_TYPE_UINT8 = 3\n"
        "uint8 FIELD_TYPE_INT16 = 4\n"
        "uint8 FIELD_TYPE_UINT16 = 5\n"
        "uint8 FIELD_TYPE_INT32 = 6\n"
        "uint8 FIELD_TYPE_UINT32 = 7\n"
        "uint8 FIELD_TYPE_INT64 = 8\n"
        "uint8 FIELD_TYPE_UINT64 = 9\n"
        "\n"
        "# Floating-Point Types\n"
        "uint8 FIELD_TYPE_FLOAT = 10\n"
        "uint8 FIELD_TYPE_DOUBLE = 11\n"
        "uint8 FIELD_TYPE_LONG_DOUBLE = 12\n"
        "\n"
        "# Char and WChar Types\n"
        "uint8 FIELD_TYPE_CHAR = 13\n"
        "uint8 FIELD_TYPE_WCHAR = 14\n"
        "\n"
        "# Boolean Type\n"
        "uint8 FIELD_TYPE_BOOLEAN = 15\n"
        "\n"
        "# Byte/Octet Type\n"
        "uint8 FIELD_TYPE_BYTE = 16\n"
        "\n"
        "# String Types\n"
        "uint8 FIELD_TYPE_STRING = 17\n"
        "uint8 FIELD_TYPE_WSTRING = 18\n"
        "\n"
        "# Fixed String Types\n"
        "uint8 FIELD_TYPE_FIXED_STRING = 19\n"
        "uint8 FIELD_TYPE_FIXED_WSTRING = 20\n"
        "\n"
        "# Bounded String Types\n"
        "uint8 FIELD_TYPE_BOUNDED_STRING = 21\n"
        "uint8 FIELD_TYPE_BOUNDED_WSTRING = 22\n"
        "\n"
        "# Fixed Sized Array Types\n"
        "uint8 FIELD_TYPE_NESTED_TYPE_ARRAY = 49\n"
        "uint8 FIELD_TYPE_INT8_ARRAY = 50\n"
        "uint8 FIELD_TYPE_UINT8_ARRAY = 51\n"
        "uint8 FIELD_TYPE_INT16_ARRAY = 52\n"
        "uint8 FIELD_TYPE_UINT16_ARRAY = 53\n"
        "uint8 FIELD_TYPE_INT32_ARRAY = 54\n"
        "uint8 FIELD_TYPE_UINT32_ARRAY = 55\n"
        "uint8 FIELD_TYPE_INT64_ARRAY = 56\n"
        "uint8 FIELD_TYPE_UINT64_ARRAY = 57\n"
        "uint8 FIELD_TYPE_FLOAT_ARRAY = 58\n"
        "uint8 FIELD_TYPE_DOUBLE_ARRAY = 59\n"
        "uint8 FIELD_TYPE_LONG_DOUBLE_ARRAY = 60\n"
        "uint8 FIELD_TYPE_CHAR_ARRAY = 61\n"
        "uint8 FIELD_TYPE_WCHAR_ARRAY = 62\n"
        "uint8 FIELD_TYPE_BOOLEAN_ARRAY = 63\n"
        "uint8 FIELD_TYPE_BYTE_ARRAY = 64\n"
        "uint8 FIELD_TYPE_STRING_ARRAY = 65\n"
        "uint8 FIELD_TYPE_WSTRING_ARRAY = 66\n"
        "uint8 FIELD_TYPE_FIXED_STRING_ARRAY = 67\n"
        "uint8 FIELD_TYPE_FIXED_WSTRING_ARRAY = 68\n"
        "uint8 FIELD_TYPE_BOUNDED_STRING_ARRAY = 69\n"
        "uint8 FIELD_TYPE_BOUNDED_WSTRING_ARRAY = 70\n"
        "\n"
        "# Bounded Sequence Types\n"
        "uint8 FIELD_TYPE_NESTED_TYPE_BOUNDED_SEQUENCE = 97\n"
        "uint8 FIELD_TYPE_INT8_BOUNDED_SEQUENCE = 98\n"
        "uint8 FIELD_TYPE_UINT8_BOUNDED_SEQUENCE = 99\n"
        "uint8 FIELD_TYPE_INT16_BOUNDED_SEQUENCE = 100\n"
        "uint8 FIELD_TYPE_UINT16_BOUNDED_SEQUENCE = 101\n"
        "uint8 FIELD_TYPE_INT32_BOUNDED_SEQUENCE = 102\n"
        "uint8 FIELD_TYPE_UINT32_BOUNDED_SEQUENCE = 103\n"
        "uint8 FIELD_TYPE_INT64_BOUNDED_SEQUENCE = 104\n"
        "uint8 FIELD_TYPE_UINT64_BOUNDED_SEQUENCE = 105\n"
        "uint8 FIELD_TYPE_FLOAT_BOUNDED_SEQUENCE = 106\n"
        "uint8 FIELD_TYPE_DOUBLE_BOUNDED_SEQUENCE = 107\n"
        "uint8 FIELD_TYPE_LONG_DOUBLE_BOUNDED_SEQUENCE = 108\n"
        "uint8 FIELD_TYPE_CHAR_BOUNDED_SEQUENCE = 109\n"
        "uint8 FIELD_TYPE_WCHAR_BOUNDED_SEQUENCE = 110\n"
        "uint8 FIELD_TYPE_BOOLEAN_BOUNDED_SEQUENCE = 111\n"
        "uint8 FIELD_TYPE_BYTE_BOUNDED_SEQUENCE = 112\n"
        "uint8 FIELD_TYPE_STRING_BOUNDED_SEQUENCE = 113\n"
        "uint8 FIELD_TYPE_WSTRING_BOUNDED_SEQUENCE = 114\n"
        "uint8 FIELD_TYPE_FIXED_STRING_BOUNDED_SEQUENCE = 115\n"
        "uint8 FIELD_TYPE_FIXED_WSTRING_BOUNDED_SEQUENCE = 116\n"
        "uint8 FIELD_TYPE_BOUNDED_STRING_BOUNDED_SEQUENCE = 117\n"
        "uint8 FIELD_TYPE_BOUNDED_WSTRING_BOUNDED_SEQUENCE = 118\n"
        "\n"
        "# Unbounded Sequence Types\n"
        "uint8 FIELD_TYPE_NESTED_TYPE_UNBOUNDED_SEQUENCE = 145\n"
        "uint8 FIELD_TYPE_INT8_UNBOUNDED_SEQUENCE = 146\n"
        "uint8 FIELD_TYPE_UINT8_UNBOUNDED_SEQUENCE = 147\n"
        "uint8 FIELD_TYPE_INT16_UNBOUNDED_SEQUENCE = 148\n"
        "uint8 FIELD_TYPE_UINT16_UNBOUNDED_SEQUENCE = 149\n"
        "uint8 FIELD_TYPE_INT32_UNBOUNDED_SEQUENCE = 150\n"
        "uint8 FIELD_TYPE_UINT32_UNBOUNDED_SEQUENCE = 151\n"
        "uint8 FIELD_TYPE_INT64_UNBOUNDED_SEQUENCE = 152\n"
        "uint8 FIELD_TYPE_UINT64_UNBOUNDED_SEQUENCE = 153\n"
        "uint8 FIELD_TYPE_FLOAT_UNBOUNDED_SEQUENCE = 154\n"
        "uint8 FIELD_TYPE_DOUBLE_UNBOUNDED_SEQUENCE = 155\n"
        "uint8 FIELD_TYPE_LONG_DOUBLE_UNBOUNDED_SEQUENCE = 156\n"
        "uint8 FIELD_TYPE_CHAR_UNBOUNDED_SEQUENCE = 157\n"
        "uint8 FIELD_TYPE_WCHAR_UNBOUNDED_SEQUENCE = 158\n"
        "uint8 FIELD_TYPE_BOOLEAN_UNBOUNDED_SEQUENCE = 159\n"
        "uint8 FIELD_TYPE_BYTE_UNBOUNDED_SEQUENCE = 160\n"
        "uint8 FIELD_TYPE_STRING_UNBOUNDED_SEQUENCE = 161\n"
        "uint8 FIELD_TYPE_WSTRING_UNBOUNDED_SEQUENCE = 162\n"
        "uint8 FIELD_TYPE_FIXED_STRING_UNBOUNDED_SEQUENCE = 163\n"
        "uint8 FIELD_TYPE_FIXED_WSTRING_UNBOUNDED_SEQUENCE = 164\n"
        "uint8 FIELD_TYPE_BOUNDED_STRING_UNBOUNDED_SEQUENCE = 165\n"
        "uint8 FIELD_TYPE_BOUNDED_WSTRING_UNBOUNDED_SEQUENCE = 166\n"
        "\n"
        "# Identifying number for the type of the field, using one of the above constants.\n"
        "uint8 type_id 0\n"
        "\n"
        "# Only used when the type is an array or a bounded sequence.\n"
        "# In the case of an array, this is the fixed capacity of the array.\n"
        "# In the case of a bounded sequence, this is the maximum capacity of the sequence.\n"
        "# In all other cases this field is unused.\n"
        "uint64 capacity\n"
        "\n"
        "# Only used when the type is a fixed or bounded string/wstring, or a array/sequence of those.\n"
        "# In the case of a fixed string/wstring, it is the fixed length of the string.\n"
        "# In the case of a bounded string/wstring, it is the maximum capacity of the string.\n"
        "# In the case of an array/sequence of fixed string/wstring, it is the fixed length of the strings.\n"
        "# In the case of an array/sequence of bounded string/wstring, it is the maximum capacity of the strings.\n"
        "# It is not currently possible to have different string capacities per element in the array/sequence.\n"
        "uint64 string_capacity\n"
        "\n"
        "# Only used when the type is a nested type or array/sequence of nested types.\n"
        "# This is limited to 255 characters.\n"
        "# TODO(wjwwood): this 255 character limit was chosen due to this being the limit\n"
        "#   for DDSI-RTPS based middlewares, which is the most commonly used right now.\n"
        "#   We lack a ROS 2 specific limit in our design documents, but we should update\n"
        "#   this and/or link to the design doc when that is available.\n"
        "string<=255 nested_type_name\n"
    )
    FIELD_TYPE_NOT_SET: ClassVar[int] = 0
    FIELD_TYPE_NESTED_TYPE: ClassVar[int] = 1
    FIELD_TYPE_INT8: ClassVar[int] = 2
    FIELD_TYPE_UINT8: ClassVar[int] = 3
    FIELD_TYPE_INT16: ClassVar[int] = 4
    FIELD_TYPE_UINT16: ClassVar[int] = 5
    FIELD_TYPE_INT32: ClassVar[int] = 6
    FIELD_TYPE_UINT32: ClassVar[int] = 7
    FIELD_TYPE_INT64: ClassVar[int] = 8
    FIELD_TYPE_UINT64: ClassVar[int] = 9
    FIELD_TYPE_FLOAT: ClassVar[int] = 10
    FIELD_TYPE_DOUBLE: ClassVar[int] = 11
    FIELD_TYPE_LONG_DOUBLE: ClassVar[int] = 12
    FIELD_TYPE_CHAR: ClassVar[int] = 13
    FIELD_TYPE_WCHAR: ClassVar[int] = 14
    FIELD_TYPE_BOOLEAN: ClassVar[int] = 15
    FIELD_TYPE_BYTE: ClassVar[int] = 16
    FIELD_TYPE_STRING: ClassVar[int] = 17
    FIELD_TYPE_WSTRING: ClassVar[int] = 18
    FIELD_TYPE_FIXED_STRING: ClassVar[int] = 19
    FIELD_TYPE_FIXED_WSTRING: ClassVar[int] = 20
    FIELD_TYPE_BOUNDED_STRING: ClassVar[int] = 21
    FIELD_TYPE_BOUNDED_WSTRING: ClassVar[int] = 22
    FIELD_TYPE_NESTED_TYPE_ARRAY: ClassVar[int] = 49
    FIELD_TYPE_INT8_ARRAY: ClassVar[int] = 50
    FIELD_TYPE_UINT8_ARRAY: ClassVar[int] = 51
    FIELD_TYPE_INT16_ARRAY: ClassVar[int] = 52
    FIELD_TYPE_UINT16_ARRAY: ClassVar[int] = 53
    FIELD_TYPE_INT32_ARRAY: ClassVar[int] = 54
    FIELD_TYPE_UINT32_ARRAY: ClassVar[int] = 55
    FIELD_TYPE_INT64_ARRAY: ClassVar[int] = 56
    FIELD_TYPE_UINT64_ARRAY: ClassVar[int] = 57
    FIELD_TYPE_FLOAT_ARRAY: ClassVar[int] = 58
    FIELD_TYPE_DOUBLE_ARRAY: ClassVar[int] = 59
    FIELD_TYPE_LONG_DOUBLE_ARRAY: ClassVar[int] = 60
    FIELD_TYPE_CHAR_ARRAY: ClassVar[int] = 61
    FIELD_TYPE_WCHAR_ARRAY: ClassVar[int] = 62
    FIELD_TYPE_BOOLEAN_ARRAY: ClassVar[int] = 63
    FIELD_TYPE_BYTE_ARRAY: ClassVar[int] = 64
    FIELD_TYPE_STRING_ARRAY: ClassVar[int] = 65
    FIELD_TYPE_WSTRING_ARRAY: ClassVar[int] = 66
    FIELD_TYPE_FIXED_STRING_ARRAY: ClassVar[int] = 67
    FIELD_TYPE_FIXED_WSTRING_ARRAY: ClassVar[int] = 68
    FIELD_TYPE_BOUNDED_STRING_ARRAY: ClassVar[int] = 69
    FIELD_TYPE_BOUNDED_WSTRING_ARRAY: ClassVar[int] = 70
    FIELD_TYPE_NESTED_TYPE_BOUNDED_SEQUENCE: ClassVar[int] = 97
    FIELD_TYPE_INT8_BOUNDED_SEQUENCE: ClassVar[int] = 98
    FIELD_TYPE_UINT8_BOUNDED_SEQUENCE: ClassVar[int] = 99
    FIELD_TYPE_INT16_BOUNDED_SEQUENCE: ClassVar[int] = 100
    FIELD_TYPE_UINT16_BOUNDED_SEQUENCE: ClassVar[int] = 101
    FIELD_TYPE_INT32_BOUNDED_SEQUENCE: ClassVar[int] = 102
    FIELD_TYPE_UINT32_BOUNDED_SEQUENCE: ClassVar[int] = 103
    FIELD_TYPE_INT64_BOUNDED_SEQUENCE: ClassVar[int] = 104
    FIELD_TYPE_UINT64_BOUNDED_SEQUENCE: ClassVar[int] = 105
    FIELD_TYPE_FLOAT_BOUNDED_SEQUENCE: ClassVar[int] = 106
    FIELD_TYPE_DOUBLE_BOUNDED_SEQUENCE: ClassVar[int] = 107
    FIELD_TYPE_LONG_DOUBLE_BOUNDED_SEQUENCE: ClassVar[int] = 108
    FIELD_TYPE_CHAR_BOUNDED_SEQUENCE: ClassVar[int] = 109
    FIELD_TYPE_WCHAR_BOUNDED_SEQUENCE: ClassVar[int] = 110
    FIELD_TYPE_BOOLEAN_BOUNDED_SEQUENCE: ClassVar[int] = 111
    FIELD_TYPE_BYTE_BOUNDED_SEQUENCE: ClassVar[int] = 112
    FIELD_TYPE_STRING_BOUNDED_SEQUENCE: ClassVar[int] = 113
    FIELD_TYPE_WSTRING_BOUNDED_SEQUENCE: ClassVar[int] = 114
    FIELD_TYPE_FIXED_STRING_BOUNDED_SEQUENCE: ClassVar[int] = 115
    FIELD_TYPE_FIXED_WSTRING_BOUNDED_SEQUENCE: ClassVar[int] = 116
    FIELD_TYPE_BOUNDED_STRING_BOUNDED_SEQUENCE: ClassVar[int] = 117
    FIELD_TYPE_BOUNDED_WSTRING_BOUNDED_SEQUENCE: ClassVar[int] = 118
    FIELD_TYPE_NESTED_TYPE_UNBOUNDED_SEQUENCE: ClassVar[int] = 145
    FIELD_TYPE_INT8_UNBOUNDED_SEQUENCE: ClassVar[int] = 146
    FIELD_TYPE_UINT8_UNBOUNDED_SEQUENCE: ClassVar[int] = 147
    FIELD_TYPE_INT16_UNBOUNDED_SEQUENCE: ClassVar[int] = 148
    FIELD_TYPE_UINT16_UNBOUNDED_SEQUENCE: ClassVar[int] = 149
    FIELD_TYPE_INT32_UNBOUNDED_SEQUENCE: ClassVar[int] = 150
    FIELD_TYPE_UINT32_UNBOUNDED_SEQUENCE: ClassVar[int] = 151
    FIELD_TYPE_INT64_UNBOUNDED_SEQUENCE: ClassVar[int] = 152
    FIELD_TYPE_UINT64_UNBOUNDED_SEQUENCE: ClassVar[int] = 153
    FIELD_TYPE_FLOAT_UNBOUNDED_SEQUENCE: ClassVar[int] = 154
    FIELD_TYPE_DOUBLE_UNBOUNDED_SEQUENCE: ClassVar[int] = 155
    FIELD_TYPE_LONG_DOUBLE_UNBOUNDED_SEQUENCE: ClassVar[int] = 156
    FIELD_TYPE_CHAR_UNBOUNDED_SEQUENCE: ClassVar[int] = 157
    FIELD_TYPE_WCHAR_UNBOUNDED_SEQUENCE: ClassVar[int] = 158
    FIELD_TYPE_BOOLEAN_UNBOUNDED_SEQUENCE: ClassVar[int] = 159
    FIELD_TYPE_BYTE_UNBOUNDED_SEQUENCE: ClassVar[int] = 160
    FIELD_TYPE_STRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 161
    FIELD_TYPE_WSTRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 162
    FIELD_TYPE_FIXED_STRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 163
    FIELD_TYPE_FIXED_WSTRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 164
    FIELD_TYPE_BOUNDED_STRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 165
    FIELD_TYPE_BOUNDED_WSTRING_UNBOUNDED_SEQUENCE: ClassVar[int] = 166

    type_id: _uint8 = 0
    capacity: _uint64 = 0
    string_capacity: _uint64 = 0
    nested_type_name: Annotated[str, msgspec.Meta(max_length=255)] = ""


class Field(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/Field``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/Field"
    __ros_definition__: ClassVar[str] = (
        "# Represents a single field in a type.\n"
        "\n"
        "# Name of the field.\n"
        "string name\n"
        "# Type of the field, including details about the type like length, nested name, etc.\n"
        "FieldType type\n"
        "# Literal default value of the field as a string, as it appeared in the original\n"
        "# message description file, whether that be .msg/.srv/.action or .idl.\n"
        "string default_value\n"
    )

    name: str = ""
    type: FieldType = msgspec.field(default_factory=FieldType)
    default_value: str = ""


class IndividualTypeDescription(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/IndividualTypeDescription``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/IndividualTypeDescription"
    __ros_definition__: ClassVar[str] = (
        "# Represents a single type, without the types it references, if any.\n"
        "\n"
        "# Name of the type.\n"
        "# This is limited to 255 characters.\n"
        "# TODO(wjwwood): this 255 character limit was chosen due to this being the limit\n"
        "#   for DDSI-RTPS based middlewares, which is the most commonly used right now.\n"
        "#   We lack a ROS 2 specific limit in our design documents, but we should update\n"
        "#   this and/or link to the design doc when that is available.\n"
        "string<=255 type_name\n"
        "# Fields of the type.\n"
        "Field[] fields\n"
    )

    type_name: Annotated[str, msgspec.Meta(max_length=255)] = ""
    fields: list[Field] = msgspec.field(default_factory=list)


class KeyValue(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/KeyValue``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/KeyValue"
    __ros_definition__: ClassVar[str] = (
        "# Represents an arbitrary key-value pair for application-specific information.\n"
        "\n"
        "string key\n"
        "string value\n"
    )

    key: str = ""
    value: str = ""


class TypeDescription(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/TypeDescription``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/TypeDescription"
    __ros_definition__: ClassVar[str] = (
        "# Represents a complete type description, including the type itself as well as the types it references.\n"
        "\n"
        "# Description of the type.\n"
        "IndividualTypeDescription type_description\n"
        "# Descriptions of all referenced types, recursively.\n"
        "IndividualTypeDescription[] referenced_type_descriptions\n"
    )

    type_description: IndividualTypeDescription = msgspec.field(default_factory=IndividualTypeDescription)
    referenced_type_descriptions: list[IndividualTypeDescription] = msgspec.field(default_factory=list)


class TypeSource(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/msg/TypeSource``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/msg/TypeSource"
    __ros_definition__: ClassVar[str] = (
        "# Represents the original source of a ROS 2 interface definition.\n"
        "\n"
        "# ROS interface type name, in PACKAGE/NAMESPACE/TYPENAME format.\n"
        "string type_name\n"
        "\n"
        "# The type of the original source file, typically matching the file extension.\n"
        "# Well-known encodings: \"idl\", \"msg\", \"srv\", \"action\", \"dynamic\", \"implicit\".\n"
        "# \"dynamic\" specifies a type created programmatically by a user, thus having no source.\n"
        "# \"implicit\" specifies a type created automatically as a subtype of a\n"
        "# complex type (service or action) - such as the request message for a service.\n"
        "# Implicit types will have no contents, the full source will be available on the parent srv/action.\n"
        "string encoding\n"
        "\n"
        "# Dumped contents of the interface definition source file.\n"
        "# If `encoding` is \"dynamic\" or \"implicit\", this field will be empty.\n"
        "string raw_file_contents\n"
    )

    type_name: str = ""
    encoding: str = ""
    raw_file_contents: str = ""
