"""``rclpy.impl.logging_severity``: the severities, as :mod:`actors.ros.log` numbers them."""

from actors.ros.log import LoggingSeverity

__all__ = ["LoggingSeverity"]
