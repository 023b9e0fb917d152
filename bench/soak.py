"""Soak and load: the demo graph on the wall clock for minutes, its control socket hammered (not CI).

``python -m bench.soak [--minutes 10]``
    Runs ``python -m actors.run graph.toml`` for the given minutes, samples its
    RSS every 10 s, and every 10 s hammers the control socket with one bounded
    round: 300 connections opened at once (more than the 256 allowed), each
    asking for the graph, plus a publish and a short-lived subscription.
    Prints the RSS samples, the RSS slope after the first minute (KB/min, least
    squares), the connections served, refused and failed, and the graph's
    descriptors before and after.

``python -m bench.soak --connections``
    Issue 17's acceptance 2: 2,000 connections opened at once and 500 idle
    ones held, in waves for 30 s from a process of their own, while a prober
    asks for the node list every 100 ms (as ``actors node list`` does,
    through the command line's own client); prints the probe latencies
    (median, p99, max, how many over 1 s), what the waves got, and the
    graph's descriptors before, at their peak and after.  Every 50th probe
    also times a real ``actors node list`` process (Python's start included).

``python -m bench.soak --round2 [--minutes 30] [--fresh-names] [--without PART ...]``
    Issue 34's acceptance 6: the TurtleBot graph with the Zenoh transport, a
    recorder and the live view; beside it a plain Zenoh peer declaring 500
    liveliness tokens and taking them back every 10 s, a Foxglove viewer
    subscribed to every channel (20 s visits, again and again), and every
    10 s a control round (50 connections, a publish, a subscription) and an
    ``actors topic echo /odom --once``.  The baseline, in the same run, is a
    bare Zenoh peer subscribed to the same liveliness tokens.  Prints RSS
    and descriptors every 10 s, the RSS slopes over the last 20 minutes (the
    graph's and the bare peer's) and the descriptors' range.  The tokens'
    names come from three sets in turn; with ``--fresh-names`` every round
    has new ones, and Zenoh itself (upstream, the bare peer as much as the
    graph) keeps about 1.3 KB per name it ever heard of.  ``--without`` leaves
    parts out, to find what grows: ``churn`` (the token-churning peer),
    ``recorder``, ``viewer`` (the live view and its viewer), ``cli`` (the
    control rounds and ``topic echo``), ``zenoh`` (the transport, and with it
    the churner and the bare peer).  Runs shorter than 23 minutes take the
    slope after their first 3.

``python -m bench.soak --stalled``
    Acceptance 3: five ``actors topic echo /scan`` processes whose output
    nobody reads, for 60 s; prints the graph's RSS growth beside the same 60 s
    of the same graph with no reader.

Every figure comes from the graph process (``/proc/<pid>``): Linux only.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import multiprocessing
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

import anyio
import msgspec

from actors.cli._client import connect
from actors.ops.control import Diagnose, GetGraph, Publish, Reply, Subscribe, decode_reply, frame
from actors.ops.doctor import Report

__all__ = ["GraphProcess", "hammer_round", "rss_kb", "slope", "main"]

ROOT = Path(__file__).resolve().parent.parent
SAMPLE_EVERY = 10.0  # s


def rss_kb(pid: int) -> int:
    """The resident set size of process ``pid``, in KB."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise RuntimeError(f"no VmRSS for process {pid}")


def fds(pid: int) -> int:
    """How many descriptors process ``pid`` has open."""
    return len(os.listdir(f"/proc/{pid}/fd"))


def slope(samples: list[tuple[float, int]]) -> float:
    """The least-squares slope of ``(seconds, KB)`` samples, in KB per minute."""
    ts = [t for t, _ in samples]
    ks = [k for _, k in samples]
    mean_t, mean_k = statistics.fmean(ts), statistics.fmean(ks)
    var = sum((t - mean_t) ** 2 for t in ts)
    return 60.0 * sum((t - mean_t) * (k - mean_k) for t, k in samples) / var if var else 0.0


class GraphProcess:
    """``python -m actors.run GRAPH`` in its own control directory; ``name`` is its endpoint name."""

    def __init__(self, graph: Path, runtime_dir: Path, *options: str) -> None:
        self.name = graph.stem
        self.env = {**os.environ, "XDG_RUNTIME_DIR": str(runtime_dir), "PYTHONUNBUFFERED": "1"}
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "actors.run", str(graph), *options],
            cwd=ROOT,
            env=self.env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
        )
        self.path = runtime_dir / "actors" / f"{self.name}.sock"
        self.log: list[str] = []
        threading.Thread(target=self._drain, daemon=True).start()
        deadline = time.monotonic() + 30
        while not self._answers():
            if time.monotonic() > deadline or self.proc.poll() is not None:
                raise RuntimeError("the graph did not start:\n" + "".join(self.log))
            time.sleep(0.1)

    def _drain(self) -> None:
        assert self.proc.stderr is not None
        for line in self.proc.stderr:
            self.log.append(line)

    def _answers(self) -> bool:
        with contextlib.suppress(Exception), self.connect() as conn:
            conn.graph()
            return True
        return False

    def connect(self):
        """A command-line connection to the graph (the environment names its directory)."""
        os.environ["XDG_RUNTIME_DIR"] = self.env["XDG_RUNTIME_DIR"]
        return connect(self.name)

    @property
    def pid(self) -> int:
        return self.proc.pid

    def stop(self) -> int:
        """SIGTERM, then the exit code."""
        self.proc.terminate()
        return self.proc.wait(timeout=30)

    def tracebacks(self) -> int:
        """How many tracebacks the graph printed."""
        return sum("Traceback" in line for line in self.log)


async def _one(path: Path, request: object, outcome: Counter[str], *, hold: float = 0.0) -> None:
    try:
        with anyio.fail_after(10):
            async with await anyio.connect_unix(path) as stream:
                with contextlib.suppress(anyio.BrokenResourceError, anyio.ClosedResourceError):
                    await stream.send(frame(request))  # a refused connection is closed before we speak
                reply = await _reply(stream)
                if hold:
                    await anyio.sleep(hold)
    except TimeoutError:
        outcome["timed out"] += 1
        return
    except OSError as exc:
        outcome[f"connect failed ({exc.strerror or exc})"] += 1
        return
    except (anyio.EndOfStream, anyio.IncompleteRead, anyio.BrokenResourceError):
        outcome["closed without an answer"] += 1
        return
    if reply.ok:
        outcome["served"] += 1
    elif reply.busy:
        outcome["refused (busy)"] += 1
    else:
        outcome[f"error: {reply.error[:60]}"] += 1


async def _reply(stream: anyio.abc.SocketStream) -> Reply:
    buffer = b""
    while len(buffer) < 4 or len(buffer) < 4 + int.from_bytes(buffer[:4], "big"):
        buffer += await stream.receive()
    size = int.from_bytes(buffer[:4], "big")
    return decode_reply(buffer[4 : 4 + size])


async def _idle(path: Path, seconds: float, outcome: Counter[str]) -> None:
    """Connect and say nothing for ``seconds`` (or until the graph closes the connection)."""
    try:
        async with await anyio.connect_unix(path) as stream:
            with anyio.move_on_after(seconds):
                with contextlib.suppress(anyio.EndOfStream, anyio.BrokenResourceError):
                    data = await stream.receive()
                    outcome["idle: refused" if decode_reply(data[4:]).busy else "idle: answered"] += 1
                    return
            outcome["idle: held"] += 1
    except OSError as exc:
        outcome[f"idle: connect failed ({exc.strerror or exc})"] += 1
    except (anyio.EndOfStream, msgspec.DecodeError):
        outcome["idle: closed by the graph"] += 1


def hammer_round(path: Path, connections: int = 300) -> Counter[str]:
    """One bounded round: ``connections`` opened at once asking for the graph, a publish, a subscription."""
    outcome: Counter[str] = Counter()

    async def round_() -> None:
        async with anyio.create_task_group() as tg:
            for _ in range(connections):  # each held a moment after its answer: all open at once
                tg.start_soon(functools.partial(_one, path, GetGraph(), outcome, hold=0.3))
            tg.start_soon(_one, path, Publish(topic="/soak", type="std_msgs/msg/String", msg={"data": "x"}), outcome)
            tg.start_soon(functools.partial(_one, path, Subscribe(topic="/scan"), outcome, hold=1.0))

    anyio.run(round_)
    return outcome


@contextlib.contextmanager
def demo_graph() -> Iterator[GraphProcess]:
    """The demo graph, running in a private control directory."""
    with tempfile.TemporaryDirectory() as tmp:
        runtime_dir = Path(tmp) / "run"
        runtime_dir.mkdir(mode=0o700)
        graph = GraphProcess(ROOT / "graph.toml", runtime_dir)
        try:
            yield graph
        finally:
            code = graph.stop()
            print(f"graph exit code {code}, tracebacks in its log: {graph.tracebacks()}")


def soak(minutes: float) -> None:
    """The 10-minute soak (see the module docstring)."""
    with demo_graph() as graph:
        start = time.monotonic()
        fds_before = fds(graph.pid)
        samples: list[tuple[float, int]] = []
        totals: Counter[str] = Counter()
        print(f"{'t (s)':>7} {'RSS (KB)':>9} {'fds':>4}  round")
        while (now := time.monotonic() - start) < minutes * 60:
            samples.append((now, rss_kb(graph.pid)))
            outcome = hammer_round(graph.path)
            totals.update(outcome)
            print(f"{now:7.0f} {samples[-1][1]:9d} {fds(graph.pid):4d}  {dict(outcome)}", flush=True)
            time.sleep(max(0.0, SAMPLE_EVERY - (time.monotonic() - start - now)))
        samples.append((time.monotonic() - start, rss_kb(graph.pid)))
        time.sleep(1)  # the graph notices the last hang-ups
        settled = [(t, k) for t, k in samples if t >= 60] or samples
        print(f"RSS: {samples[0][1]} KB at start, {samples[-1][1]} KB at the end")
        print(f"RSS slope after the first minute: {slope(settled):.1f} KB/min ({len(settled)} samples)")
        print(f"connections: {dict(totals)}")
        print(f"graph descriptors: {fds_before} before, {fds(graph.pid)} after")
        with graph.connect() as conn:
            report = conn.request(Diagnose(), Report)
        for check in report.checks:
            if check.name == "control endpoint":
                print(f"doctor, control endpoint: {(*check.reasons, *check.warnings)}")


def _storm(path: Path, seconds: float, crowd: int, idle: int, results: multiprocessing.Queue) -> None:
    """Waves of ``crowd`` connections at once and ``idle`` silent ones for ``seconds``; puts (waves, outcomes)."""
    outcome: Counter[str] = Counter()

    async def wave() -> None:
        async with anyio.create_task_group() as tg:
            for _ in range(idle):
                tg.start_soon(_idle, path, 5.0, outcome)
            for _ in range(crowd):
                tg.start_soon(_one, path, GetGraph(), outcome)

    waves = 0
    start = time.monotonic()
    while time.monotonic() - start < seconds:
        anyio.run(wave)
        waves += 1
    results.put((waves, dict(outcome)))


def connections(seconds: float = 30.0, crowd: int = 2000, idle: int = 500) -> None:
    """Acceptance 2 of issue 17 (see the module docstring)."""
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if soft < crowd + idle + 100 <= hard:  # the storm's process holds every one of them at once
        resource.setrlimit(resource.RLIMIT_NOFILE, (crowd + idle + 100, hard))
    with demo_graph() as graph:
        baseline = fds(graph.pid)
        latencies: list[float] = []
        failures: list[str] = []
        cli: list[tuple[float, int]] = []
        peak_fds = baseline
        # The storm has a process of its own: in this one its 2,500 tasks would hold the GIL
        # the prober needs, and the prober's latency would be the storm's, not the graph's.
        fork = multiprocessing.get_context("fork")
        results = fork.Queue()
        storm = fork.Process(target=_storm, args=(graph.path, seconds, crowd, idle, results))
        storm.start()
        probes = 0
        while storm.is_alive() and results.empty():
            began = time.monotonic()
            try:
                with graph.connect() as conn:
                    conn.graph()
                latencies.append(time.monotonic() - began)
            except Exception as exc:
                failures.append(str(exc))
            peak_fds = max(peak_fds, fds(graph.pid))
            probes += 1
            if probes % 50 == 0:  # now and then the real command line, Python's start included
                began = time.monotonic()
                done = subprocess.run(
                    [sys.executable, "-m", "actors", "node", "list"], env=graph.env, capture_output=True, text=True
                )
                cli.append((time.monotonic() - began, done.returncode))
            time.sleep(0.1)
        waves, outcome = results.get()
        storm.join()
        time.sleep(1)  # the graph notices the last hang-ups
        lat = sorted(latencies)
        print(f"{waves} waves of {crowd} connections at once and {idle} idle ones, {seconds:.0f} s")
        print(f"outcomes: {outcome}")
        print(
            f"node list probes during the storm: {len(lat)} answered, {len(failures)} failed; latency median "
            f"{statistics.median(lat) * 1000:.1f} ms, p99 {lat[int(len(lat) * 0.99)] * 1000:.1f} ms, "
            f"max {lat[-1] * 1000:.1f} ms, over 1 s: {sum(t > 1 for t in lat)}"
        )
        if failures:
            print(f"  failures: {Counter(failures).most_common(3)}")
        print(
            f"`actors node list` processes during the storm (with Python's start): "
            f"{[f'{t:.2f} s (exit {c})' for t, c in cli]}"
        )
        print(f"graph descriptors: baseline {baseline}, peak {peak_fds}, after {fds(graph.pid)}")
        print(f"graph still running: {graph.proc.poll() is None}")


def stalled(seconds: float = 60.0, readers: int = 5) -> None:
    """Acceptance 3 of issue 17 (see the module docstring)."""
    for with_readers in (False, True):
        with demo_graph() as graph:
            time.sleep(10)  # past start-up's allocations
            procs = []
            if with_readers:
                for _ in range(readers):
                    # stdout is a pipe nobody reads: once its 64 KB fill, the reader stalls.
                    procs.append(
                        subprocess.Popen(
                            [sys.executable, "-m", "actors", "topic", "echo", "/scan"],
                            env=graph.env,
                            stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL,
                        )
                    )
                time.sleep(5)  # connected and stalled
            before = rss_kb(graph.pid)
            time.sleep(seconds)
            after = rss_kb(graph.pid)
            for proc in procs:
                proc.kill()
                proc.wait()
            what = f"{readers} stalled `topic echo /scan` readers" if with_readers else "no reader (baseline)"
            print(f"{what}: RSS {before} KB -> {after} KB over {seconds:.0f} s: {after - before:+d} KB")


# A plain Zenoh peer that declares tokens of fresh names and takes them back, round after round.
_CHURN = """
import json, sys, time
import zenoh
port, tokens, name_sets = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])  # name_sets 0: fresh every round
config = zenoh.Config()
config.insert_json5("connect/endpoints", json.dumps([f"tcp/127.0.0.1:{port}"]))
config.insert_json5("scouting/multicast/enabled", "false")
session = zenoh.open(config)
zid, round_ = str(session.info.zid()), 0
while True:
    names = round_ % name_sets if name_sets else round_
    declared = [
        session.liveliness().declare_token(f"@ros2_lv/0/{zid}/0/{i}/NN/%/%/churn_{names}_{i}") for i in range(tokens)
    ]
    time.sleep(5)
    for token in declared:
        token.undeclare()
    round_ += 1
    time.sleep(5)
"""

# The baseline: a bare Zenoh peer that hears every liveliness token of the domain, as the transport does.
_BARE = """
import json, sys, threading
import zenoh
config = zenoh.Config()
where = "listen" if sys.argv[2:] == ["--listen"] else "connect"
config.insert_json5(f"{where}/endpoints", json.dumps([f"tcp/127.0.0.1:{sys.argv[1]}"]))
config.insert_json5("scouting/multicast/enabled", "false")
session = zenoh.open(config)
heard = zenoh.handlers.Callback(lambda sample: None)
watch = session.liveliness().declare_subscriber("@ros2_lv/**", heard, history=True)
threading.Event().wait()
"""

# A Foxglove viewer that subscribes to every channel and reads for a while, then leaves; again and again.
_VIEWER = """
import asyncio, json, sys
import websockets

async def visit(url):
    async with websockets.connect(url, subprotocols=["foxglove.sdk.v1", "foxglove.websocket.v1"], max_size=None) as ws:
        ids, loop = 0, asyncio.get_running_loop()
        end = loop.time() + 20
        while loop.time() < end:
            try:
                frame = await asyncio.wait_for(ws.recv(), timeout=1)
            except asyncio.TimeoutError:
                continue
            if isinstance(frame, str):
                message = json.loads(frame)
                if message.get("op") == "advertise":
                    subs = [{"id": (ids := ids + 1), "channelId": c["id"]} for c in message["channels"]]
                    await ws.send(json.dumps({"op": "subscribe", "subscriptions": subs}))

async def main(url):
    while True:
        try:
            await visit(url)
        except Exception as exc:
            print(f"viewer: {exc!r}", file=sys.stderr, flush=True)
        await asyncio.sleep(2)

asyncio.run(main(sys.argv[1]))
"""


def _free_port() -> int:
    import socket

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


WITHOUT = ("churn", "recorder", "viewer", "cli", "zenoh")
"""What ``--round2 --without`` may leave out."""


def round2(minutes: float, fresh_names: bool = False, without: frozenset[str] = frozenset()) -> None:
    """Issue 34's soak: TurtleBot with recorder, live view, Zenoh, a churning peer, a viewer, CLI loops."""
    with tempfile.TemporaryDirectory() as tmp:
        runtime_dir = Path(tmp) / "run"
        runtime_dir.mkdir(mode=0o700)
        zenoh_port, view_port = _free_port(), _free_port()
        graph_file = Path(tmp) / "soak_turtlebot.toml"
        transport = (
            f'\n[transport]\nkind = "zenoh"\nconnect = ["tcp/127.0.0.1:{zenoh_port}"]\n'
            f'listen = ["tcp/127.0.0.1:{zenoh_port}"]\n'
        )
        graph_file.write_text((ROOT / "graphs/turtlebot.toml").read_text() + ("" if "zenoh" in without else transport))
        bag = Path(tmp) / "soak.mcap"
        options = [] if "recorder" in without else ["--record", str(bag)]
        options += [] if "viewer" in without else ["--foxglove", str(view_port)]
        graph = GraphProcess(graph_file, runtime_dir, *options)
        name_sets = "0" if fresh_names else "3"
        helpers = []
        if "zenoh" not in without and "churn" not in without:
            helpers.append(
                subprocess.Popen([sys.executable, "-c", _CHURN, str(zenoh_port), "500", name_sets], cwd=ROOT)
            )
        # Without the transport the bare peer listens alone: the floor of a Zenoh session that hears nothing.
        bare_config = [str(zenoh_port)] if "zenoh" not in without else [str(_free_port()), "--listen"]
        helpers.append(bare := subprocess.Popen([sys.executable, "-c", _BARE, *bare_config], cwd=ROOT))
        if "viewer" not in without:
            helpers.append(subprocess.Popen([sys.executable, "-c", _VIEWER, f"ws://127.0.0.1:{view_port}"], cwd=ROOT))
        try:
            start = time.monotonic()
            fds_before = fds(graph.pid)
            samples: list[tuple[float, int]] = []
            baseline: list[tuple[float, int]] = []
            descriptors: list[int] = []
            print(f"{'t (s)':>7} {'RSS (KB)':>9} {'fds':>4} {'bare (KB)':>9}  round")
            while (now := time.monotonic() - start) < minutes * 60:
                samples.append((now, rss_kb(graph.pid)))
                baseline.append((now, rss_kb(bare.pid)))
                descriptors.append(fds(graph.pid))
                outcome: Counter[str] = Counter()
                if "cli" not in without:
                    outcome = hammer_round(graph.path, connections=50)
                    with graph.connect() as conn:
                        conn.graph()
                    subprocess.run(
                        [sys.executable, "-m", "actors", "topic", "echo", "/odom", "--once", "--graph", graph.name],
                        cwd=ROOT,
                        env=graph.env,
                        capture_output=True,
                        timeout=60,
                    )
                print(
                    f"{now:7.0f} {samples[-1][1]:9d} {descriptors[-1]:4d} {baseline[-1][1]:9d}  {dict(outcome)}",
                    flush=True,
                )
                time.sleep(max(0.0, SAMPLE_EVERY - (time.monotonic() - start - now)))
            window = 20 if minutes >= 23 else max(minutes - 3, 1)
            last = [(t, k) for t, k in samples if t >= samples[-1][0] - window * 60] or samples
            bare_last = [(t, k) for t, k in baseline if t >= last[0][0]]
            print(f"RSS: {samples[0][1]} KB at start, {samples[-1][1]} KB at the end")
            print(
                f"RSS slope over the last {(last[-1][0] - last[0][0]) / 60:.0f} min: {slope(last):.1f} KB/min "
                f"(the bare Zenoh peer beside it: {slope(bare_last):.1f} KB/min, {baseline[-1][1]} KB at the end)"
            )
            print(
                f"graph descriptors: {fds_before} at start, {min(descriptors)} to {max(descriptors)} while it ran, "
                f"{fds(graph.pid)} at the end"
            )
        finally:
            for helper in helpers:
                helper.terminate()
                helper.wait(timeout=30)
            code = graph.stop()
            size = f"{bag.stat().st_size} B" if bag.exists() else "none"
            print(f"graph exit code {code}, tracebacks in its log: {graph.tracebacks()}, bag {size}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.soak", description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="how long the soak runs (default 10)")
    parser.add_argument("--connections", action="store_true", help="acceptance 2: 2,000 + 500 idle connections")
    parser.add_argument("--stalled", action="store_true", help="acceptance 3: five stalled readers for 60 s")
    parser.add_argument(
        "--round2",
        action="store_true",
        help="issue 34: TurtleBot, recorder, live view and viewer, a Zenoh peer churning tokens, CLI loops",
    )
    parser.add_argument(
        "--fresh-names", action="store_true", help="with --round2: new token names every round (upstream keeps each)"
    )
    parser.add_argument(
        "--without",
        nargs="+",
        choices=WITHOUT,
        default=[],
        metavar="PART",
        help=f"with --round2: leave parts out ({', '.join(WITHOUT)})",
    )
    args = parser.parse_args(argv)
    if not Path("/proc/self/status").exists():
        print("bench.soak reads /proc: Linux only", file=sys.stderr)
        return 2
    if args.connections:
        connections()
    elif args.stalled:
        stalled()
    elif args.round2:
        round2(args.minutes, args.fresh_names, frozenset(args.without))
    else:
        soak(args.minutes)
    return 0


if __name__ == "__main__":
    sys.exit(main())
