"""``rclpy.parameter``: actors' Parameter and its types."""

from __future__ import annotations

from actors.params import Parameter, ParameterType

__all__ = ["Parameter", "ParameterType"]
