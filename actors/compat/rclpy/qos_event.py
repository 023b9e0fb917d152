"""``rclpy.qos_event``: the older name of ``rclpy.event_handler``."""

from __future__ import annotations

from actors.qos_events import (
    QoSRequestedDeadlineMissedInfo,
    QoSOfferedDeadlineMissedInfo,
    QoSLivelinessChangedInfo,
    QoSLivelinessLostInfo,
    QoSMessageLostInfo,
    QoSRequestedIncompatibleQoSInfo,
    QoSOfferedIncompatibleQoSInfo,
    QoSSubscriptionMatchedInfo,
    QoSPublisherMatchedInfo,
    IncompatibleTypeInfo,
    SubscriptionEventCallbacks,
    PublisherEventCallbacks,
)

__all__ = [
    "QoSRequestedDeadlineMissedInfo",
    "QoSOfferedDeadlineMissedInfo",
    "QoSLivelinessChangedInfo",
    "QoSLivelinessLostInfo",
    "QoSMessageLostInfo",
    "QoSRequestedIncompatibleQoSInfo",
    "QoSOfferedIncompatibleQoSInfo",
    "QoSSubscriptionMatchedInfo",
    "QoSPublisherMatchedInfo",
    "IncompatibleTypeInfo",
    "SubscriptionEventCallbacks",
    "PublisherEventCallbacks",
]
