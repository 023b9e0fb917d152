"""``rclpy.topic_or_service_is_hidden``: whether a name is hidden (a part of it starts with ``_``)."""

from __future__ import annotations

from actors.ros.names import is_hidden_name as topic_or_service_is_hidden

__all__ = ["topic_or_service_is_hidden"]
