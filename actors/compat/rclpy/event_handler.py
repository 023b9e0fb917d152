"""``rclpy.event_handler``: QoS event callbacks and what they receive (:mod:`actors.qos_events`).

A script node's event callbacks run when the script spins it, as its other callbacks do.
"""

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
