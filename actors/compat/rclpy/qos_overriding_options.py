"""``rclpy.qos_overriding_options``: a publisher's or subscription's QoS taken from read-only parameters.

Created with ``qos_overriding_options=``, an endpoint declares one parameter
per chosen policy, ``qos_overrides.<topic>.<publisher|subscription>[_<id>].<policy>``,
whose default is the profile's own value (enum policies as lower-case names,
durations in nanoseconds).  A value given for it at start (``--ros-args -p``,
a parameters file, ``parameter_overrides``) replaces that policy in the
profile the endpoint is made with; the options' callback then judges the
result, and a refusal raises InvalidQosOverridesError.  The parameters are
read-only: QoS is fixed once the endpoint exists, as in ROS.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from actors.compat.rclpy.publisher import Publisher
from actors.compat.rclpy.subscription import Subscription
from actors.errors import ParameterAlreadyDeclaredException
from actors.ros import qos as _qos
from actors.ros.qos import QoSPolicyKind, QoSProfile
from actors.ros.time import Duration
from interfaces.rcl_interfaces.msg import ParameterDescriptor, SetParametersResult

__all__ = ["InvalidQosOverridesError", "QosCallbackResult", "QosCallbackType", "QoSOverridingOptions"]

#: What a validation callback returns: ``successful``, and a ``reason`` when not.
QosCallbackResult = SetParametersResult
QosCallbackType = Callable[[QoSProfile], SetParametersResult]

_ENUM_POLICIES = {
    QoSPolicyKind.HISTORY: _qos.HistoryPolicy,
    QoSPolicyKind.RELIABILITY: _qos.ReliabilityPolicy,
    QoSPolicyKind.DURABILITY: _qos.DurabilityPolicy,
    QoSPolicyKind.LIVELINESS: _qos.LivelinessPolicy,
}
_DURATION_POLICIES = {QoSPolicyKind.LIFESPAN, QoSPolicyKind.DEADLINE, QoSPolicyKind.LIVELINESS_LEASE_DURATION}
# The policies a profile holds (not INVALID); a subscription has no lifespan.
_PROFILE_POLICIES = [*_ENUM_POLICIES, QoSPolicyKind.DEPTH, *_DURATION_POLICIES]


class InvalidQosOverridesError(Exception):
    """The options' callback refused the QoS profile the overrides made."""


class QoSOverridingOptions:
    """Which policies of an endpoint get a parameter, the callback that validates them, and an id."""

    def __init__(
        self,
        policy_kinds: Iterable[QoSPolicyKind],
        *,
        callback: QosCallbackType | None = None,
        entity_id: str | None = None,
    ) -> None:
        self._policy_kinds = policy_kinds
        self._callback = callback
        self._entity_id = entity_id

    @property
    def policy_kinds(self) -> Iterable[QoSPolicyKind]:
        """The policies that get a parameter."""
        return self._policy_kinds

    @property
    def callback(self) -> QosCallbackType | None:
        """The validation callback, called with the overridden profile."""
        return self._callback

    @property
    def entity_id(self) -> str | None:
        """What tells apart two endpoints of one node on one topic in the parameters' names."""
        return self._entity_id

    @classmethod
    def with_default_policies(
        cls, *, callback: QosCallbackType | None = None, entity_id: str | None = None
    ) -> QoSOverridingOptions:
        """Options for history, depth and reliability, ROS's default choice."""
        policies = (QoSPolicyKind.HISTORY, QoSPolicyKind.DEPTH, QoSPolicyKind.RELIABILITY)
        return cls(policies, callback=callback, entity_id=entity_id)


def _declare_qos_parameters(
    entity_type: type, node: Any, topic_name: str, qos: QoSProfile, options: QoSOverridingOptions
) -> None:
    """Declare (or read, when declared already) ``options``' parameters and write their values into ``qos``.

    ``entity_type`` is rclpy's Publisher or Subscription class; ``topic_name``
    the endpoint's full topic name.  Raises InvalidQosOverridesError when the
    options' callback refuses the result, TypeError for another entity type.
    """
    if not (isinstance(entity_type, type) and issubclass(entity_type, (Publisher, Subscription))):
        raise TypeError("Argument `entity_type` should be a subclass of Publisher or Subscription")
    kind = "publisher" if issubclass(entity_type, Publisher) else "subscription"
    prefix = f"qos_overrides.{topic_name}.{kind}{'' if options.entity_id is None else '_' + options.entity_id}"
    about = f"for {kind} `{topic_name}` with id `{options.entity_id}`"
    for policy in options.policy_kinds:
        if policy not in _PROFILE_POLICIES or (kind == "subscription" and policy == QoSPolicyKind.LIFESPAN):
            continue
        name = f"{prefix}.{policy.name.lower()}"
        descriptor = ParameterDescriptor(description=f"{policy.name.lower()} {about}", read_only=True)
        try:
            parameter = node.declare_parameter(name, _get_qos_policy_parameter(qos, policy), descriptor)
        except ParameterAlreadyDeclaredException:
            parameter = node.get_parameter(name)
        _override(qos, policy, parameter.value)
    if options.callback is not None:
        result = options.callback(qos)
        if not result.successful:
            raise InvalidQosOverridesError(f"Provided QoS overrides {about}, are not valid: {result.reason}")


def _get_qos_policy_parameter(qos: QoSProfile, policy: QoSPolicyKind) -> str | int | bool:
    """The parameter value of ``policy`` in ``qos``: a lower-case name, a count or nanoseconds."""
    value = getattr(qos, policy.name.lower())
    if policy in _ENUM_POLICIES:
        if value.name == "UNKNOWN":
            raise ValueError("User provided QoS profile is invalid")
        return str(value.name.lower())
    if isinstance(value, Duration):
        return value.nanoseconds
    return value  # depth: an int


def _override(qos: QoSProfile, policy: QoSPolicyKind, value: Any) -> None:
    # Write a parameter's value back into the profile, in the policy's own type.
    if policy in _ENUM_POLICIES:
        try:
            value = _ENUM_POLICIES[policy][str(value).upper()]
        except KeyError:
            raise RuntimeError(f"Unexpected QoS override for policy `{policy.name.lower()}`: `{value}`") from None
    elif policy in _DURATION_POLICIES:
        value = Duration(nanoseconds=value)
    setattr(qos, policy.name.lower(), value)
