"""QoS profiles as rclpy's: validation, mutability, presets, policy enums, the compatibility check, snapshots."""

from __future__ import annotations

import msgspec
import pytest

from actors.errors import InvalidQoSProfileException
from actors.ros.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    LivelinessPolicy,
    QoSCompatibility,
    QoSDurabilityPolicy,
    QoSHistoryPolicy,
    QoSLivelinessPolicy,
    QoSPolicyKind,
    QoSPresetProfiles,
    QoSProfile,
    QoSReliabilityPolicy,
    QoSSnapshot,
    ReliabilityPolicy,
    as_qos,
    qos_check_compatible,
    qos_incompatibility,
    qos_policy_name_from_kind,
    qos_profile_action_status_default,
    qos_profile_best_available,
    qos_profile_default,
    qos_profile_parameter_events,
    qos_profile_parameters,
    qos_profile_rosout_default,
    qos_profile_sensor_data,
    qos_profile_services_default,
    qos_profile_system_default,
    qos_profile_unknown,
)
from actors.ros.time import Duration, Infinite


def test_a_profile_needs_a_history_or_a_depth():
    with pytest.raises(InvalidQoSProfileException):
        QoSProfile()
    with pytest.raises(InvalidQoSProfileException):
        QoSProfile(history=HistoryPolicy.KEEP_LAST)
    assert QoSProfile(history=HistoryPolicy.KEEP_ALL).history is HistoryPolicy.KEEP_ALL
    profile = QoSProfile(depth=7)
    assert (profile.history, profile.depth) == (HistoryPolicy.KEEP_LAST, 7)
    assert profile.reliability is ReliabilityPolicy.RELIABLE and profile.durability is DurabilityPolicy.VOLATILE
    assert profile.liveliness is LivelinessPolicy.SYSTEM_DEFAULT and profile.deadline == Duration()
    with pytest.warns(UserWarning, match="zero depth"):
        QoSProfile(depth=0)
    with pytest.raises(ValueError):
        QoSProfile(depth=-1)


def test_a_profile_is_mutable_and_keeps_enum_members():
    profile = QoSProfile(depth=5)
    profile.reliability = 2  # a number becomes the member, so `is` works as rclpy code uses it
    assert profile.reliability is QoSReliabilityPolicy.BEST_EFFORT
    profile.durability = QoSDurabilityPolicy.TRANSIENT_LOCAL
    profile.deadline = Duration(seconds=2)
    profile.depth = 8
    assert profile == QoSProfile(
        depth=8,
        reliability=ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
        deadline=Duration(seconds=2),
    )
    assert profile != QoSProfile(depth=8)
    with pytest.raises(TypeError):
        hash(profile)
    with pytest.raises(TypeError):
        profile.deadline = 2.0  # a Duration, as rclpy asks
    with pytest.raises(TypeError):
        profile.reliability = "reliable"
    with pytest.raises(ValueError):
        profile.liveliness = 2  # no liveliness has that number
    with pytest.raises(TypeError):
        profile.avoid_ros_namespace_conventions = 1


def test_rclpys_alias_names_are_the_same_classes():
    assert QoSHistoryPolicy is HistoryPolicy and QoSReliabilityPolicy is ReliabilityPolicy
    assert QoSDurabilityPolicy is DurabilityPolicy and QoSLivelinessPolicy is LivelinessPolicy
    assert ReliabilityPolicy.short_keys() == ["system_default", "reliable", "best_effort", "unknown", "best_available"]
    assert ReliabilityPolicy.get_from_short_key("Best_Effort") == 2
    assert LivelinessPolicy.MANUAL_BY_TOPIC.short_key == "manual_by_topic"
    assert qos_policy_name_from_kind(QoSPolicyKind.DEADLINE) == "DEADLINE"
    assert int(QoSPolicyKind.LIVELINESS_LEASE_DURATION) == 256


# (history, depth, reliability, durability, lifespan ns, deadline ns, liveliness, lease ns) of rclpy Kilted's presets.
PRESETS = {
    "unknown": (qos_profile_unknown, (3, 0, 3, 3, 0, 0, 4, 0)),
    "default": (qos_profile_default, (1, 10, 1, 2, 0, 0, 0, 0)),
    "system_default": (qos_profile_system_default, (0, 0, 0, 0, 0, 0, 0, 0)),
    "sensor_data": (qos_profile_sensor_data, (1, 5, 2, 2, 0, 0, 0, 0)),
    "services_default": (qos_profile_services_default, (1, 10, 1, 2, 0, 0, 0, 0)),
    "parameters": (qos_profile_parameters, (1, 1000, 1, 2, 0, 0, 0, 0)),
    "parameter_events": (qos_profile_parameter_events, (1, 1000, 1, 2, 0, 0, 0, 0)),
    "action_status_default": (qos_profile_action_status_default, (1, 1, 1, 1, 0, 0, 0, 0)),
    "best_available": (qos_profile_best_available, (1, 10, 4, 4, 0, 2**63 - 2, 5, 2**63 - 2)),
    "rosout_default": (qos_profile_rosout_default, (1, 1000, 1, 1, 10**10, 0, 0, 0)),
}


@pytest.mark.parametrize("key", list(PRESETS))
def test_every_preset_has_rclpys_values(key):
    profile, expected = PRESETS[key]
    values = (
        profile.history,
        profile.depth,
        profile.reliability,
        profile.durability,
        profile.lifespan.nanoseconds,
        profile.deadline.nanoseconds,
        profile.liveliness,
        profile.liveliness_lease_duration.nanoseconds,
    )
    assert tuple(int(v) for v in values) == expected
    assert QoSPresetProfiles.get_from_short_key(key) == profile  # equal presets are one member, as in rclpy


def test_the_preset_names():
    assert QoSPresetProfiles.short_keys() == [
        "unknown",
        "default",
        "system_default",
        "sensor_data",
        "services_default",
        "parameters",
        "parameter_events",
        "action_status_default",
        "best_available",
        "rosout_default",
    ]
    assert QoSPresetProfiles.SENSOR_DATA.value.depth == 5


def profile(**policies) -> QoSProfile:
    return QoSProfile(depth=10, liveliness=policies.pop("liveliness", LivelinessPolicy.AUTOMATIC), **policies)


R, D, L = ReliabilityPolicy, DurabilityPolicy, LivelinessPolicy


# Outcomes and texts checked against rclpy Kilted's qos_check_compatible (rmw_fastrtps_cpp).
@pytest.mark.parametrize(
    ("offered", "requested", "level", "reason"),
    [
        ({}, {}, "OK", ""),
        ({"reliability": R.BEST_EFFORT}, {}, "ERROR", "ERROR: Best effort publisher and reliable subscription;"),
        (
            {"durability": D.VOLATILE},
            {"durability": D.TRANSIENT_LOCAL},
            "ERROR",
            "ERROR: Volatile publisher and transient local subscription;",
        ),
        (
            {"deadline": Duration(seconds=2)},
            {"deadline": Duration(seconds=1)},
            "ERROR",
            "ERROR: Subscription deadline is less than publisher deadline;",
        ),
        ({}, {"deadline": Duration(seconds=1)}, "ERROR", "ERROR: Subscription has a deadline, but publisher does not;"),
        ({"deadline": Duration(seconds=1)}, {}, "OK", ""),
        (
            {"liveliness": L.AUTOMATIC},
            {"liveliness": L.MANUAL_BY_TOPIC},
            "ERROR",
            "ERROR: Publisher's liveliness is automatic and subscription's is manual by topic;",
        ),
        (
            {"liveliness_lease_duration": Duration(seconds=2)},
            {"liveliness_lease_duration": Duration(seconds=1)},
            "ERROR",
            "ERROR: Subscription liveliness lease duration is less than publisher;",
        ),
        (
            {"reliability": R.BEST_EFFORT, "durability": D.VOLATILE},
            {"durability": D.TRANSIENT_LOCAL},
            "ERROR",
            "ERROR: Best effort publisher and reliable subscription;"
            "ERROR: Volatile publisher and transient local subscription;",
        ),
        (
            {"liveliness": L.SYSTEM_DEFAULT},
            {"liveliness": L.SYSTEM_DEFAULT},
            "WARNING",
            "WARNING: Publisher liveliness is system_default and subscription liveliness is system_default;",
        ),
        (
            {"reliability": R.SYSTEM_DEFAULT},
            {},
            "WARNING",
            "WARNING: Reliable subscription, but publisher is system_default;",
        ),
        (
            {"durability": D.SYSTEM_DEFAULT},
            {"durability": D.SYSTEM_DEFAULT},
            "WARNING",
            "WARNING: Publisher durabilty is system_default and subscription durability is system_default;",
        ),
        (
            {"liveliness": L.SYSTEM_DEFAULT},
            {"liveliness": L.MANUAL_BY_TOPIC},
            "WARNING",
            "WARNING: Subscription's liveliness is manual by topic, but publisher's is system_default;",
        ),
        (
            {"reliability": R.BEST_EFFORT, "durability": D.SYSTEM_DEFAULT},
            {"reliability": R.SYSTEM_DEFAULT, "durability": D.TRANSIENT_LOCAL},
            "WARNING",
            "WARNING: Best effort publisher, but subscription is system_default;"
            "WARNING: Transient local subscription, but publisher is system_default;",
        ),
        ({"reliability": R.UNKNOWN}, {}, "WARNING", "WARNING: Reliable subscription, but publisher is unknown;"),
        ({"reliability": R.BEST_AVAILABLE}, {}, "OK", ""),
        ({"liveliness": L.MANUAL_BY_TOPIC}, {"liveliness": L.AUTOMATIC}, "OK", ""),
    ],
)
def test_the_compatibility_check_says_what_rclpy_says(offered, requested, level, reason):
    assert qos_check_compatible(profile(**offered), profile(**requested)) == (QoSCompatibility[level], reason)


def test_two_default_profiles_only_warn():
    # rclpy's QoSProfile(depth=10) leaves liveliness to the system: the check cannot promise.
    compatibility, _ = qos_check_compatible(QoSProfile(depth=10), QoSProfile(depth=10))
    assert compatibility is QoSCompatibility.WARNING


def test_a_snapshot_resolves_system_defaults_and_is_shared():
    snapshot = as_qos(qos_profile_system_default)
    assert (snapshot.history, snapshot.depth, snapshot.reliability, snapshot.durability, snapshot.liveliness) == (
        HistoryPolicy.KEEP_LAST,
        10,
        ReliabilityPolicy.RELIABLE,
        DurabilityPolicy.VOLATILE,
        LivelinessPolicy.AUTOMATIC,
    )
    assert as_qos(qos_profile_default) is as_qos(10)  # equal QoS, one object
    best = as_qos(qos_profile_best_available)
    assert (best.deadline_ns, best.liveliness_lease_duration_ns, best.liveliness) == (0, 0, LivelinessPolicy.AUTOMATIC)
    with pytest.raises(TypeError):
        as_qos("10")
    with pytest.raises(TypeError):
        as_qos(True)


def test_a_snapshot_is_frozen_encodes_and_turns_back_into_a_profile():
    original = QoSProfile(
        depth=3,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
        deadline=Duration(seconds=1.5),
        lifespan=Infinite,
        liveliness=LivelinessPolicy.MANUAL_BY_TOPIC,
        liveliness_lease_duration=Duration(seconds=2),
    )
    snapshot = as_qos(original)
    with pytest.raises(AttributeError):
        snapshot.depth = 4  # type: ignore[misc]
    assert msgspec.msgpack.decode(msgspec.msgpack.encode(snapshot), type=QoSSnapshot) == snapshot
    assert snapshot.to_profile() == original
    original.depth = 9
    assert snapshot.depth == 3  # a snapshot does not follow the profile


def test_why_a_pair_does_not_connect():
    assert qos_incompatibility(as_qos(10), as_qos(10)) is None
    assert qos_incompatibility(
        as_qos(profile(deadline=Duration(seconds=2))), as_qos(profile(deadline=Duration(seconds=1)))
    ) == ("publisher offers a deadline of 2 s, subscription requests 1 s")
    assert qos_incompatibility(as_qos(profile()), as_qos(profile(liveliness=L.MANUAL_BY_TOPIC))) == (
        "publisher offers AUTOMATIC liveliness, subscription requests MANUAL_BY_TOPIC"
    )
    assert qos_incompatibility(as_qos(profile()), as_qos(profile(liveliness_lease_duration=Duration(seconds=1)))) == (
        "publisher offers a liveliness lease of none, subscription requests 1 s"
    )
