"""``rclpy.impl.implementation_singleton``: a Python stand-in for the parts of rclpy's C extension programs reach.

rclpy's ``rclpy_implementation`` is its compiled extension.  Programs and tests
reach into it for a few names: the middleware's identifier, the errors ROS
arguments raise, and the predefined QoS profiles as plain dictionaries.  This
stand-in has those names, with actors' behaviour behind them; anything else
of the extension (wait sets, raw handles) is absent.
"""

from __future__ import annotations

from types import SimpleNamespace

from actors.compat.rclpy.utilities import get_rmw_implementation_identifier
from actors.errors import RosArgsError
from actors.ros import qos as _qos

__all__ = ["rclpy_implementation"]


class _PredefinedQoS:
    """``rmw_qos_profile_t``: ``predefined(name)`` is the named profile's PolicyRecord."""

    @staticmethod
    def predefined(name: str) -> _qos.PolicyRecord:
        """The profile ``qos_profile_<...>`` of that name; ValueError for an unknown one."""
        profile = getattr(_qos, name, None)
        if not name.startswith("qos_profile_") or not isinstance(profile, _qos.QoSProfile):
            raise ValueError(f"unknown predefined QoS profile {name!r}")
        return profile.get_c_qos_profile()


rclpy_implementation = SimpleNamespace(
    rclpy_get_rmw_implementation_identifier=get_rmw_implementation_identifier,
    # Both of rcl's ROS-argument errors are actors' RosArgsError, whose text names the argument.
    UnknownROSArgsError=RosArgsError,
    RCLInvalidROSArgsError=RosArgsError,
    rmw_qos_profile_t=_PredefinedQoS,
)
