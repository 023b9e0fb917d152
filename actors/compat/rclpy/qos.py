"""``rclpy.qos``: actors' QoS (:mod:`actors.ros.qos`), which has rclpy's names and semantics."""

from __future__ import annotations

from actors.ros import qos as _qos
from actors.ros.qos import *  # noqa: F403 - the whole of actors.ros.qos, under rclpy's module name

__all__ = list(_qos.__all__)
