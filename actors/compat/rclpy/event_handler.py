"""``rclpy.event_handler``: QoS event callbacks and what they receive (:mod:`actors.ros.qos_events`).

A script node's event callbacks run when the script spins it, as its other callbacks do.
"""

from __future__ import annotations

from actors.ros import qos_events as _events
from actors.ros.qos_events import *  # noqa: F403 - the whole of actors.ros.qos_events, under rclpy's name

__all__ = list(_events.__all__)
