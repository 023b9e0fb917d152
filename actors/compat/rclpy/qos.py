"""``rclpy.qos``: actors' QoS (:mod:`actors.qos`), which has rclpy's names and semantics."""

from __future__ import annotations

from actors import qos as _qos
from actors.qos import *  # noqa: F403 - the whole of actors.qos, under rclpy's module name

__all__ = list(_qos.__all__)
