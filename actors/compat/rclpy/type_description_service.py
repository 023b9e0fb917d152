"""``rclpy.type_description_service``: the name of the parameter that switches ``~/get_type_description`` on."""

from __future__ import annotations

__all__ = ["START_TYPE_DESCRIPTION_SERVICE_PARAM"]

START_TYPE_DESCRIPTION_SERVICE_PARAM = "start_type_description_service"
