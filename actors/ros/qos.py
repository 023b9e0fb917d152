"""Quality of service, as rclpy.qos: policies, QoSProfile, the presets, and the compatibility check.

:class:`QoSProfile` is rclpy's: mutable, validated as rclpy validates it (a
profile needs a history or a depth; KEEP_LAST needs a depth), its policies
kept as enum members (``profile.reliability is ReliabilityPolicy.RELIABLE``),
its durations as :class:`~actors.ros.time.Duration`.  An endpoint never holds the
caller's profile: it takes a :class:`QoSSnapshot`, frozen and resolved (every
SYSTEM_DEFAULT policy replaced by what it means here, durations in integer
nanoseconds), which is also what introspection sends to the command line.

What SYSTEM_DEFAULT (and UNKNOWN) mean here: ``qos_profile_default``'s
policies, i.e. KEEP_LAST 10, RELIABLE, VOLATILE, AUTOMATIC liveliness, no
deadline, lifespan or lease.  A depth of 0 with KEEP_LAST means that depth of
10.  BEST_AVAILABLE liveliness is AUTOMATIC, and a BEST_AVAILABLE deadline or
lease is none; BEST_AVAILABLE reliability and durability are settled by the
topic table when the endpoint joins its topic (see ``actors.ros.topics``).
"""

from __future__ import annotations

import copy
import warnings
from enum import Enum, IntEnum
from typing import Any

import msgspec

from actors.errors import InvalidQoSProfileException
from actors.ros.time import Duration

__all__ = [
    "QoSPolicyEnum",
    "HistoryPolicy",
    "ReliabilityPolicy",
    "DurabilityPolicy",
    "LivelinessPolicy",
    "QoSHistoryPolicy",
    "QoSReliabilityPolicy",
    "QoSDurabilityPolicy",
    "QoSLivelinessPolicy",
    "QoSPolicyKind",
    "qos_policy_name_from_kind",
    "QoSProfile",
    "QoSSnapshot",
    "PolicyRecord",
    "InvalidQoSProfileException",
    "DeadlineBestAvailable",
    "LivelinessLeaseDurationeBestAvailable",
    "qos_profile_unknown",
    "qos_profile_default",
    "qos_profile_system_default",
    "qos_profile_sensor_data",
    "qos_profile_services_default",
    "qos_profile_parameters",
    "qos_profile_parameter_events",
    "qos_profile_best_available",
    "qos_profile_action_status_default",
    "qos_profile_rosout_default",
    "QoSPresetProfiles",
    "QoSCompatibility",
    "qos_check_compatible",
    "profile_from_short_keys",
    "as_qos",
    "incompatible_policies",
    "qos_incompatibility",
]


class QoSPolicyEnum(IntEnum):
    """A QoS policy's values (numbered as rmw's), with rclpy's short keys (``"best_effort"``)."""

    @classmethod
    def short_keys(cls) -> list[str]:
        """Every value's short key: ``["system_default", "reliable", ...]``."""
        return [name.lower() for name in cls.__members__]

    @classmethod
    def get_from_short_key(cls, name: str) -> int:
        """The value of a short key, any case; KeyError for an unknown one."""
        return cls[name.upper()].value

    @property
    def short_key(self) -> str:
        """This value's short key."""
        return self.name.lower()


class HistoryPolicy(QoSPolicyEnum):
    """How many messages a queue keeps."""

    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(QoSPolicyEnum):
    """Delivery guarantee requested or offered."""

    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(QoSPolicyEnum):
    """Whether late subscribers get earlier messages."""

    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(QoSPolicyEnum):
    """How a publisher shows it is alive: by existing, or by publishing within its lease."""

    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


# rclpy's other names for the same classes.
QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy


class QoSPolicyKind(IntEnum):
    """Which policy made a publisher and a subscription incompatible (values as rmw's)."""

    INVALID = 1 << 0
    DURABILITY = 1 << 1
    DEADLINE = 1 << 2
    LIVELINESS = 1 << 3
    RELIABILITY = 1 << 4
    HISTORY = 1 << 5
    LIFESPAN = 1 << 6
    DEPTH = 1 << 7
    LIVELINESS_LEASE_DURATION = 1 << 8
    AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


def qos_policy_name_from_kind(policy_kind: QoSPolicyKind | int) -> str:
    """``QoSPolicyKind.DURABILITY`` (or its number) -> ``"DURABILITY"``."""
    return QoSPolicyKind(policy_kind).name


_UNSET = Duration()  # a duration of 0: the policy is not set (rmw's "default")
_BEST_AVAILABLE_NS = 2**63 - 2  # rmw's marker for a best-available deadline or lease
DeadlineBestAvailable = Duration(nanoseconds=_BEST_AVAILABLE_NS)
LivelinessLeaseDurationeBestAvailable = Duration(nanoseconds=_BEST_AVAILABLE_NS)  # rclpy's spelling


class QoSProfile:
    """Quality of service of a publisher or subscription, as ``rclpy.qos.QoSProfile``.

    ``QoSProfile(depth=10)`` is KEEP_LAST 10; ``QoSProfile(history=KEEP_ALL)``
    needs no depth.  Unset policies take ``qos_profile_default``'s values.
    Policies may be changed after construction (``profile.durability = ...``);
    an endpoint copies the profile when it is created, so changing it later
    changes no endpoint.  Raises InvalidQoSProfileException without a history
    or depth, or KEEP_LAST without a depth; TypeError for a value of the wrong
    kind; ValueError for a number no policy has.
    """

    __slots__ = (
        "_history",
        "_depth",
        "_reliability",
        "_durability",
        "_lifespan",
        "_deadline",
        "_liveliness",
        "_liveliness_lease_duration",
        "_avoid_ros_namespace_conventions",
    )

    def __init__(
        self,
        history: HistoryPolicy | int | None = None,
        depth: int | None = None,
        reliability: ReliabilityPolicy | int | None = None,
        durability: DurabilityPolicy | int | None = None,
        lifespan: Duration | None = None,
        deadline: Duration | None = None,
        liveliness: LivelinessPolicy | int | None = None,
        liveliness_lease_duration: Duration | None = None,
        avoid_ros_namespace_conventions: bool | None = None,
    ) -> None:
        if history is None:
            if depth is None:
                raise InvalidQoSProfileException("a QoSProfile needs a history and/or a depth")
            history = HistoryPolicy.KEEP_LAST
        self.history = history
        if self._history is HistoryPolicy.KEEP_LAST and depth is None:
            raise InvalidQoSProfileException("a KEEP_LAST QoSProfile needs a depth")
        self.depth = 10 if depth is None else depth
        self.reliability = ReliabilityPolicy.RELIABLE if reliability is None else reliability
        self.durability = DurabilityPolicy.VOLATILE if durability is None else durability
        self.lifespan = _UNSET if lifespan is None else lifespan
        self.deadline = _UNSET if deadline is None else deadline
        self.liveliness = LivelinessPolicy.SYSTEM_DEFAULT if liveliness is None else liveliness
        self.liveliness_lease_duration = _UNSET if liveliness_lease_duration is None else liveliness_lease_duration
        self.avoid_ros_namespace_conventions = bool(avoid_ros_namespace_conventions)

    @property
    def history(self) -> HistoryPolicy:
        """KEEP_LAST, KEEP_ALL (or SYSTEM_DEFAULT)."""
        return self._history

    @history.setter
    def history(self, value: HistoryPolicy | int) -> None:
        self._history = _policy(HistoryPolicy, value, "history")

    @property
    def depth(self) -> int:
        """How many messages KEEP_LAST keeps (and TRANSIENT_LOCAL replays)."""
        return self._depth

    @depth.setter
    def depth(self, value: int) -> None:
        if isinstance(value, bool) or not isinstance(value, int):
            raise TypeError(f"QoS depth must be an int, got {value!r}")
        if value < 0:
            raise ValueError(f"QoS depth must be greater than or equal to zero, got {value}")
        if value == 0 and self._history is HistoryPolicy.KEEP_LAST:
            warnings.warn(
                "A zero depth with KEEP_LAST doesn't make sense; no data could be stored: "
                "it is taken as the default depth (10)",
                stacklevel=2,
            )
        self._depth = value

    @property
    def reliability(self) -> ReliabilityPolicy:
        """RELIABLE or BEST_EFFORT (or SYSTEM_DEFAULT, BEST_AVAILABLE)."""
        return self._reliability

    @reliability.setter
    def reliability(self, value: ReliabilityPolicy | int) -> None:
        self._reliability = _policy(ReliabilityPolicy, value, "reliability")

    @property
    def durability(self) -> DurabilityPolicy:
        """VOLATILE or TRANSIENT_LOCAL (or SYSTEM_DEFAULT, BEST_AVAILABLE)."""
        return self._durability

    @durability.setter
    def durability(self, value: DurabilityPolicy | int) -> None:
        self._durability = _policy(DurabilityPolicy, value, "durability")

    @property
    def lifespan(self) -> Duration:
        """How long a published message stays deliverable (0: forever)."""
        return self._lifespan

    @lifespan.setter
    def lifespan(self, value: Duration) -> None:
        self._lifespan = _duration(value, "lifespan")

    @property
    def deadline(self) -> Duration:
        """The longest gap between messages before a deadline-missed event (0: none)."""
        return self._deadline

    @deadline.setter
    def deadline(self, value: Duration) -> None:
        self._deadline = _duration(value, "deadline")

    @property
    def liveliness(self) -> LivelinessPolicy:
        """AUTOMATIC or MANUAL_BY_TOPIC (or SYSTEM_DEFAULT, BEST_AVAILABLE)."""
        return self._liveliness

    @liveliness.setter
    def liveliness(self, value: LivelinessPolicy | int) -> None:
        self._liveliness = _policy(LivelinessPolicy, value, "liveliness")

    @property
    def liveliness_lease_duration(self) -> Duration:
        """How long a MANUAL_BY_TOPIC publisher stays alive without publishing or asserting (0: forever)."""
        return self._liveliness_lease_duration

    @liveliness_lease_duration.setter
    def liveliness_lease_duration(self, value: Duration) -> None:
        self._liveliness_lease_duration = _duration(value, "liveliness_lease_duration")

    @property
    def avoid_ros_namespace_conventions(self) -> bool:
        """Kept for rclpy's sake; names here always follow ROS's conventions."""
        return self._avoid_ros_namespace_conventions

    @avoid_ros_namespace_conventions.setter
    def avoid_ros_namespace_conventions(self, value: bool) -> None:
        if not isinstance(value, bool):
            raise TypeError(f"avoid_ros_namespace_conventions must be a bool, got {value!r}")
        self._avoid_ros_namespace_conventions = value

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, QoSProfile):
            return NotImplemented
        return all(getattr(self, slot) == getattr(other, slot) for slot in self.__slots__)

    __hash__ = None  # type: ignore[assignment]  # mutable, as rclpy's: unhashable, which object types as hashable

    def get_c_qos_profile(self) -> PolicyRecord:
        """rclpy's hand-over to rmw: a copy whose ``to_dict()`` gives this profile's keyword arguments."""
        return PolicyRecord(self)

    def __repr__(self) -> str:
        fields = ", ".join(f"{slot[1:]}={getattr(self, slot)!r}" for slot in self.__slots__)
        return f"QoSProfile({fields})"


class PolicyRecord:
    """A profile's policies as rmw holds them (rclpy's ``rmw_qos_profile_t``): ``to_dict()`` for QoSProfile(**...)."""

    __slots__ = ("_values",)

    def __init__(self, profile: QoSProfile) -> None:
        self._values = {slot[1:]: getattr(profile, slot) for slot in profile.__slots__}

    def to_dict(self) -> dict[str, Any]:
        """The policies by QoSProfile's keyword names."""
        return dict(self._values)


def _policy(kind: type[QoSPolicyEnum], value: Any, what: str) -> Any:
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"QoS {what} must be a {kind.__name__} or its number, got {value!r}")
    return kind(value)


def _duration(value: Any, what: str) -> Duration:
    if not isinstance(value, Duration):
        raise TypeError(f"QoS {what} must be a Duration, got {value!r}")
    return value


class QoSSnapshot(msgspec.Struct, frozen=True, kw_only=True):
    """The QoS an endpoint was made with: resolved, frozen, durations in nanoseconds (0: none).

    What introspection and the command line see (it encodes to msgpack).
    """

    depth: int = 10
    history: HistoryPolicy = HistoryPolicy.KEEP_LAST
    reliability: ReliabilityPolicy = ReliabilityPolicy.RELIABLE
    durability: DurabilityPolicy = DurabilityPolicy.VOLATILE
    lifespan_ns: int = 0
    deadline_ns: int = 0
    liveliness: LivelinessPolicy = LivelinessPolicy.AUTOMATIC
    liveliness_lease_duration_ns: int = 0
    avoid_ros_namespace_conventions: bool = False

    def to_profile(self) -> QoSProfile:
        """This snapshot as an rclpy-shaped QoSProfile (``endpoint.qos_profile``)."""
        return QoSProfile(
            history=self.history,
            depth=self.depth,
            reliability=self.reliability,
            durability=self.durability,
            lifespan=Duration(nanoseconds=self.lifespan_ns),
            deadline=Duration(nanoseconds=self.deadline_ns),
            liveliness=self.liveliness,
            liveliness_lease_duration=Duration(nanoseconds=self.liveliness_lease_duration_ns),
            avoid_ros_namespace_conventions=self.avoid_ros_namespace_conventions,
        )


_VAGUE = frozenset({"SYSTEM_DEFAULT", "UNKNOWN"})
# A plain depth's other policies, in a snapshot's field order.
_DEPTH_ONLY = (
    ReliabilityPolicy.RELIABLE,
    DurabilityPolicy.VOLATILE,
    0,
    0,
    LivelinessPolicy.AUTOMATIC,
    0,
    False,
)  # the values whose meaning is the middleware's
_snapshots: dict[tuple[Any, ...], QoSSnapshot] = {}  # one shared snapshot per distinct profile
# The snapshot of a plain depth, found without building and hashing the key above: its enum
# members hash in Python, and every node's create_publisher(..., 10) paid 2.4 µs for it.
_by_depth: dict[int, QoSSnapshot] = {}


def _ns(duration: Duration) -> int:
    return 0 if duration.nanoseconds == _BEST_AVAILABLE_NS else duration.nanoseconds


def as_qos(qos: QoSProfile | QoSSnapshot | int) -> QoSSnapshot:
    """The resolved, frozen QoS of a profile, of a snapshot, or of a depth (KEEP_LAST of that depth).

    Raises TypeError for anything else, and ValueError for a negative depth.
    Endpoints with the same QoS share one snapshot.
    """
    if isinstance(qos, QoSSnapshot):
        return qos
    if type(qos) is int and (known := _by_depth.get(qos)) is not None:
        return known
    if isinstance(qos, bool) or not isinstance(qos, (QoSProfile, int)):
        raise TypeError(f"Expected QoSProfile or int, but received {qos!r}")  # rclpy's words
    if isinstance(qos, int):
        if qos < 0:
            raise ValueError(f"QoS depth must be greater than or equal to zero, got {qos}")
        key: tuple[Any, ...] = (HistoryPolicy.KEEP_LAST, qos or 10, *_DEPTH_ONLY)
    else:
        history = HistoryPolicy.KEEP_LAST if qos.history.name in _VAGUE else qos.history
        liveliness = qos.liveliness
        key = (
            history,
            qos.depth or 10,
            ReliabilityPolicy.RELIABLE if qos.reliability.name in _VAGUE else qos.reliability,
            DurabilityPolicy.VOLATILE if qos.durability.name in _VAGUE else qos.durability,
            _ns(qos.lifespan),
            _ns(qos.deadline),
            LivelinessPolicy.AUTOMATIC
            if liveliness.name in _VAGUE or liveliness == LivelinessPolicy.BEST_AVAILABLE
            else liveliness,
            _ns(qos.liveliness_lease_duration),
            qos.avoid_ros_namespace_conventions,
        )
    snapshot = _snapshots.get(key)
    if snapshot is None:
        names = (
            "history",
            "depth",
            "reliability",
            "durability",
            "lifespan_ns",
            "deadline_ns",
            "liveliness",
            "liveliness_lease_duration_ns",
            "avoid_ros_namespace_conventions",
        )
        snapshot = _snapshots[key] = QoSSnapshot(**dict(zip(names, key)))
    if type(qos) is int:
        _by_depth[qos] = snapshot
    return snapshot


# -- the presets, with rclpy's values --------------------------------------------------

qos_profile_unknown = QoSProfile(
    history=HistoryPolicy.UNKNOWN,
    depth=0,
    reliability=ReliabilityPolicy.UNKNOWN,
    durability=DurabilityPolicy.UNKNOWN,
    liveliness=LivelinessPolicy.UNKNOWN,
)
qos_profile_default = QoSProfile(depth=10)
qos_profile_system_default = QoSProfile(
    history=HistoryPolicy.SYSTEM_DEFAULT,
    depth=0,
    reliability=ReliabilityPolicy.SYSTEM_DEFAULT,
    durability=DurabilityPolicy.SYSTEM_DEFAULT,
)
qos_profile_sensor_data = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
qos_profile_services_default = QoSProfile(depth=10)
qos_profile_parameters = QoSProfile(depth=1000)
qos_profile_parameter_events = QoSProfile(depth=1000)
qos_profile_best_available = QoSProfile(
    depth=10,
    reliability=ReliabilityPolicy.BEST_AVAILABLE,
    durability=DurabilityPolicy.BEST_AVAILABLE,
    deadline=DeadlineBestAvailable,
    liveliness=LivelinessPolicy.BEST_AVAILABLE,
    liveliness_lease_duration=LivelinessLeaseDurationeBestAvailable,
)
qos_profile_action_status_default = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
qos_profile_rosout_default = QoSProfile(
    depth=1000, durability=DurabilityPolicy.TRANSIENT_LOCAL, lifespan=Duration(seconds=10)
)


class QoSPresetProfiles(Enum):
    """Every preset by name, as rclpy's (``QoSPresetProfiles.SENSOR_DATA.value``)."""

    UNKNOWN = qos_profile_unknown
    DEFAULT = qos_profile_default
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default
    BEST_AVAILABLE = qos_profile_best_available
    ROSOUT_DEFAULT = qos_profile_rosout_default

    @classmethod
    def short_keys(cls) -> list[str]:
        """Every preset's short key: ``["unknown", "default", ..., "sensor_data", ...]``."""
        return [name.lower() for name in cls.__members__]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        """The preset of a short key, any case; KeyError for an unknown one."""
        return cls[name.upper()].value


def profile_from_short_keys(
    preset: str,
    *,
    history: str | None = None,
    depth: int | None = None,
    reliability: str | None = None,
    durability: str | None = None,
    liveliness: str | None = None,
    lease_seconds: float | None = None,
) -> QoSProfile:
    """A copy of the preset named ``preset`` (``sensor_data``) with the policies given in its place,
    by their short keys: what ``ros2 topic``'s ``--qos-*`` options make.  KeyError for an unknown key."""
    profile = copy.copy(QoSPresetProfiles.get_from_short_key(preset))
    if history:
        profile.history = HistoryPolicy.get_from_short_key(history)
    if durability:
        profile.durability = DurabilityPolicy.get_from_short_key(durability)
    if reliability:
        profile.reliability = ReliabilityPolicy.get_from_short_key(reliability)
    if liveliness:
        profile.liveliness = LivelinessPolicy.get_from_short_key(liveliness)
    if lease_seconds and lease_seconds >= 0:
        profile.liveliness_lease_duration = Duration(seconds=lease_seconds)
    if depth and depth >= 0:
        profile.depth = depth
    elif profile.durability == DurabilityPolicy.TRANSIENT_LOCAL and profile.depth == 0:
        profile.depth = 1  # as ros2's: a latched topic keeps its last message at least
    return profile


# -- compatibility ---------------------------------------------------------------------


class QoSCompatibility(IntEnum):
    """Whether a publisher and a subscription can connect: OK, maybe (WARNING), or not (ERROR)."""

    OK = 0
    WARNING = 1
    ERROR = 2


def _errors(pub: Any, sub: Any, deadlines: tuple[int, int], leases: tuple[int, int]) -> list[tuple[QoSPolicyKind, str]]:
    """(kind, rmw's text) of each policy that stops ``pub`` from reaching ``sub``, in rmw's order."""
    found = []
    if pub.reliability == ReliabilityPolicy.BEST_EFFORT and sub.reliability == ReliabilityPolicy.RELIABLE:
        found.append((QoSPolicyKind.RELIABILITY, "Best effort publisher and reliable subscription"))
    if pub.durability == DurabilityPolicy.VOLATILE and sub.durability == DurabilityPolicy.TRANSIENT_LOCAL:
        found.append((QoSPolicyKind.DURABILITY, "Volatile publisher and transient local subscription"))
    pub_deadline, sub_deadline = deadlines
    if not pub_deadline and sub_deadline:
        found.append((QoSPolicyKind.DEADLINE, "Subscription has a deadline, but publisher does not"))
    if pub_deadline and sub_deadline and sub_deadline < pub_deadline:
        found.append((QoSPolicyKind.DEADLINE, "Subscription deadline is less than publisher deadline"))
    if pub.liveliness == LivelinessPolicy.AUTOMATIC and sub.liveliness == LivelinessPolicy.MANUAL_BY_TOPIC:
        found.append(
            (QoSPolicyKind.LIVELINESS, "Publisher's liveliness is automatic and subscription's is manual by topic")
        )
    pub_lease, sub_lease = leases
    if not pub_lease and sub_lease:
        found.append(
            (
                QoSPolicyKind.LIVELINESS_LEASE_DURATION,
                "Subscription has a liveliness lease duration, but publisher does not",
            )
        )
    if pub_lease and sub_lease and sub_lease < pub_lease:
        found.append(
            (QoSPolicyKind.LIVELINESS_LEASE_DURATION, "Subscription liveliness lease duration is less than publisher")
        )
    return found


def _warnings(pub: QoSProfile, sub: QoSProfile) -> list[str]:
    """rmw's warnings for policies whose outcome depends on the middleware's defaults."""
    found = []
    for policy, kind, one_sided in (
        (
            "reliability",
            ReliabilityPolicy,
            (
                (ReliabilityPolicy.RELIABLE, "Reliable subscription, but publisher is {pub}"),
                (ReliabilityPolicy.BEST_EFFORT, "Best effort publisher, but subscription is {sub}"),
            ),
        ),
        (
            "durability",
            DurabilityPolicy,  # "durabilty": rmw's spelling, kept so the text matches
            (
                (DurabilityPolicy.TRANSIENT_LOCAL, "Transient local subscription, but publisher is {pub}"),
                (DurabilityPolicy.VOLATILE, "Volatile publisher, but subscription is {sub}"),
            ),
        ),
        (
            "liveliness",
            LivelinessPolicy,
            (
                (
                    LivelinessPolicy.MANUAL_BY_TOPIC,
                    "Subscription's liveliness is manual by topic, but publisher's is {pub}",
                ),
                (LivelinessPolicy.AUTOMATIC, "Publisher's liveliness is automatic, but subscription's is {sub}"),
            ),
        ),
    ):
        offered, requested = kind(getattr(pub, policy)), kind(getattr(sub, policy))
        names = {"pub": offered.short_key, "sub": requested.short_key}
        (sub_value, sub_text), (pub_value, pub_text) = one_sided
        label = "durabilty" if policy == "durability" else policy
        if offered.name in _VAGUE and requested.name in _VAGUE:
            found.append(f"Publisher {label} is {names['pub']} and subscription {policy} is {names['sub']}")
        elif offered.name in _VAGUE and requested == sub_value:
            found.append(sub_text.format(**names))
        elif offered == pub_value and requested.name in _VAGUE:
            found.append(pub_text.format(**names))
    return found


def qos_check_compatible(publisher_qos: QoSProfile, subscription_qos: QoSProfile) -> tuple[QoSCompatibility, str]:
    """Whether a publisher with ``publisher_qos`` reaches a subscription with ``subscription_qos``, and why.

    As rclpy (rmw's texts): ERROR when a policy stops the connection, WARNING
    when it depends on what SYSTEM_DEFAULT (or UNKNOWN) means, OK otherwise.
    """
    errors = _errors(
        publisher_qos,
        subscription_qos,
        (publisher_qos.deadline.nanoseconds, subscription_qos.deadline.nanoseconds),
        (publisher_qos.liveliness_lease_duration.nanoseconds, subscription_qos.liveliness_lease_duration.nanoseconds),
    )
    if errors:
        return QoSCompatibility.ERROR, "".join(f"ERROR: {text};" for _, text in errors)
    found = _warnings(publisher_qos, subscription_qos)
    if found:
        return QoSCompatibility.WARNING, "".join(f"WARNING: {text};" for text in found)
    return QoSCompatibility.OK, ""


def incompatible_policies(offered: QoSSnapshot, requested: QoSSnapshot) -> list[QoSPolicyKind]:
    """The policies that stop a publisher offering ``offered`` from reaching ``requested`` (empty: none)."""
    return [
        kind
        for kind, _ in _errors(
            offered,
            requested,
            (offered.deadline_ns, requested.deadline_ns),
            (offered.liveliness_lease_duration_ns, requested.liveliness_lease_duration_ns),
        )
    ]


def qos_incompatibility(offered: QoSSnapshot, requested: QoSSnapshot) -> str | None:
    """Why a publisher offering ``offered`` cannot feed a subscription requesting ``requested``, or None."""
    kinds = incompatible_policies(offered, requested)
    if not kinds:
        return None

    def seconds(ns: int) -> str:
        return f"{ns / 1e9:g} s" if ns else "none"

    reasons = {
        QoSPolicyKind.RELIABILITY: f"publisher offers {offered.reliability.name}, "
        f"subscription requests {requested.reliability.name}",
        QoSPolicyKind.DURABILITY: f"publisher offers {offered.durability.name}, "
        f"subscription requests {requested.durability.name}",
        QoSPolicyKind.DEADLINE: f"publisher offers a deadline of {seconds(offered.deadline_ns)}, "
        f"subscription requests {seconds(requested.deadline_ns)}",
        QoSPolicyKind.LIVELINESS: f"publisher offers {offered.liveliness.name} liveliness, "
        f"subscription requests {requested.liveliness.name}",
        QoSPolicyKind.LIVELINESS_LEASE_DURATION: "publisher offers a liveliness lease of "
        f"{seconds(offered.liveliness_lease_duration_ns)}, "
        f"subscription requests {seconds(requested.liveliness_lease_duration_ns)}",
    }
    return "; ".join(reasons[kind] for kind in dict.fromkeys(kinds))
