"""Reading and playing bags: bag info, bag play into a graph, damaged and foreign bags, recorded expectations."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import anyio
import pytest
from conftest import ROOT, python_env, read_bag

from actors import Node, Runtime, VirtualTimeLoop, codec
from actors.errors import BagError
from actors.ops.control import ControlEndpoint
from actors.recording import Recorder
from actors.recording.expect import BagExpectation, differences
from actors.recording.player import play
from actors.recording.reader import Bag
from interfaces.geometry_msgs.msg import Twist
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import LaserScan

pytest_plugins = ["pytester"]

mcap_reader = pytest.importorskip("mcap.reader")


async def _turtlebot(path: Path, seconds: float) -> None:
    from nodes.constant_control import ConstantControl
    from world.robot import TurtleBot
    from world.sim import World

    async with Runtime(name="bag", attach=[Recorder(path, chunk_size=8192)]) as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        rt.spawn(ConstantControl, params={"v": 0.2})
        await rt.wait(seconds)


@pytest.fixture(scope="module")
def bag(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """10 s of the TurtleBot graph, recorded on a virtual clock from 0."""
    path = tmp_path_factory.mktemp("bag") / "run.mcap"
    anyio.run(_turtlebot, path, 10, backend_options={"loop_factory": VirtualTimeLoop})
    return path


def _odoms(path: Path) -> list[tuple[int, bytes]]:
    with open(path, "rb") as f:
        return [(m.log_time, m.data) for _, _, m in mcap_reader.make_reader(f).iter_messages(topics=["/odom"])]


def actors_cli(*args: str) -> subprocess.CompletedProcess[str]:
    # ros2 bag info prints dates in local time: UTC here, so that they read the same everywhere.
    return subprocess.run(
        [sys.executable, "-m", "actors", *args],
        cwd=ROOT,
        env={**python_env(), "TZ": "UTC"},
        capture_output=True,
        text=True,
        timeout=60,
    )


# --------------------------------------------------------------------------- bag info


@pytest.mark.slow
def test_bag_info_prints_as_ros2_bag_info(bag):
    done = actors_cli("bag", "info", str(bag))
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    size, whole = bag.stat().st_size, Bag(bag)
    assert whole.start == 0 and 9_950_000_000 <= whole.end <= 10_000_000_000
    end = f"{whole.end // 10**9}.{whole.end % 10**9:09d}"
    assert lines[:8] == [
        "",
        f"Files:             {bag}",
        f"Bag size:          {size / 1024:.1f} KiB",
        "Storage id:        mcap",
        "ROS Distro:        kilted",
        f"Duration:          {end}s",
        "Start:             Jan  1 1970 00:00:00.000000000 (0.000000000)",
        f"End:               Jan  1 1970 00:00:{end.zfill(12)} ({end})",
    ]
    counts = {t.name: t.count for t in Bag(bag).topics}
    assert counts["/odom"] in (199, 200) and counts["/scan"] in (99, 100)  # 20 Hz and 10 Hz, 10 s
    topic_lines = [
        f"Topic: {name} | Type: {codec.ros_name(codec.get_type(t))} | Count: {counts[name]} | Serialization Format: cdr"
        for name, t in (("/cmd_vel", "geometry_msgs/msg/Twist"), ("/odom", "nav_msgs/msg/Odometry"))
    ]
    assert f"Topic information: {topic_lines[0]}" in lines and f"{' ' * 19}{topic_lines[1]}" in lines
    assert lines[-2:] == ["Service:           0", "Service information: "]


@pytest.mark.slow
def test_bag_info_reads_a_rosbag2_bag_directory(tmp_path):
    async def record() -> None:
        from nodes.talker import MinimalPublisher

        async with Runtime(attach=[Recorder(tmp_path / "talk")]) as rt:
            rt.spawn(MinimalPublisher)
            await rt.wait(2.2)

    anyio.run(record, backend_options={"loop_factory": VirtualTimeLoop})
    assert sorted(p.name for p in (tmp_path / "talk").iterdir()) == ["metadata.yaml", "talk_0.mcap"]
    done = actors_cli("bag", "info", str(tmp_path / "talk"))
    assert done.returncode == 0 and "Files:             talk_0.mcap" in done.stdout
    assert "Topic: /topic | Type: std_msgs/msg/String | Count: 4 |" in done.stdout
    from rosbags.rosbag2 import Reader  # rosbags reads the directory through its metadata.yaml

    with Reader(tmp_path / "talk") as reader:
        assert reader.message_count == 4 + 1 and {c.topic for c in reader.connections} >= {"/topic"}


# --------------------------------------------------------------------------- damaged bags


@pytest.mark.slow
def test_a_truncated_bag_is_named_with_its_byte_and_recovered_when_asked(bag, tmp_path):
    data = bag.read_bytes()
    cut = tmp_path / "cut.mcap"
    cut.write_bytes(data[: len(data) // 2])
    done = actors_cli("bag", "info", str(cut))
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr == (
        f"actors: {cut}: byte {len(data) // 2}: the file ends without a footer: it is truncated "
        "(its recording was stopped by force?); --recover reads the whole chunks before it\n"
    )
    with pytest.raises(BagError, match=r"the file ends without a footer"):
        Bag(cut)
    recovered = Bag(cut, recover=True)
    assert 0 < recovered.message_count < Bag(bag).message_count and recovered.problems
    done = actors_cli("bag", "info", str(cut), "--recover")
    assert done.returncode == 0 and "warning:" in done.stderr and "Topic: /odom" in done.stdout


@pytest.mark.slow
def test_a_corrupt_chunk_is_named_and_play_refuses_it(bag, tmp_path):
    data = bytearray(bag.read_bytes())
    with open(bag, "rb") as f:
        first = mcap_reader.make_reader(f).get_summary().chunk_indexes[0]
    spot = first.chunk_start_offset + first.chunk_length // 2
    data[spot] ^= 0xFF
    bad = tmp_path / "bad.mcap"
    bad.write_bytes(bytes(data))
    with pytest.raises(BagError) as caught:
        list(Bag(bad).messages())
    assert str(caught.value).startswith(f"{bad}: byte {first.chunk_start_offset}: ")
    done = actors_cli("bag", "play", str(bad), "--graph", "nothing_runs_here")
    assert done.returncode == 2 and done.stderr.startswith(f"actors: {bad}: byte {first.chunk_start_offset}: ")


@pytest.mark.slow
def test_not_an_mcap_file(tmp_path):
    junk = tmp_path / "junk.mcap"
    junk.write_text("hello")
    done = actors_cli("bag", "info", str(junk))
    assert (
        done.returncode == 2
        and done.stderr == f"actors: {junk}: byte 0: not an MCAP file (no MCAP magic at the start)\n"
    )
    assert actors_cli("bag", "info", str(tmp_path / "missing.mcap")).returncode == 2


# --------------------------------------------------------------------------- playing


class OdomListener(Node):
    """Keeps every Odometry it hears, with the runtime time it heard it."""

    def __init__(self) -> None:
        super().__init__("odom_listener")
        self.heard: list[tuple[int, Odometry]] = []
        self.create_subscription(
            Odometry, "odom", lambda m: self.heard.append((self.get_clock().now().nanoseconds, m)), 1000
        )


@pytest.mark.virtual_time
async def test_play_publishes_the_messages_in_order_at_their_offsets(bag):
    async with Runtime() as rt:
        listener = rt.spawn(OdomListener)
        await anyio.sleep(5)
        played = await play(rt, Bag(bag), topics=["/odom"])
        await anyio.sleep(0.01)  # the listener's turn for the last one
    recorded = _odoms(bag)
    assert played == len(recorded) == len(listener.heard) > 190
    assert [codec.encode_cdr(m) for _, m in listener.heard] == [data for _, data in recorded]
    # At their recorded offsets on the virtual clock, from when playing began (5 s).
    assert [t for t, _ in listener.heard] == [5_000_000_000 + t - recorded[0][0] for t, _ in recorded]


@pytest.mark.virtual_time
@pytest.mark.slow
async def test_actors_bag_play_into_a_running_graph(bag):
    # A real command line against a graph on virtual time: the graph plays the bag on its clock,
    # so 10 s of bag pass in the graph's virtual time, whatever the wall clock does meanwhile.
    async with Runtime(name="bag_play_target", attach=[ControlEndpoint()]) as rt:
        listener = rt.spawn(OdomListener)
        scans = rt.spawn(ScanCounter)
        start = rt.clock.now_ns()
        done = await anyio.run_process(
            [
                sys.executable,
                "-m",
                "actors",
                "bag",
                "play",
                str(bag),
                "--graph",
                "bag_play_target",
                "--remap",
                "/scan:=/scan_played",
            ],
            cwd=ROOT,
            env=python_env(),
            check=False,
        )
        assert done.returncode == 0, done.stderr.decode()
        elapsed = rt.clock.now_ns() - start
        await anyio.sleep(0.01)  # the listeners' turn for the last ones
    recorded = _odoms(bag)
    assert [codec.encode_cdr(m) for _, m in listener.heard] == [data for _, data in recorded]
    assert scans.count == Bag(bag).topics[[t.name for t in Bag(bag).topics].index("/scan")].count  # as /scan_played
    assert recorded[-1][0] - recorded[0][0] <= elapsed
    assert done.stderr.decode() == f"played {Bag(bag).message_count} message(s) from {bag}\n"


class ScanCounter(Node):
    """Counts the LaserScans on ``scan_played``."""

    def __init__(self) -> None:
        super().__init__("scan_counter")
        self.count = 0
        self.create_subscription(LaserScan, "scan_played", self.heard, 100)

    def heard(self, msg: LaserScan) -> None:
        self.count += 1


@pytest.mark.slow
def test_unknown_types_without_a_schema_are_listed_and_skipped(tmp_path):
    from actors.recording.bag_writer import BagWriter

    path = tmp_path / "foreign.mcap"
    writer = BagWriter(path)
    odd = writer.add_topic("/odd", "no_such_msgs/msg/Thing", definition="", type_hash="")
    twist = writer.add_topic(
        "/cmd_vel",
        "geometry_msgs/msg/Twist",
        definition=codec.definition_text(Twist),
        type_hash=codec.type_hash(Twist),
    )
    writer.write(odd, 1, b"\x00\x01\x00\x00\x07\x00\x00\x00")
    writer.write(twist, 2, codec.encode_cdr(Twist()))
    writer.close()
    from actors.recording.player import plan

    playable, skipped = plan(Bag(path))
    assert list(playable) == ["/cmd_vel"]
    assert skipped == ["skipping /odd: unknown type no_such_msgs/msg/Thing (1 message(s))"]
    done = actors_cli("bag", "play", str(path), "--graph", "nothing_runs_here")
    assert done.stderr.splitlines()[0] == "skipping /odd: unknown type no_such_msgs/msg/Thing (1 message(s))"
    assert done.returncode == 2  # and then: no graph named so


# --------------------------------------------------------------------------- recorded expectations


class Follower(Node):
    """A controller under test: turns toward where odometry says it is heading, at a gain."""

    def __init__(self, gain: float = 1.0) -> None:
        super().__init__("follower")
        self.gain = gain
        self.pub = self.create_publisher(Twist, "cmd_vel_out", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)

    def on_odom(self, odom: Odometry) -> None:
        cmd = Twist()
        cmd.linear.x = 0.1 + self.gain * odom.pose.pose.position.x
        self.pub.publish(cmd)


async def _controller_run(inputs: Path, out: Path, gain: float) -> None:
    async with Runtime(attach=[Recorder(out, topics=["/cmd_vel_out"])]) as rt:
        rt.spawn(Follower, gain)
        await play(rt, Bag(inputs), topics=["/odom"])
        await anyio.sleep(0.1)


def test_record_once_then_assert_forever(bag, tmp_path):
    expected = tmp_path / "expected" / "cmd_vel.mcap"
    runs = {}
    for name, gain in (("first", 1.0), ("again", 1.0), ("changed", 1.5)):
        runs[name] = tmp_path / f"{name}.mcap"
        anyio.run(_controller_run, bag, runs[name], gain, backend_options={"loop_factory": VirtualTimeLoop})
    with pytest.raises(AssertionError, match="run pytest --record-bags once"):
        BagExpectation().check(runs["first"], expected)
    BagExpectation(update=True).check(runs["first"], expected)
    BagExpectation().check(runs["again"], expected)  # the same inputs and code: the same bag
    with pytest.raises(AssertionError) as caught:
        BagExpectation().check(runs["changed"], expected)
    first = differences(runs["changed"], expected)[0]
    got, _, expected_text = first.partition("; expected ")
    assert got.startswith("message ") and ": got /cmd_vel_out at " in got and "'linear': {'x': " in got
    assert expected_text.startswith("/cmd_vel_out at ") and got.split(" at ")[1] != expected_text.split(" at ")[1]
    assert first in str(caught.value)


def test_the_bag_expectation_fixture(pytester):
    pytester.makeini("[pytest]\nasyncio_default_fixture_loop_scope = function\n")  # pytest-asyncio warns when unset
    pytester.makepyfile(
        """
        def test_it(bag_expectation, tmp_path):
            assert bag_expectation.update is True
        """
    )
    assert pytester.runpytest("-p", "no:cacheprovider", "--record-bags").ret == 0


# --------------------------------------------------------------------------- bag record


class Counting(Node):
    """Publishes 0, 1, 2... on ``count`` at 200 Hz."""

    def __init__(self) -> None:
        super().__init__("counting")
        from interfaces.std_msgs.msg import Int64

        self.msg_type = Int64
        self.pub = self.create_publisher(Int64, "count", 10)
        self.n = 0
        self.create_timer(0.005, self.tick)

    def tick(self) -> None:
        self.pub.publish(self.msg_type(data=self.n))
        self.n += 1


@pytest.mark.slow
async def test_actors_bag_record_against_a_running_graph(tmp_path):
    import signal

    out = tmp_path / "count.mcap"
    async with Runtime(name="bag_record_source", attach=[ControlEndpoint()]) as rt:
        counting = rt.spawn(Counting)
        async with await anyio.open_process(
            [sys.executable, "-m", "actors", "bag", "record", "-o", str(out), "/count", "--graph", "bag_record_source"],
            cwd=ROOT,
            env=python_env(),
        ) as process:
            try:
                with anyio.fail_after(20):
                    while not counting.pub.get_subscription_count():  # the recorder's subscription
                        await anyio.sleep(0.01)
                    first = counting.n
                    while counting.n < first + 40:
                        await anyio.sleep(0.01)
                process.send_signal(signal.SIGINT)
                with anyio.fail_after(20):
                    assert await process.wait() == 0
            finally:
                if process.returncode is None:  # failed: leaving the block would wait for it forever
                    process.kill()
    reader = read_bag(out)
    values = [codec.decode_cdr(m.data, "std_msgs/msg/Int64").data for _, _, m in reader.iter_messages()]
    assert reader.get_summary().statistics.message_count == len(values)
    assert len(values) >= 30 and values == list(range(values[0], values[0] + len(values)))
