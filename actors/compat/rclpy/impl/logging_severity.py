"""``rclpy.impl.logging_severity``: the severities, as :mod:`actors.log` numbers them."""

from actors.log import LoggingSeverity

__all__ = ["LoggingSeverity"]
