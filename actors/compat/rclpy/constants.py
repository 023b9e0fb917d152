"""``rclpy.constants``."""

__all__ = ["S_TO_NS"]

S_TO_NS = 1_000_000_000
