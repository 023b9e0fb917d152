"""Generated from statistics_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.builtin_interfaces.msg import Time

__all__ = [
    "MetricsMessage",
    "StatisticDataPoint",
    "StatisticDataType",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class StatisticDataPoint(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``statistics_msgs/msg/StatisticDataPoint``."""

    __ros_type__: ClassVar[str] = "statistics_msgs/msg/StatisticDataPoint"
    __ros_definition__: ClassVar[str] = (
        "#############################################\n"
        "# This holds the structure of a single data point of a StatisticDataType.\n"
        "#\n"
        "# This message is used in MetricsStatisticsMessage, defined in MetricsStatisticsMessage.msg.\n"
        "#\n"
        "# Examples of the value of data point are\n"
        "# - average size of messages received\n"
        "# - standard deviation of the period of messages published\n"
        "# - maximum age of messages published\n"
        "#\n"
        "# A value of nan represents no data is available.\n"
        "# One example is that standard deviation is only available when there are two or more data points but there is only one,\n"
        "# and in this case the value would be nan.\n"
        "# +inf and -inf are not allowed.\n"
        "#\n"
        "#############################################\n"
        "\n"
        "# The statistic type of this data point, defined in StatisticDataType.msg\n"
        "# Default value should be StatisticDataType.STATISTICS_DATA_TYPE_UNINITIALIZED (0).\n"
        "uint8 data_type\n"
        "\n"
        "# The value of the data point\n"
        "float64 data\n"
    )

    data_type: _uint8 = 0
    data: float = 0.0


class MetricsMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``statistics_msgs/msg/MetricsMessage``."""

    __ros_type__: ClassVar[str] = "statistics_msgs/msg/MetricsMessage"
    __ros_definition__: ClassVar[str] = (
        "#############################################\n"
        "# A generic metrics message providing statistics for measurements from different sources. For example,\n"
        "# measure a system's CPU % for a given window yields the following data points over a window of time:\n"
        "#\n"
        "#   - average cpu %\n"
        "#   - std deviation\n"
        "#   - min\n"
        "#   - max\n"
        "#   - sample count\n"
        "#\n"
        "# These are all represented as different 'StatisticDataPoint's.\n"
        "#############################################\n"
        "\n"
        "# Name metric measurement source, e.g., node, topic, or process name\n"
        "string measurement_source_name\n"
        "\n"
        "# Name of the metric being measured, e.g. cpu_percentage, free_memory_mb, message_age, etc.\n"
        "string metrics_source\n"
        "\n"
        "# Unit of measure of the metric, e.g. percent, mb, seconds, etc.\n"
        "string unit\n"
        "\n"
        "# Measurement window start time\n"
        "builtin_interfaces/Time window_start\n"
        "\n"
        "# Measurement window end time\n"
        "builtin_interfaces/Time window_stop\n"
        "\n"
        "# A list of statistics data point, defined in StatisticDataPoint.msg\n"
        "StatisticDataPoint[] statistics\n"
    )

    measurement_source_name: str = ""
    metrics_source: str = ""
    unit: str = ""
    window_start: Time = msgspec.field(default_factory=Time)
    window_stop: Time = msgspec.field(default_factory=Time)
    statistics: list[StatisticDataPoint] = msgspec.field(default_factory=list)


class StatisticDataType(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``statistics_msgs/msg/StatisticDataType``."""

    __ros_type__: ClassVar[str] = "statistics_msgs/msg/StatisticDataType"
    __ros_definition__: ClassVar[str] = (
        "#############################################\n"
        "# This file contains the commonly used constants for the statistics data type.\n"
        "#\n"
        "# The value 0 is reserved for unitialized statistic message data type.\n"
        "# Range of values: [0, 255].\n"
        "# Unallowed values: any value that is not specified in this file.\n"
        "#\n"
        "#############################################\n"
        "\n"
        "# Constant for uninitialized\n"
        "uint8 STATISTICS_DATA_TYPE_UNINITIALIZED = 0\n"
        "\n"
        "# Allowed values\n"
        "uint8 STATISTICS_DATA_TYPE_AVERAGE = 1\n"
        "uint8 STATISTICS_DATA_TYPE_MINIMUM = 2\n"
        "uint8 STATISTICS_DATA_TYPE_MAXIMUM = 3\n"
        "uint8 STATISTICS_DATA_TYPE_STDDEV = 4\n"
        "uint8 STATISTICS_DATA_TYPE_SAMPLE_COUNT = 5\n"
    )
    STATISTICS_DATA_TYPE_UNINITIALIZED: ClassVar[int] = 0
    STATISTICS_DATA_TYPE_AVERAGE: ClassVar[int] = 1
    STATISTICS_DATA_TYPE_MINIMUM: ClassVar[int] = 2
    STATISTICS_DATA_TYPE_MAXIMUM: ClassVar[int] = 3
    STATISTICS_DATA_TYPE_STDDEV: ClassVar[int] = 4
    STATISTICS_DATA_TYPE_SAMPLE_COUNT: ClassVar[int] = 5
