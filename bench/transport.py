"""Scenario k (zenoh): across processes on loopback, actors over Zenoh beside rclpy over Fast DDS.

Every measurement runs in two child processes, as two graphs would: a
*sink* (subscriber, server or echo) starts first and prints ``ready``; then
a *source* (publisher, client or pinger) does the work; one of them prints
the result as JSON.  ``python -m bench.transport ROLE JSON_ARGS`` is a child.

- one-way: ``n`` String messages ("Hello World"), RELIABLE + KEEP_ALL on both
  sides (no drops: Zenoh blocks; rclpy's publish fails while Fast DDS's history
  is full, and the source tries again until it is taken), published in
  batches of 100; deliveries per second at the sink, first to last message
  (a sink that hears nothing for 5 s stops and reports what came: the row
  then says how many were lost);
- round trip: ``n`` SetBool calls one after another; microseconds per call;
- latency: ``n`` small messages (Int64) pinged to an echo process and back,
  one at a time; the median round trip in microseconds (one way is half).

rclpy's sink, server and echo spin an EventsExecutor (the faster of rclpy's
two here); its source and client spin one too.  The actors children run the
Zenoh transport on the loop ``actors run`` gives a graph with a transport
(:func:`actors.core.loops.wall_loop`: uvloop when the ``fast`` extra is
installed, else select), meeting on a private port.

The floor: a bare eclipse-zenoh pair of Python processes doing the same on
the same port, with no graph around it: a subscriber callback (zenoh's
default, ``indirect=True``: one long-lived Python thread per subscriber)
counting the String's CDR bytes that a publisher puts; a queryable answering
``get`` calls one after another (a caller blocked on zenoh's FIFO channel of
replies); a callback echoing the Int64's bytes back.  What actors adds is its own work
above that (keys, attachments, CDR, the hand-off into the loop).
"""

from __future__ import annotations

import importlib.util
import json
import socket
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from typing import Any

from bench import ros
from bench.harness import ROOT, Result, child_env, repeat

__all__ = ["run"]

SCENARIO = "k. zenoh (2 processes)"
ZENOH_HINT = "zenoh: not installed — pip install -e '.[zenoh]'"
BATCH = 100
IDLE = 5.0  # seconds without a message after which a sink stops waiting for the rest


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def _pair(sink: str, source: str, args: dict[str, Any], env: dict[str, str], result_from: str) -> Any:
    """Start the sink, wait for its ``ready``, run the source; the JSON that ``result_from`` prints."""
    args = {**args, "port": _free_port()}
    command = [sys.executable, "-m", "bench.transport"]
    first = subprocess.Popen([*command, sink, json.dumps(args)], cwd=ROOT, env=env, stdout=subprocess.PIPE, text=True)
    second = None
    try:
        assert first.stdout is not None
        if first.stdout.readline().strip() != "ready":
            raise RuntimeError(f"{sink} did not start")
        second = subprocess.Popen(
            [*command, source, json.dumps(args)], cwd=ROOT, env=env, stdout=subprocess.PIPE, text=True
        )
        reader = first if result_from == "sink" else second
        out, _ = reader.communicate(timeout=300)
        lines = out.strip().splitlines()
        if not lines:  # its traceback went to stderr
            raise RuntimeError(f"the {result_from} exited ({reader.returncode}) without a result")
        return json.loads(lines[-1])
    finally:
        for proc in (first, second):
            if proc is not None and proc.poll() is None:
                proc.kill()
                proc.wait()


MEASURES: dict[str, tuple[str, str, str, str, bool]] = {
    # name: (sink role, source role, who prints, unit, higher is better)
    "one-way": ("sink", "source", "sink", "deliveries/s", True),
    "round trip": ("server", "client", "client", "µs/call", False),
    "latency p50": ("echo", "ping", "ping", "µs round trip", False),
}


def run(quick: bool = False) -> list[Result]:
    """The three measurements, actors over Zenoh beside rclpy over Fast DDS."""
    counts = {
        "one-way": 20_000 if quick else 100_000,
        "round trip": 500 if quick else 2_000,
        "latency p50": 500 if quick else 2_000,
    }
    reps = 2 if quick else 5
    results: list[Result] = []
    zenoh_missing = importlib.util.find_spec("zenoh") is None
    for measure, (sink, source, result_from, unit, higher) in MEASURES.items():
        args = {"n": counts[measure]}
        actors_case = f"{measure}: actors (Zenoh)"
        ros_case = f"{measure}: rclpy (Fast DDS)"
        if zenoh_missing:
            results.append(Result(SCENARIO, actors_case, unit, [], higher, note=ZENOH_HINT))
        else:
            floor = f"{measure}: bare zenoh (floor)"
            runs = repeat(lambda: _pair(f"actors_{sink}", f"actors_{source}", args, child_env(), result_from), reps)
            results.append(
                _result(actors_case, unit, runs, higher, args["n"], baselines={"rclpy": ros_case, "floor": floor})
            )
            runs = repeat(lambda: _pair(f"zenoh_{sink}", f"zenoh_{source}", args, child_env(), result_from), reps)
            results.append(_result(floor, unit, runs, higher, args["n"]))
        why = ros.unavailable()
        if why is not None:
            results.append(Result(SCENARIO, ros_case, unit, [], higher, note=why))
            continue
        try:
            ros_runs = repeat(lambda: _pair(f"ros_{sink}", f"ros_{source}", args, ros.ros_env(), result_from), reps)
        except Exception as exc:
            results.append(Result(SCENARIO, ros_case, unit, [], higher, note=f"failed: {exc}"))
            continue
        results.append(_result(ros_case, unit, ros_runs, higher, args["n"]))
    return results


def _result(
    case: str, unit: str, runs: list[Any], higher: bool, n: int, baselines: dict[str, str] | None = None
) -> Result:
    """A row from the children's answers: a figure each, or [rate, received] from a sink."""
    if runs and isinstance(runs[0], list):
        lost = [n - received for _, received in runs]
        note = f"lost {max(lost):,} of {n:,} in a run" if any(lost) else ""
        return Result(SCENARIO, case, unit, [rate for rate, _ in runs], higher, note=note, baselines=baselines or {})
    return Result(SCENARIO, case, unit, runs, higher, baselines=baselines or {})


def _rate(stamps: list[float]) -> float:
    """Deliveries per second, first to last."""
    return (len(stamps) - 1) / (stamps[-1] - stamps[0])


def _waiting(stamps: list[float], n: int) -> bool:
    """Whether a sink should keep waiting: not all came, and the last came less than IDLE ago."""
    return len(stamps) < n and not (stamps and time.perf_counter() - stamps[-1] > IDLE)


# -- the actors children ----------------------------------------------------------------


def _actors(role: str, args: dict[str, Any]) -> Any:
    import anyio

    from actors import HistoryPolicy, Node, QoSProfile, ReliabilityPolicy, Runtime
    from actors.core.loops import wall_loop
    from actors.launch.graph_file import TransportSection
    from actors.transport.zenoh import ZenohTransport
    from bench.services import handle
    from interfaces.std_msgs.msg import Int64, String
    from interfaces.std_srvs.srv import SetBool

    endpoint = f"tcp/127.0.0.1:{args['port']}"
    section = TransportSection(connect=[endpoint], listen=[endpoint, "tcp/127.0.0.1:0"])
    qos = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)
    n = args["n"]

    async def main() -> Any:
        async with Runtime(name=role, attach=[ZenohTransport(section)]) as rt:
            node = rt.spawn(Node, "bench", start_parameter_services=False)
            if role == "sink":
                stamps: list[float] = []
                node.create_subscription(String, "chatter", lambda msg: stamps.append(time.perf_counter()), qos)
                _ready()
                while _waiting(stamps, n):
                    await anyio.sleep(0.05)
                return [_rate(stamps), len(stamps)]
            if role == "source":
                pub = node.create_publisher(String, "chatter", qos)
                await _until(lambda: pub.get_subscription_count() > 0)
                msg = String(data="Hello World")
                for _ in range(0, n, BATCH):
                    for _ in range(BATCH):
                        pub.publish(msg)
                    await anyio.lowlevel.checkpoint()
                await anyio.sleep_forever()  # the sink reports; the parent ends this process
            if role == "server":
                node.create_service(SetBool, "set_bool", handle)
                _ready()
                await anyio.sleep_forever()
            if role == "client":
                client = node.create_client(SetBool, "set_bool")
                await client.wait_for_service()
                request = SetBool.Request(data=True)
                start = time.perf_counter()
                for _ in range(n):
                    await client.call(request)
                return (time.perf_counter() - start) / n * 1e6
            if role == "echo":
                back = node.create_publisher(Int64, "pong", 10)
                node.create_subscription(Int64, "ping", back.publish, 10)
                _ready()
                await anyio.sleep_forever()
            assert role == "ping"
            pings = node.create_publisher(Int64, "ping", 10)
            answered = anyio.Event()
            node.create_subscription(Int64, "pong", lambda msg: answered.set(), 10)
            await _until(lambda: pings.get_subscription_count() > 0)
            await _warm(lambda: pings.publish(Int64(data=-1)), lambda: answered)
            trips = []
            for i in range(n):
                answered = anyio.Event()
                start = time.perf_counter()
                pings.publish(Int64(data=i))
                await answered.wait()
                trips.append((time.perf_counter() - start) * 1e6)
            return statistics.median(trips)

    return anyio.run(main, backend_options={"loop_factory": wall_loop(None, transport=True)})


async def _until(condition: Callable[[], bool]) -> None:
    import anyio

    while not condition():  # discovery, across processes: nothing local to wait on
        await anyio.sleep(0.01)


async def _warm(send: Callable[[], None], answered: Callable[[], Any]) -> None:
    """Ping until the first pong comes back: the echo's way back is discovered too."""
    import anyio

    while True:
        send()
        with anyio.move_on_after(0.1):
            await answered().wait()
            return


def _ready() -> None:
    print("ready", flush=True)


# -- the rclpy children -------------------------------------------------------------------


def _rclpy(role: str, args: dict[str, Any]) -> Any:
    import rclpy
    from rclpy._rclpy_pybind11 import RCLError
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import Int64, String
    from std_srvs.srv import SetBool

    from bench.services import handle

    rclpy.init()
    executor = ros._executor("events")
    node = rclpy.create_node(f"bench_{role}")
    executor.add_node(node)
    qos = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)
    n = args["n"]
    spin = ros._spin_until
    if role == "sink":
        stamps: list[float] = []
        node.create_subscription(String, "chatter", lambda msg: stamps.append(time.perf_counter()), qos)
        _ready()
        while _waiting(stamps, n):
            executor.spin_once(timeout_sec=0.05)
        return [_rate(stamps), len(stamps)]
    if role == "source":
        pub = node.create_publisher(String, "chatter", qos)
        spin(executor, lambda: pub.get_subscription_count() > 0)
        msg = String(data="Hello World")
        for _ in range(0, n, BATCH):
            for _ in range(BATCH):
                while True:
                    try:
                        pub.publish(msg)
                        break
                    except RCLError:  # KEEP_ALL's history is full: wait for acknowledgements, as Zenoh blocks
                        executor.spin_once(timeout_sec=0.001)
            executor.spin_once(timeout_sec=0)
        spin(executor, lambda: False, timeout=float("inf"))
    if role == "server":
        node.create_service(SetBool, "set_bool", handle)
        _ready()
        spin(executor, lambda: False, timeout=float("inf"))
    if role == "client":
        client = node.create_client(SetBool, "set_bool")
        spin(executor, client.service_is_ready)
        request = SetBool.Request(data=True)
        start = time.perf_counter()
        for _ in range(n):
            future = client.call_async(request)
            spin(executor, future.done)
        return (time.perf_counter() - start) / n * 1e6
    if role == "echo":
        back = node.create_publisher(Int64, "pong", 10)
        node.create_subscription(Int64, "ping", back.publish, 10)
        _ready()
        spin(executor, lambda: False, timeout=float("inf"))
    assert role == "ping"
    pings = node.create_publisher(Int64, "ping", 10)
    pongs: list[int] = []
    node.create_subscription(Int64, "pong", lambda msg: pongs.append(msg.data), 10)
    spin(executor, lambda: pings.get_subscription_count() > 0)
    while not pongs:  # the echo's way back is discovered too
        pings.publish(Int64(data=-1))
        executor.spin_once(timeout_sec=0.1)
    trips = []
    for i in range(n):
        start = time.perf_counter()
        pings.publish(Int64(data=i))
        spin(executor, lambda: pongs[-1] == i)
        trips.append((time.perf_counter() - start) * 1e6)
    return statistics.median(trips)


# -- the bare zenoh children ---------------------------------------------------------------


def _zenoh(role: str, args: dict[str, Any]) -> Any:
    import threading

    import zenoh

    from actors import codec
    from interfaces.std_msgs.msg import Int64, String

    endpoint = f"tcp/127.0.0.1:{args['port']}"
    config = zenoh.Config()
    config.insert_json5("mode", '"peer"')
    config.insert_json5("scouting/multicast/enabled", "false")
    config.insert_json5("scouting/delay", "0")
    config.insert_json5("connect/endpoints", json.dumps([endpoint]))
    config.insert_json5("connect/timeout_ms", "0")
    config.insert_json5("connect/exit_on_failure", "false")
    # The first of the two binds the port; the other connects to it (as the actors children).
    config.insert_json5("listen/endpoints", json.dumps([endpoint, "tcp/127.0.0.1:0"]))
    config.insert_json5("listen/exit_on_failure", "false")
    session = zenoh.open(config)
    n = args["n"]
    if role == "sink":
        stamps: list[float] = []
        sub = session.declare_subscriber("chatter", lambda sample: stamps.append(time.perf_counter()))
        _ready()
        while _waiting(stamps, n):
            time.sleep(0.05)
        del sub
        return [_rate(stamps), len(stamps)]
    if role == "source":
        pub = session.declare_publisher("chatter", congestion_control=zenoh.CongestionControl.BLOCK)
        while not pub.matching_status.matching:
            time.sleep(0.01)
        payload = codec.encode_cdr(String(data="Hello World"))
        for _ in range(n):
            pub.put(payload)
        threading.Event().wait()  # the sink reports; the parent ends this process
    if role == "server":
        reply = codec.encode_cdr(String(data="done"))
        queryable = session.declare_queryable("set_bool", lambda query: query.reply(query.key_expr, reply))
        _ready()
        threading.Event().wait()
        del queryable
    if role == "client":
        request = codec.encode_cdr(Int64(data=1))
        while not list(session.get("set_bool", payload=request)):
            time.sleep(0.01)  # discovery, across processes
        start = time.perf_counter()
        for _ in range(n):
            replies = list(session.get("set_bool", payload=request))
            assert replies, "the queryable did not answer"
        return (time.perf_counter() - start) / n * 1e6
    if role == "echo":
        back = session.declare_publisher("pong")
        sub = session.declare_subscriber("ping", lambda sample: back.put(sample.payload))
        _ready()
        threading.Event().wait()
        del sub
    assert role == "ping"
    answered = threading.Event()
    pongs = session.declare_subscriber("pong", lambda sample: answered.set())
    pings = session.declare_publisher("ping")
    while not answered.is_set():  # the echo's way back is discovered too
        pings.put(codec.encode_cdr(Int64(data=-1)))
        answered.wait(0.1)
    trips = []
    for i in range(n):
        answered.clear()
        start = time.perf_counter()
        pings.put(codec.encode_cdr(Int64(data=i)))
        answered.wait()
        trips.append((time.perf_counter() - start) * 1e6)
    del pongs
    return statistics.median(trips)


def main(argv: Sequence[str]) -> None:
    """``python -m bench.transport ROLE JSON_ARGS``: one child; prints ``ready`` and/or its result."""
    role, args = argv[0], json.loads(argv[1])
    family, _, part = role.partition("_")
    children = {"actors": _actors, "zenoh": _zenoh, "ros": _rclpy}
    result = children[family](part, args)
    print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
