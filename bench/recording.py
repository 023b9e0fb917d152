"""What recording costs: one-way throughput with a recorder on, bag writing speed, and bag play on virtual time.

``python -m bench.recording [--quick]`` (scenario l of ``python -m bench``).

- one-way: talker→listener deliveries/s (``bench.throughput``'s measurement)
  with a :class:`~actors.recording.Recorder` attached, beside the same run
  without one.  The recorder writes in a worker thread; its buffer
  (``max_pending``) is a tenth of the messages, so the publisher outruns it
  and is held up while it is written; the row says how many were dropped
  (none, unless the recorder is made lossy).
- burst: a million messages (200k with ``--quick``) published as fast as
  the loop goes into a recorder with its default buffer, from the first
  publish until the bag is closed; messages recorded per second, and how
  many the bag is missing (it must be none).
- writing: LaserScans (360 beams, 1.5 KB of CDR each) published in bursts
  into a recorded graph whose buffer holds a tenth of them (every burst in
  this scenario is larger than the buffer it goes into), from the first
  publish until the bag is closed;
  MB/s of messages recorded (CDR bytes: the same scan over and over
  compresses to almost nothing, so the file's own size would say little).
  Baseline: the ``mcap`` library's own writer adding the same payloads,
  already encoded, with the same zstd chunking.
- play: the acceptance's 30 s TurtleBot bag played into a graph with a
  listener on the virtual clock; wall-clock seconds.
"""

from __future__ import annotations

import asyncio
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

import anyio

from actors import Node, QoSProfile, Runtime, VirtualTimeLoop, codec
from actors.recording import Recorder
from actors.recording.player import play
from actors.recording.reader import Bag
from bench.harness import Result, repeat, standalone
from bench.throughput import actors_rate
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import String

__all__ = ["run", "write_rate", "library_rate", "play_seconds"]

BURST = 100  # scans published between yields to the loop
BEAMS = 360


class _Scans(Node):
    def __init__(self) -> None:
        super().__init__("scanner")
        self.pub = self.create_publisher(LaserScan, "scan", QoSProfile(depth=BURST))


class _Burst(Node):
    def __init__(self) -> None:
        super().__init__("burster")
        self.pub = self.create_publisher(String, "burst", QoSProfile(depth=BURST))


def _scan() -> LaserScan:
    return LaserScan(
        angle_min=-3.14,
        angle_max=3.14,
        angle_increment=0.0175,
        range_min=0.1,
        range_max=3.5,
        ranges=[1.0 + i / BEAMS for i in range(BEAMS)],
        intensities=[],
    )


def _recorded_seconds(recorder: Recorder, node: type[_Scans | _Burst], msg: Any, n: int) -> float:
    """Seconds from the first of ``n`` publishes of ``msg`` (``BURST`` between yields) until the bag is closed."""

    async def main() -> float:
        async with Runtime(attach=[recorder]) as rt:
            publish = rt.spawn(node).pub.publish
            await asyncio.sleep(0)
            start = time.perf_counter()
            for _ in range(n // BURST):
                for _ in range(BURST):
                    publish(msg)
                await asyncio.sleep(0)
        return time.perf_counter() - start  # the runtime has closed the bag

    return asyncio.run(main())


def write_rate(n: int, folder: Path) -> tuple[float, int]:
    """MB/s of CDR recorded for ``n`` LaserScans (buffer: ``n // 10``), first publish to closed bag; and drops."""
    path = folder / f"scans{time.perf_counter_ns()}.mcap"
    recorder = Recorder(path, max_pending=n // 10)
    msg = _scan()
    seconds = _recorded_seconds(recorder, _Scans, msg, n)
    path.unlink()
    return n * len(codec.encode_cdr(msg)) / seconds / 1e6, recorder.dropped


def burst_rate(n: int, folder: Path) -> tuple[float, int]:
    """Messages/s recorded for a burst of ``n`` Strings (first publish to closed bag); and how many the bag misses."""
    path = folder / f"burst{time.perf_counter_ns()}.mcap"
    seconds = _recorded_seconds(Recorder(path, topics=["/burst"]), _Burst, String(data="Hello World"), n)
    recorded = sum(t.count for t in Bag(path).topics if t.name == "/burst")
    path.unlink()
    return n / seconds, n - recorded


def library_rate(n: int, folder: Path) -> float:
    """MB/s of CDR the ``mcap`` library's Writer adds for ``n`` encoded LaserScans (zstd, 1 MiB chunks)."""
    from mcap.writer import CompressionType, Writer

    path = folder / f"library{time.perf_counter_ns()}.mcap"
    data = codec.encode_cdr(_scan())
    start = time.perf_counter()
    with open(path, "wb") as f:
        writer = Writer(f, chunk_size=1 << 20, compression=CompressionType.ZSTD)
        writer.start(profile="ros2", library="bench")
        schema = writer.register_schema(
            "sensor_msgs/msg/LaserScan", "ros2msg", codec.definition_text(LaserScan).encode()
        )
        channel = writer.register_channel("/scan", "cdr", schema)
        for i in range(n):
            writer.add_message(channel, log_time=i, data=data, publish_time=i)
        writer.finish()
    seconds = time.perf_counter() - start
    path.unlink()
    return n * len(data) / seconds / 1e6


async def _turtlebot(path: Path, seconds: float) -> None:
    from nodes.constant_control import ConstantControl
    from world.robot import TurtleBot
    from world.sim import World

    async with Runtime(attach=[Recorder(path)]) as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.2})
        await rt.wait(seconds)


class _Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.count = 0
        self.create_subscription(Odometry, "odom", self.heard, 1000)

    def heard(self, msg: Any) -> None:
        self.count += 1


def play_seconds(bag: Path) -> float:
    """Wall-clock seconds to play ``bag`` into a graph with an /odom listener, on the virtual clock."""

    async def main() -> float:
        async with Runtime() as rt:
            listener = rt.spawn(_Listener)
            start = time.perf_counter()
            await play(rt, Bag(bag))
            seconds = time.perf_counter() - start
            await anyio.sleep(0.01)
        assert listener.count > 0
        return seconds

    return anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop})


def run(quick: bool = False) -> list[Result]:
    """The recording rows, each beside its baseline measured in the same run."""
    n = 10_000 if quick else 100_000
    scans = 2_000 if quick else 20_000
    reps = 5
    folder = Path(tempfile.mkdtemp(prefix="bench-recording-"))
    try:
        results = _one_way(n, reps, folder)
        bursts = repeat(lambda: burst_rate(200_000 if quick else 1_000_000, folder), 3, warmup=False)
        results.append(
            Result(
                "l. recording: burst",
                f"{200_000 if quick else 1_000_000:,} messages, default buffer",
                "messages/s recorded",
                [rate for rate, _ in bursts],
                note=f"missing from the bag per run: {[lost for _, lost in bursts]}",
            )
        )
        written = repeat(lambda: write_rate(scans, folder), reps)
        dropped = sorted(d for _, d in written)[len(written) // 2]
        results.append(
            Result(
                "l. recording: writing",
                "LaserScan bag",
                "MB/s of CDR",
                [mb for mb, _ in written],
                baselines={"library": "mcap library Writer"},
                note=f"{scans} scans of {len(codec.encode_cdr(_scan()))} B; median {dropped} dropped",
            )
        )
        results.append(
            Result(
                "l. recording: writing",
                "mcap library Writer",
                "MB/s of CDR",
                repeat(lambda: library_rate(scans, folder), reps),
                note="payloads encoded beforehand",
            )
        )
        bag = folder / "turtlebot.mcap"
        anyio.run(_turtlebot, bag, 30.0, backend_options={"loop_factory": VirtualTimeLoop})
        count, size = Bag(bag).message_count, bag.stat().st_size
        results.append(
            Result(
                "l. recording: play",
                "30 s TurtleBot bag, virtual clock",
                "s",
                repeat(lambda: play_seconds(bag), reps),
                higher_better=False,
                note=f"{count} messages, {size / 1024:.0f} KiB",
            )
        )
        return results
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _one_way(n: int, reps: int, folder: Path) -> list[Result]:
    drops: list[int] = []

    def recorded() -> float:
        recorder = Recorder(folder / f"one_way{time.perf_counter_ns()}.mcap", max_pending=n // 10)
        rate = actors_rate(n, 1, attach=[recorder])
        drops.append(recorder.dropped)
        return rate

    with_recorder = repeat(recorded, reps)
    del drops[0]  # the warm-up's
    return [
        Result(
            "l. recording: one-way",
            "recording on",
            "deliveries/s",
            with_recorder,
            baselines={"off": "recording off"},
            note=f"dropped per run: {drops}",
        ),
        Result("l. recording: one-way", "recording off", "deliveries/s", repeat(lambda: actors_rate(n, 1), reps)),
    ]


if __name__ == "__main__":
    standalone(run, __doc__, "fewer messages")
