"""``rclpy.topic_endpoint_info``: what ``get_publishers_info_by_topic`` returns, one per endpoint."""

from __future__ import annotations

from actors.ros.endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum

__all__ = ["TopicEndpointInfo", "TopicEndpointTypeEnum"]
