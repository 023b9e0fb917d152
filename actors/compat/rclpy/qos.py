"""``rclpy.qos``: actors' QoS profiles and policies, under rclpy's names."""

from __future__ import annotations

from actors.topics import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
    qos_profile_system_default,
)

__all__ = [
    "QoSProfile",
    "HistoryPolicy",
    "ReliabilityPolicy",
    "DurabilityPolicy",
    "QoSHistoryPolicy",
    "QoSReliabilityPolicy",
    "QoSDurabilityPolicy",
    "qos_profile_sensor_data",
    "qos_profile_system_default",
]

QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
