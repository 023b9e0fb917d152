"""The rclpy baselines: the same workloads through real ROS 2, each run in its own process.

Installed with ``pip install -e '.[bench-ros]'`` (ROS 2 Kilted wheels for
Python 3.11).  rclpy's init/shutdown and the DDS participant are process-wide,
so every measurement runs in a child ``python -m bench.ros MEASURE EXECUTOR
ARGS`` that prints its samples as JSON; the parent (the scenario modules) turns
them into Results beside actors' own.  Both executors are measured:
``SingleThreadedExecutor`` and ``rclpy.experimental.EventsExecutor``.

The child environment (:func:`ros_env`) is all the wheels need: a writable
``ROS_LOG_DIR`` (rcl's logging fails without a home directory to write to),
``RMW_IMPLEMENTATION=rmw_fastrtps_cpp``, and
``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` so DDS discovery never leaves
this machine.  The wheels' own start-up hook sets LD_LIBRARY_PATH by
re-executing Python once; a child that inherits a bootstrapped environment
skips that, as a shell with ROS sourced would.
"""

from __future__ import annotations

import functools
import gc
import importlib.util
import json
import os
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from typing import Any

from bench.harness import Result, child_env, repeat, run_child, time_to_line

__all__ = ["EXECUTORS", "INSTALL_HINT", "baselines", "unavailable", "measured", "first_message", "nodes"]

EXECUTORS = {"single": "rclpy SingleThreaded", "events": "rclpy EventsExecutor"}
LABELS = {"single": "rclpy ST", "events": "rclpy Events"}
INSTALL_HINT = "rclpy: not installed — pip install -e '.[bench-ros]'"
DEPTH = 1000  # queue depths, as the actors side: nothing is dropped
BATCH = 100  # messages published between spins, as the actors side publishes between yields
FIRST_MESSAGE = "I heard"


def baselines(executors: Sequence[str] = tuple(EXECUTORS)) -> dict[str, str]:
    """The ``Result.baselines`` entries that compare a case with rclpy's rows."""
    return {LABELS[e]: EXECUTORS[e] for e in executors}


@functools.cache
def ros_env() -> dict[str, str]:
    """The environment an rclpy child needs (see the module docstring)."""
    env = child_env(
        {
            "ROS_LOG_DIR": tempfile.mkdtemp(prefix="bench-ros-log-"),
            "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp",
            "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
        }
    )
    if "_ROS_WHEELS_BOOTSTRAP_COMPLETE" not in os.environ:
        del env["_ROS_WHEELS_BOOTSTRAP_COMPLETE"]  # let the wheels set their library path
    return env


@functools.cache
def unavailable() -> str | None:
    """Why rclpy cannot be measured here, or None when it can (checked once, in a child)."""
    if importlib.util.find_spec("rclpy") is None:
        return INSTALL_HINT
    try:
        run_child(["-m", "bench.ros", "probe", "single", "{}"], ros_env(), timeout=60)
    except Exception as exc:
        return f"rclpy: failed to start — {exc}"
    return None


def _missing(scenario: str, unit: str, higher_better: bool, why: str) -> list[Result]:
    return [Result(scenario, "rclpy", unit, [], higher_better, note=why)]


def measured(
    scenario: str,
    measure: str,
    unit: str,
    reps: int,
    *,
    higher_better: bool = True,
    **args: Any,
) -> list[Result]:
    """One Result per executor for ``measure`` (``one_way`` or ``service``) with ``args``."""
    why = unavailable()
    if why is not None:
        return _missing(scenario, unit, higher_better, why)
    results = []
    for executor, case in EXECUTORS.items():
        try:
            samples = run_child(["-m", "bench.ros", measure, executor, json.dumps({**args, "reps": reps})], ros_env())
        except Exception as exc:
            results.append(Result(scenario, case, unit, [], higher_better, note=f"failed: {exc}"))
            continue
        results.append(Result(scenario, case, unit, samples, higher_better))
    return results


def first_message(scenario: str, reps: int) -> list[Result]:
    """Seconds from process start to the listener's first message, talker on a 0.5 s timer."""
    why = unavailable()
    if why is not None:
        return _missing(scenario, "s", False, why)
    results = []
    for executor, case in EXECUTORS.items():
        args = ["-m", "bench.ros", "first_message", executor, "{}"]
        try:
            samples = repeat(lambda: time_to_line(args, FIRST_MESSAGE, ros_env()), reps)
        except Exception as exc:
            results.append(Result(scenario, case, "s", [], False, note=f"failed: {exc}"))
            continue
        results.append(Result(scenario, case, "s", samples, False))
    return results


@functools.cache
def nodes(count: int, executor: str, reps: int) -> list[dict[str, float]] | str:
    """``reps`` fresh processes that each create ``count`` idle rclpy nodes.

    Each run gives ``spawn`` (seconds to create them) and ``rss_per_node``
    (bytes).  Cached, so start-up and memory share the runs.  Returns why
    instead when rclpy cannot be measured.
    """
    why = unavailable()
    if why is not None:
        return why
    args = ["-m", "bench.ros", "nodes", executor, json.dumps({"count": count})]
    try:
        return repeat(lambda: run_child(args, ros_env(), timeout=1800), reps, warmup=False)
    except Exception as exc:
        return f"failed: {exc}"


# -- the child side: runs with rclpy imported ------------------------------------


def _executor(kind: str) -> Any:
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.experimental import EventsExecutor

    return SingleThreadedExecutor() if kind == "single" else EventsExecutor()


def _spin_until(
    executor: Any, done: Callable[[], bool], what: str | Callable[[], str] = "", timeout: float = 60
) -> None:
    """Spin until ``done()``; RuntimeError naming ``what`` after ``timeout`` seconds, not a hang."""
    deadline = time.monotonic() + timeout
    while not done():
        if time.monotonic() > deadline:
            raise RuntimeError(f"no progress for {timeout:.0f} s: {what() if callable(what) else what}")
        executor.spin_once(timeout_sec=0.1)


def _one_way_rate(kind: str, n: int, subscribers: int) -> float:
    """Deliveries per second from one publisher to ``subscribers`` subscriptions, as bench.throughput."""
    import rclpy
    from rclpy.qos import QoSProfile
    from std_msgs.msg import String

    executor = _executor(kind)
    talker = rclpy.create_node("talker")
    pub = talker.create_publisher(String, "topic", QoSProfile(depth=DEPTH))
    received = 0

    def on_msg(msg: String) -> None:
        nonlocal received
        received += 1

    listeners = [rclpy.create_node(f"listener{i}") for i in range(subscribers)]
    for node in listeners:
        node.create_subscription(String, "topic", on_msg, QoSProfile(depth=DEPTH))
    for node in [talker, *listeners]:
        executor.add_node(node)
    _spin_until(executor, lambda: pub.get_subscription_count() == subscribers)
    msg = String(data="Hello World")
    total = n * subscribers
    start = time.perf_counter()
    for sent in range(BATCH, n + 1, BATCH):
        for _ in range(BATCH):
            pub.publish(msg)
        # Each batch delivered before the next: with 500 messages in flight the
        # EventsExecutor lost a batch (10 subscribers) and the run never ended.
        _spin_until(executor, lambda: received >= sent * subscribers, lambda: f"{received} of {total} delivered")
    elapsed = time.perf_counter() - start
    executor.shutdown()
    for node in [talker, *listeners]:
        node.destroy_node()
    return total / elapsed


def _service_time(kind: str, n: int, callers: int) -> float:
    """Microseconds per SetBool call, ``callers`` chains of calls in flight, as bench.services."""
    import rclpy
    from rclpy.qos import QoSProfile
    from std_srvs.srv import SetBool

    from bench.services import handle

    executor = _executor(kind)
    server = rclpy.create_node("server")
    server.create_service(SetBool, "set_bool", handle, qos_profile=QoSProfile(depth=DEPTH))
    caller = rclpy.create_node("caller")
    client = caller.create_client(SetBool, "set_bool", qos_profile=QoSProfile(depth=DEPTH))
    for node in (server, caller):
        executor.add_node(node)
    _spin_until(executor, client.service_is_ready)
    request = SetBool.Request(data=True)
    per_caller = n // callers
    done = 0

    def call(left: int) -> None:
        # Each caller sends its next request when the previous response arrives.
        def on_response(_future: Any) -> None:
            nonlocal done
            done += 1
            if left > 1:
                call(left - 1)

        client.call_async(request).add_done_callback(on_response)

    start = time.perf_counter()
    for _ in range(callers):
        call(per_caller)
    _spin_until(executor, lambda: done >= per_caller * callers)
    elapsed = time.perf_counter() - start
    executor.shutdown()
    server.destroy_node()
    caller.destroy_node()
    return elapsed / (per_caller * callers) * 1e6


def _first_message(kind: str) -> None:
    """The tutorial's talker (0.5 s timer) and listener; print a line on the first message, spin on."""
    import rclpy
    from std_msgs.msg import String

    executor = _executor(kind)
    talker = rclpy.create_node("minimal_publisher")
    pub = talker.create_publisher(String, "topic", 10)
    talker.create_timer(0.5, lambda: pub.publish(String(data="Hello World")))
    listener = rclpy.create_node("minimal_subscriber")
    listener.create_subscription(String, "topic", lambda msg: print(f"{FIRST_MESSAGE}: {msg.data}"), 10)
    executor.add_node(talker)
    executor.add_node(listener)
    # spin_once in a loop: EventsExecutor.spin() fires no timers in the Kilted wheels (9.1.2).
    _spin_until(executor, lambda: False, timeout=float("inf"))


def _rss() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _nodes(kind: str, count: int) -> dict[str, float]:
    """Create ``count`` idle nodes (1 publisher, 1 subscription, 1 timer each), as bench.memory."""
    import rclpy
    from std_msgs.msg import String

    executor = _executor(kind)
    warm = rclpy.create_node("warm")  # the process-wide DDS participant exists before measuring
    executor.add_node(warm)
    executor.spin_once(timeout_sec=0.01)
    gc.collect()
    before = _rss()
    start = time.perf_counter()
    idle = []
    for i in range(count):
        node = rclpy.create_node(f"idle{i}")
        node.create_publisher(String, "out", 10)
        node.create_subscription(String, "in", lambda msg: None, 10)
        node.create_timer(1.0, lambda: None)
        executor.add_node(node)
        idle.append(node)
    executor.spin_once(timeout_sec=0)
    spawn = time.perf_counter() - start
    gc.collect()
    return {"spawn": spawn, "rss_per_node": (_rss() - before) / count}


def main(argv: Sequence[str]) -> None:
    """``python -m bench.ros MEASURE EXECUTOR JSON_ARGS``: measure, print the result as JSON."""
    import rclpy

    measure, kind, args = argv[0], argv[1], json.loads(argv[2])
    rclpy.init()
    if measure == "first_message":
        _first_message(kind)
        return
    reps = args.pop("reps", 1)
    result: Any
    if measure == "one_way":
        result = repeat(lambda: _one_way_rate(kind, **args), reps)
    elif measure == "service":
        result = repeat(lambda: _service_time(kind, **args), reps)
    elif measure == "nodes":
        result = _nodes(kind, **args)
    else:  # probe: init worked, and the executor can be built
        _executor(kind).shutdown()
        result = {}
    print(json.dumps(result), flush=True)
    # Skip rclpy's teardown of thousands of nodes: the process ends here anyway.
    os._exit(0)


if __name__ == "__main__":
    main(sys.argv[1:])
