"""``rclpy.impl``: the implementation modules rclpy programs import directly (``logging_severity``)."""

__all__: list[str] = []
