"""Doctor: health checks of a running graph, the loop-lag monitor, and the platform report.

:func:`diagnose` runs every check on a runtime's graph as it is now; each
check passes or fails with one reason per problem found:

- publishers without subscribers, and subscriptions without publishers: these
  are *warnings*, as in ``ros2 doctor`` (a graph may well publish what only a
  command line reads); a check with warnings still passes unless the caller
  counts warnings as failures (``actors doctor --include-warnings``);
  hidden topics (an action's) are left out: actions have their own check;
- action clients whose action no node serves (a warning too);
- endpoints whose type differs from their topic's (the topic table refuses
  them, so this guards the invariant rather than expecting failures; across
  processes it finds real ones);
- endpoints of other processes (through a transport) whose type this process
  knows under another RIHS01 hash, or not at all: their data is ignored;
- QoS incompatibility: a best-effort publisher to a reliable subscription, a
  volatile publisher to a transient-local one (such pairs are not connected);
- nodes that crashed or keep restarting;
- subscriptions that dropped messages (a full KEEP_LAST mailbox, or a
  transport's full backlog of samples from other processes; not on
  hidden topics: an action's status subscription keeps only the latest);
- messages a node refused at its input boundary (``MessageRefused``), with
  their counts per reason and the last sender;
- callbacks that block the loop, named by node and callback (wall clock only:
  on virtual time the loop's clock stands still while a callback runs);
- the transports' limits (each attachment that is a ``LimitSource``): liveliness
  tokens of other processes ignored beyond the limit fail the check (the graph
  seen is incomplete); warnings about what peers sent left out of the log are
  warnings;
- the control endpoint's limits (asked through the endpoint): running out of
  file descriptors fails the check; connections refused at the limit, closed
  for idleness, malformed requests and samples a slow reader lost are warnings;
- required packages installed.

``/rosout``, ``/parameter_events`` and hidden endpoints (the command line's
own, the runtime's) are left out of the topic checks.
"""

from __future__ import annotations

import functools
import os
import sys
import threading
from collections import deque
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

import anyio
import msgspec

from actors.ops._connections import ConnectionStats
from actors.ros.names import is_hidden, is_hidden_name
from actors.ros.qos import qos_incompatibility
from actors.system.introspection import ActionInfo, EndpointInfo, NodeInfo, TopicInfo
from actors.transport.seam import LimitSource

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["IGNORED_TOPICS", "Check", "LagEvent", "Report", "LagMonitor", "diagnose"]

IGNORED_TOPICS = frozenset({"/rosout", "/parameter_events"})
"""Topics every graph has, left out of the publisher/subscriber checks."""

_REQUIRED = ("anyio", "msgspec", "pymunk", "numpy", "pyyaml")
_OPTIONAL = ("pillow",)


class Check(msgspec.Struct, frozen=True, kw_only=True):
    """One check: its name, whether it passed, a reason per problem found, a text per warning."""

    name: str
    passed: bool
    reasons: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    def failed(self, include_warnings: bool = False) -> bool:
        """Whether this check failed; with ``include_warnings``, a warning is a failure too."""
        return not self.passed or (include_warnings and bool(self.warnings))


class LagEvent(msgspec.Struct, frozen=True, kw_only=True):
    """The loop woke ``lag`` seconds late at ``stamp`` (runtime clock, seconds since its epoch).

    ``node`` and ``callback`` name what was running then; empty when no node's
    callback was (the loop was busy elsewhere, or the process was not scheduled).
    """

    stamp: float
    lag: float
    node: str = ""
    callback: str = ""


class Report(msgspec.Struct, frozen=True, kw_only=True):
    """Everything ``actors doctor --report`` prints."""

    graph: str
    clock: str
    checks: tuple[Check, ...]
    lag_measured: bool
    lag_events: tuple[LagEvent, ...]
    platform: dict[str, str]
    versions: dict[str, str]

    def failures(self, include_warnings: bool = False) -> list[Check]:
        """The checks that failed (with ``include_warnings``, those with warnings too)."""
        return [check for check in self.checks if check.failed(include_warnings)]


def diagnose(runtime: Runtime, monitor: LagMonitor | None = None, control: ConnectionStats | None = None) -> Report:
    """Run every check on ``runtime``'s graph now.

    The loop-lag check runs only with a ``monitor`` (the control endpoint starts
    one on wall-clock runtimes), the endpoint's check with its ``control``
    statistics.  Never raises for what it finds.
    """
    graph = runtime.graph
    topics = [t for t in graph.topics() if t.name not in IGNORED_TOPICS]
    nodes = graph.nodes()
    versions = _versions()
    checks = [
        _one_sided(topics, publishers=True),
        _one_sided(topics, publishers=False),
        _unserved(graph.actions()),
        _per_topic(topics, "topic types", _type_mismatches),
        _per_topic(topics, "type hashes", _hash_mismatches),
        _per_topic(topics, "QoS compatibility", _qos_mismatches),
        _node_health(nodes + graph.ended()),
        _per_topic(topics, "dropped messages", _drops),
        _per_topic(topics, "refused messages", _refused),
    ]
    events = tuple(monitor.events) if monitor is not None else ()
    if monitor is not None:
        checks.append(_lag(events))
    checks.extend(_limits(source) for source in runtime.attachments if isinstance(source, LimitSource))
    if control is not None:
        checks.append(_control(control))
    missing = [f"{name} is not installed" for name in _REQUIRED if versions[name] == "not installed"]
    checks.append(Check(name="required packages", passed=not missing, reasons=tuple(missing)))
    return Report(
        graph=runtime.name,
        clock="virtual" if runtime.clock.virtual else "wall",
        checks=tuple(checks),
        lag_measured=monitor is not None,
        lag_events=events,
        platform=_platform(),
        versions=versions,
    )


# --------------------------------------------------------------------------- the checks


def _visible(endpoints: Iterable[EndpointInfo]) -> list[EndpointInfo]:
    return [e for e in endpoints if not is_hidden(e.node)]


def _one_sided(topics: list[TopicInfo], *, publishers: bool) -> Check:
    """Topics with publishers but no subscriptions (or, with ``publishers=False``, the reverse).

    Warnings, not failures, as ros2doctor's topic check has them.
    """
    reasons = []
    for topic in topics:
        if is_hidden_name(topic.name):
            continue
        pubs, subs = _visible(topic.publishers), _visible(topic.subscriptions)
        have, lack = (pubs, subs) if publishers else (subs, pubs)
        if have and not lack:
            nodes = ", ".join(sorted({e.node for e in have}))
            what = "published by {} but nobody subscribes" if publishers else "subscribed by {} but nobody publishes"
            reasons.append(f"{topic.name} ({topic.type}) is {what.format(nodes)}")
    name = "publishers without subscribers" if publishers else "subscriptions without publishers"
    return Check(name=name, passed=True, warnings=tuple(reasons))


def _unserved(actions: list[ActionInfo]) -> Check:
    """Actions that clients send goals to but no node serves: warnings, as a lone subscription's."""
    reasons = tuple(
        f"{a.name} ({a.type}) has clients ({', '.join(a.clients)}) but no server"
        for a in actions
        if a.clients and not a.servers
    )
    return Check(name="action servers", passed=True, warnings=reasons)


def _per_topic(topics: list[TopicInfo], name: str, find: Callable[[TopicInfo], list[str]]) -> Check:
    reasons = [reason for topic in topics for reason in find(topic)]
    return Check(name=name, passed=not reasons, reasons=tuple(reasons))


def _type_mismatches(topic: TopicInfo) -> list[str]:
    return [
        f"{topic.name} carries {topic.type} but {e.node} uses {e.type}"
        for e in _visible((*topic.publishers, *topic.subscriptions))
        if e.type != topic.type
    ]


def _hash_mismatches(topic: TopicInfo) -> list[str]:
    """Endpoints of other processes this one cannot read: another RIHS01 hash, or a type unknown here."""
    return [
        f"{topic.name}: {e.node} (process {e.process}) uses {e.type} {e.type_hash}: {e.why}"
        for e in _visible((*topic.publishers, *topic.subscriptions))
        if e.why
    ]


def _qos_mismatches(topic: TopicInfo) -> list[str]:
    found = []
    for pub in _visible(topic.publishers):
        for sub in _visible(topic.subscriptions):
            if pub.process or sub.process:
                continue  # across processes Zenoh connects every pair, as rmw_zenoh does
            why = qos_incompatibility(pub.qos, sub.qos)
            if why is not None:
                found.append(f"{topic.name}: {pub.node} does not reach {sub.node}: {why}")
    return found


def _drops(topic: TopicInfo) -> list[str]:
    from actors.recording.recorder import RECORDER_NODE

    # The recorder's own losses count (a bag with holes), though its owner is hidden.
    lost = [
        f"{topic.name}: the recorder dropped {e.dropped} message(s): the disk could not keep up"
        for e in topic.subscriptions
        if e.node == RECORDER_NODE and e.dropped
    ]
    if is_hidden_name(topic.name):
        return lost  # an action's status keeps only its latest array (depth 1), as ROS's does
    return [
        f"{topic.name}: {e.node} dropped {e.dropped} message(s) (queue depth {e.qos.depth})"
        for e in _visible(topic.subscriptions)
        if e.dropped
    ] + lost


def _refused(topic: TopicInfo) -> list[str]:
    return [
        f"{topic.name}: {e.node} refused {sum(e.refused.values())} message(s): "
        + "; ".join(f"{reason} ({count})" for reason, count in sorted(e.refused.items()))
        + f"; the last from {e.refused_from}"
        for e in topic.subscriptions
        if e.refused
    ]


def _node_health(nodes: list[NodeInfo]) -> Check:
    reasons = []
    for node in nodes:
        if node.crashes or node.state in ("crashed", "restarting"):
            text = f"{node.name} is {node.state} after {node.crashes} crash(es) and {node.restarts} restart(s)"
            if node.last_error:
                text += f"; last error: {node.last_error}"
            reasons.append(text)
    return Check(name="node health", passed=not reasons, reasons=tuple(reasons))


def _lag(events: tuple[LagEvent, ...]) -> Check:
    worst: dict[tuple[str, str], list[float]] = {}
    for event in events:
        if event.node:
            worst.setdefault((event.node, event.callback), []).append(event.lag)
    reasons = tuple(
        f"{node}: {callback} blocked the loop {len(lags)} time(s), longest {max(lags):.3f} s"
        for (node, callback), lags in sorted(worst.items())
    )
    return Check(name="callbacks blocking the loop", passed=not reasons, reasons=reasons)


def _limits(source: LimitSource) -> Check:
    reached, warnings = source.limits()
    return Check(name="transport limits", passed=not reached, reasons=tuple(reached), warnings=tuple(warnings))


def _control(stats: ConnectionStats) -> Check:
    reasons = []
    if stats.out_of_descriptors:
        reasons.append(
            f"the graph ran out of file descriptors (limit {stats.descriptor_limit}): "
            f"{stats.out_of_descriptors} connection(s) refused; something holds too many open"
        )
    warnings = [
        f"{count} {what}"
        for count, what in (
            (stats.refused, f"connection(s) refused at the limit of {stats.connection_limit} open at once"),
            (stats.evicted, "idle connection(s) closed to let others in"),
            (stats.timed_out, "connection(s) closed for idleness or a half-sent request"),
            (stats.bad_requests, "connection(s) sent malformed requests (see the graph's log)"),
            (stats.dropped, "streamed message(s) dropped for readers that did not keep up"),
        )
        if count
    ]
    return Check(name="control endpoint", passed=not reasons, reasons=tuple(reasons), warnings=tuple(warnings))


@functools.cache  # fixed for the process; importlib.metadata scans the path
def _platform() -> dict[str, str]:
    import platform

    return {
        "system": platform.system(),
        "platform info": platform.platform(),
        "release": platform.release(),
        "processor": platform.machine(),
        "python": f"{platform.python_implementation()} {platform.python_version()}",
    }


@functools.cache
def _versions() -> dict[str, str]:
    from importlib.metadata import PackageNotFoundError, version

    found = {}
    for name in ("actors", *_REQUIRED, *_OPTIONAL):
        try:
            found[name] = version(name)
        except PackageNotFoundError:
            found[name] = "not installed"
    return found


# --------------------------------------------------------------------------- the loop-lag monitor


class _CpuWait:
    """Seconds the thread that made it has spent runnable but waiting for a CPU (0.0 where untold)."""

    def __init__(self) -> None:
        try:
            # Opened by the thread it describes: /proc/thread-self resolves to that thread for good.
            self._fd: int | None = os.open("/proc/thread-self/schedstat", os.O_RDONLY)
        except OSError:  # not Linux, or a kernel without scheduler statistics
            self._fd = None

    def __call__(self) -> float:
        if self._fd is None:
            return 0.0
        # "<ns on a CPU> <ns waiting on a run queue> <time slices>", read afresh at each pread.
        return int(os.pread(self._fd, 64, 0).split()[1]) / 1e9

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)


class LagMonitor:
    """Notices callbacks that block the loop of a wall-clock runtime.

    A task sleeps ``period`` seconds over and over on the runtime clock and
    measures how late it wakes; lateness over ``threshold`` becomes a
    :class:`LagEvent` (the last ``keep`` are kept in ``events``).  While the loop
    is blocked nothing on it can look, so a watchdog thread does: when the task's
    last tick is older than ``threshold`` it reads which node's actor is running
    what (``Actor.current``, the most recent ``busy_since`` among running actors:
    nothing else can have started while the loop is stuck), and the event names
    that node and callback, provided the callback's code is on the loop
    thread's stack at that moment: an ``async`` callback that is only awaiting
    does not hold the loop, whatever else stalls it meanwhile (a constructor,
    an import).  Nobody is blamed either when the machine, not a callback,
    held the loop: when the watchdog itself wakes late (the whole process was
    starved), or when the loop thread spent enough of the stall waiting for a
    CPU that, without that wait, it would not have lagged (Linux counts that
    wait per thread, in ``/proc/thread-self/schedstat``).  The thread only
    reads; it stops with the task.
    """

    def __init__(self, runtime: Runtime, *, threshold: float = 0.05, period: float = 0.02, keep: int = 50) -> None:
        self.threshold = threshold
        self.period = period
        self.events: deque[LagEvent] = deque(maxlen=keep)
        self._runtime = runtime
        self._tick = 0.0
        self._suspect: tuple[str, str] | None = None
        self._stop = threading.Event()
        self._loop_thread = threading.get_ident()

    async def run(self) -> None:
        """Measure until cancelled."""
        clock = self._runtime.clock
        self._tick = clock.monotonic()
        self._loop_thread = threading.get_ident()
        thread = threading.Thread(target=self._watch, name=f"actors lag monitor ({self._runtime.name})", daemon=True)
        waited = _CpuWait()
        try:
            thread.start()
            mark = waited()
            while True:
                await anyio.sleep(self.period)
                now = clock.monotonic()
                lag = now - self._tick - self.period
                if lag > self.threshold:
                    node, callback = self._suspect or ("", "")
                    if lag - (waited() - mark) <= self.threshold:
                        # Preempted: the callback would have finished in time on a free CPU.
                        node, callback = "", ""
                    self.events.append(LagEvent(stamp=clock.now_ns() / 1e9, lag=lag, node=node, callback=callback))
                # Tick first: the watchdog must not pin the next stall on this one's suspect.
                self._tick = now
                self._suspect = None
                mark = waited()
        finally:
            self._stop.set()
            waited.close()

    def _watch(self) -> None:
        # The loop's time() is time.monotonic() on a wall-clock loop: safe to read from here.
        now = self._runtime.clock.monotonic
        while True:
            before = now()
            if self._stop.wait(self.period):
                return
            if now() - before - self.period > self.threshold:
                # This thread stalled too: the whole process was not scheduled, and
                # whatever callback was running when it stopped is not to blame.
                self._suspect = ("", "")
            elif self._suspect is None and now() - self._tick > self.threshold:
                self._suspect = self._running() or ("", "")

    def _running(self) -> tuple[str, str] | None:
        latest: tuple[float, str, Any] | None = None
        for core in list(self._runtime.nodes.values()):
            actor = core.actor
            entity = actor.current
            if entity is not None and (latest is None or actor.busy_since > latest[0]):
                latest = (actor.busy_since, core.fqn, entity)
        if latest is None:
            return None
        entity = latest[2]
        fn = getattr(entity, "callback", None) or getattr(entity, "handler", None) or getattr(entity, "fn", None)
        if not self._executing(fn):
            return None  # an async callback that awaits: something else holds the loop
        return latest[1], getattr(fn, "__qualname__", None) or type(entity).__name__

    def _executing(self, fn: Any) -> bool:
        """Whether ``fn``'s code is on the loop thread's stack now (True when it cannot tell)."""
        code = getattr(getattr(fn, "__func__", fn), "__code__", None)
        frame = sys._current_frames().get(self._loop_thread)
        if code is None or frame is None:
            return True
        while frame is not None:
            if frame.f_code is code:
                return True
            frame = frame.f_back
        return False
