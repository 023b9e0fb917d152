"""The recorder: what it writes is a ROS 2 bag that rosbags, the mcap library and rclpy read back."""

from __future__ import annotations

import errno
import gc
import io
import subprocess
import sys
import weakref
from pathlib import Path

import anyio
import anyio.lowlevel
import pytest
from conftest import ROOT, python_env, read_bag

from actors import Node, Runtime, VirtualTimeLoop, codec
from actors.cli.bag import format_info
from actors.ops.doctor import diagnose
from actors.recording import Recorder
from actors.recording.mcap_writer import McapWriter
from actors.recording.reader import Bag
from actors.recording.tap import Tap
from actors.ros.topics import PublisherState
from interfaces.std_msgs.msg import String

mcap_reader = pytest.importorskip("mcap.reader")
pytest.importorskip("rosbags")


@pytest.fixture(scope="module")
def turtlebot_bag(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The acceptance command's bag: 30 s of the TurtleBot graph on the virtual clock."""
    path = tmp_path_factory.mktemp("bag") / "run.mcap"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "actors.run",
            "graphs/turtlebot.toml",
            "--clock",
            "virtual",
            "--duration",
            "30",
            "--record",
            str(path),
        ],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    return path


@pytest.mark.slow
def test_rosbags_deserializes_every_message(turtlebot_bag):
    from rosbags.highlevel import AnyReader
    from rosbags.typesys import Stores, get_typestore

    # An empty type store: rosbags learns every type from the bag's own ros2msg schemas.
    with AnyReader([turtlebot_bag], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        counts: dict[str, int] = {}
        for connection, _, raw in reader.messages():
            reader.deserialize(raw, connection.msgtype)
            counts[connection.topic] = counts.get(connection.topic, 0) + 1
        odom = next(c for c in reader.connections if c.topic == "/odom")
        last_odom = None
        for connection, _, raw in reader.messages(connections=[odom]):
            last_odom = reader.deserialize(raw, connection.msgtype)
    assert counts["/odom"] == 600 and counts["/scan"] == 300 and counts["/cmd_vel"] > 0
    assert last_odom is not None and last_odom.header.frame_id == "odom" and last_odom.header.stamp.sec == 30


def test_mcap_library_validates_summary_statistics_and_schemas(turtlebot_bag):
    from mcap.stream_reader import StreamReader

    with open(turtlebot_bag, "rb") as f:
        reader = mcap_reader.make_reader(f)
        header, summary = reader.get_header(), reader.get_summary()
        messages = list(reader.iter_messages())
    assert header.profile == "ros2"
    stats = summary.statistics
    assert stats.message_count == len(messages) == sum(stats.channel_message_counts.values())
    assert stats.channel_count == len(summary.channels) and stats.schema_count == len(summary.schemas)
    assert stats.chunk_count == len(summary.chunk_indexes) > 0
    assert {c.compression for c in summary.chunk_indexes} == {"zstd"}
    assert stats.message_start_time == min(m.log_time for _, _, m in messages)
    assert stats.message_end_time == max(m.log_time for _, _, m in messages) == 30_000_000_000
    for schema in summary.schemas.values():
        assert schema.encoding == "ros2msg"
        assert schema.data.decode() == codec.definition_text(schema.name)
    for channel in summary.channels.values():
        schema = summary.schemas[channel.schema_id]
        assert channel.message_encoding == "cdr"
        assert channel.metadata["topic_type_hash"] == codec.type_hash(schema.name)
        qos = channel.metadata["offered_qos_profiles"]  # "" for a topic nobody publishes (/kill)
        assert qos.startswith("- history: keep_last\n  depth: ") or (channel.topic == "/kill" and qos == "")
    # Every record again, from the start, with every chunk's CRC checked.
    with open(turtlebot_bag, "rb") as f:
        assert sum(1 for r in StreamReader(f, validate_crcs=True).records if type(r).__name__ == "Message") == len(
            messages
        )


def test_odom_payloads_decode_with_rclpy(turtlebot_bag):
    pytest.importorskip("rclpy")
    nav_msgs = pytest.importorskip("nav_msgs.msg")
    from rclpy.serialization import deserialize_message

    with open(turtlebot_bag, "rb") as f:
        odoms = [m for _, c, m in mcap_reader.make_reader(f).iter_messages(topics=["/odom"])]
    assert len(odoms) == 600
    for record in odoms:
        theirs = deserialize_message(record.data, nav_msgs.Odometry)
        ours = codec.decode_cdr(record.data, "nav_msgs/msg/Odometry")
        assert theirs.header.stamp.sec * 10**9 + theirs.header.stamp.nanosec == record.log_time
        assert (theirs.pose.pose.position.x, theirs.twist.twist.linear.x) == (
            ours.pose.pose.position.x,
            ours.twist.twist.linear.x,
        )
        assert list(theirs.pose.covariance) == list(ours.pose.covariance)


async def _record_turtlebot(path: Path, seconds: float) -> None:
    from nodes.constant_control import ConstantControl
    from world.robot import TurtleBot
    from world.sim import World

    async with Runtime(name="twice", attach=[Recorder(path)]) as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        rt.spawn(ConstantControl, params={"v": 0.2})
        await rt.wait(seconds)


def test_the_same_virtual_graph_twice_gives_the_same_bytes(tmp_path):
    for run in ("a", "b"):  # each on a virtual clock of its own, from 0
        (tmp_path / run).mkdir()
        anyio.run(_record_turtlebot, tmp_path / run / "run.mcap", 8, backend_options={"loop_factory": VirtualTimeLoop})
    first, second = (tmp_path / "a" / "run.mcap").read_bytes(), (tmp_path / "b" / "run.mcap").read_bytes()
    with open(tmp_path / "a" / "run.mcap", "rb") as f:
        stream = [(c.topic, m.log_time, m.data) for _, c, m in mcap_reader.make_reader(f).iter_messages()]
    assert len(stream) > 400 and first == second


class Burst(Node):
    """Publishes ``n`` messages at once, 1 s after it starts, then goes quiet."""

    def __init__(self, n: int = 50) -> None:
        super().__init__("burst")
        self.pub = self.create_publisher(String, "burst", 10)
        self.n = n
        self.timer = self.create_timer(1.0, self.fire)

    def fire(self) -> None:
        self.timer.cancel()
        for i in range(self.n):
            self.pub.publish(String(data=f"m{i}"))


@pytest.mark.virtual_time
async def test_topics_that_appear_later_are_recorded_from_their_first_message(tmp_path):
    path = tmp_path / "late.mcap"
    async with Runtime(attach=[Recorder(path)]) as rt:
        await anyio.sleep(2.5)
        rt.spawn(Burst, 5)
        await anyio.sleep(2)
    got = [
        (m.log_time, codec.decode_cdr(m.data, String).data)
        for _, c, m in read_bag(path).iter_messages(topics=["/burst"])
    ]
    assert got == [(3_500_000_000, f"m{i}") for i in range(5)]


def _recorded(path: Path, topic: str) -> list[str]:
    return [codec.decode_cdr(m.data, String).data for _, _, m in read_bag(path).iter_messages(topics=[topic])]


@pytest.mark.virtual_time
async def test_a_full_buffer_holds_the_publisher_and_loses_nothing(tmp_path):
    path = tmp_path / "full.mcap"
    recorder = Recorder(path, topics=["/burst"], max_pending=20)
    async with Runtime(attach=[recorder]) as rt:
        rt.spawn(Burst, 50)
        await anyio.sleep(1.5)
        report = diagnose(rt)
    assert recorder.dropped == 0
    assert next(c for c in report.checks if c.name == "dropped messages").passed
    assert _recorded(path, "/burst") == [f"m{i}" for i in range(50)]
    assert "Dropped" not in format_info(Bag(path))


async def test_a_burst_larger_than_the_buffer_is_recorded_whole_on_the_wall_clock(tmp_path):
    # The writer works in a thread here: the burst overtakes it many times over, and the
    # runtime closes the bag right after it, with batches still on their way to the disk.
    path = tmp_path / "wall.mcap"
    recorder = Recorder(path, topics=["/burst"], max_pending=64)
    async with Runtime(attach=[recorder]) as rt:
        publish = rt.spawn(Burst, 0).pub.publish
        for i in range(3000):
            publish(String(data=f"m{i}"))
            if i % 500 == 0:
                await anyio.lowlevel.checkpoint()  # the writer task takes a batch to its thread
    assert recorder.dropped == 0
    assert _recorded(path, "/burst") == [f"m{i}" for i in range(3000)]


@pytest.mark.virtual_time
async def test_a_lossy_recorder_drops_counts_and_bag_info_and_doctor_say_so(tmp_path):
    path = tmp_path / "drops.mcap"
    recorder = Recorder(path, topics=["/burst"], max_pending=20, lossy=True)
    async with Runtime(attach=[recorder]) as rt:
        rt.spawn(Burst, 50)
        await anyio.sleep(1.5)
        report = diagnose(rt)
        info = rt.graph.topic("/burst")
    assert recorder.dropped == 30
    assert [e.dropped for e in info.subscriptions if e.node == "/_actors_recorder"] == [30]
    drops = next(c for c in report.checks if c.name == "dropped messages")
    assert not drops.passed and drops.reasons == (
        "/burst: the recorder dropped 30 message(s): the disk could not keep up",
    )
    assert _recorded(path, "/burst") == [f"m{i}" for i in range(20)]
    text = format_info(Bag(path))
    assert "\nDropped:           30 (recorded lossy: the disk fell behind)\n" in text
    assert "Topic: /burst | Type: std_msgs/msg/String | Count: 20 | Dropped: 30 | Serialization Format: cdr" in text


@pytest.mark.virtual_time
async def test_topic_selection_and_exclusion(tmp_path):
    from nodes.listener import MinimalSubscriber
    from nodes.talker import MinimalPublisher

    only = Recorder(tmp_path / "only.mcap", topics=["topic"])
    rest = Recorder(tmp_path / "rest.mcap", exclude="^/(topic|rosout)$")
    async with Runtime(attach=[only, rest]) as rt:
        rt.spawn(MinimalPublisher)
        rt.spawn(MinimalSubscriber)
        await anyio.sleep(2.1)
    topics = {}
    for name in ("only", "rest"):
        topics[name] = sorted(c.topic for c in read_bag(tmp_path / f"{name}.mcap").get_summary().channels.values())
    assert topics == {"only": ["/topic"], "rest": ["/parameter_events"]}


@pytest.mark.slow
def test_an_existing_output_is_a_one_line_error(run_module, tmp_path):
    taken = tmp_path / "run.mcap"
    taken.write_bytes(b"keep me")
    done = run_module(
        "actors.run", "graphs/pubsub.toml", "--clock", "virtual", "--duration", "1", "--record", str(taken)
    )
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "already exists" in done.stderr
    assert taken.read_bytes() == b"keep me"


@pytest.mark.skipif(sys.platform != "linux", reason="needs RLIMIT_FSIZE and SIGXFSZ")
@pytest.mark.slow
def test_a_disk_that_fills_up_leaves_a_valid_bag_and_the_graph_running(tmp_path):
    # A file size limit stands in for a full disk: writes past it fail (EFBIG) as on a full disk.
    path = tmp_path / "full.mcap"
    script = (
        "import resource, signal, anyio\n"
        "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
        "resource.setrlimit(resource.RLIMIT_FSIZE, (60_000, 60_000))\n"
        "from actors import VirtualTimeLoop\n"
        "from actors.launch.graph_file import load_graph\n"
        "from actors.recording import Recorder\n"
        "from actors.run import run_graph\n"
        "graph, classes = load_graph('graphs/turtlebot.toml')\n"
        f"recorder = Recorder({str(path)!r}, chunk_size=16_384)\n"
        "anyio.run(lambda: run_graph(graph, classes, name='full', duration=30, attach=[recorder]),\n"
        "          backend_options={'loop_factory': VirtualTimeLoop})\n"
        "print('graph ran to its end')\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], cwd=ROOT, env=python_env(), capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0 and "graph ran to its end" in done.stdout, done.stderr
    assert "recording to" in done.stderr and "stopped" in done.stderr
    assert path.stat().st_size <= 60_000
    # The file ends at its last whole chunk, then a footer: valid MCAP, every CRC right.  (The
    # summary did not fit: the disk was full.)  The mcap library and rosbags read every message.
    from mcap.stream_reader import StreamReader
    from rosbags.highlevel import AnyReader
    from rosbags.typesys import Stores, get_typestore

    with open(path, "rb") as f:
        records = list(StreamReader(f, validate_crcs=True).records)
    written = sum(type(r).__name__ == "Message" for r in records)
    assert type(records[-1]).__name__ == "Footer" and written > 100
    assert f"keeps the {written} message(s) written before" in done.stderr
    with AnyReader([path], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        assert sum(1 for _ in reader.messages()) == written


class _FillingDisk(io.BytesIO):
    """A file with room for ``room`` bytes, then failing as a full disk does."""

    def __init__(self, room: int) -> None:
        super().__init__()
        self.room = room

    def write(self, data) -> int:  # type: ignore[override]
        if self.tell() + len(data) > self.room:
            raise OSError(errno.ENOSPC, "no space left on device")
        return super().write(data)


def test_a_batch_that_fills_the_disk_counts_every_message_left_out_of_the_file():
    writer = McapWriter(_FillingDisk(room=3_000), chunk_size=1_000, compression="")
    channel = writer.add_channel("/t", writer.add_schema("std_msgs/msg/String", "ros2msg", b"string data"), "cdr", {})
    writer.add_messages([(channel, i, i, bytes(100)) for i in range(50)])
    assert writer.error is not None and 0 < writer.message_count < 50
    assert writer.message_count + writer.lost == 50
    writer.add_message(channel, 50, 50, bytes(100))
    assert writer.message_count + writer.lost == 51


@pytest.mark.virtual_time
async def test_graph_events_tell_listeners_of_endpoints_coming_and_going():
    from nodes.listener import MinimalSubscriber
    from nodes.talker import MinimalPublisher

    events: list[tuple[str, str, str]] = []

    class Listener:
        def endpoint_added(self, topic, endpoint):
            events.append(("added", topic.name, type(endpoint).__name__))

        def endpoint_removed(self, topic, endpoint):
            events.append(("removed", topic.name, type(endpoint).__name__))

    async with Runtime() as rt:
        rt.topics.listeners.append(Listener())
        rt.spawn(MinimalPublisher)
        rt.spawn(MinimalSubscriber)
        await rt.stop("minimal_subscriber")
        await anyio.sleep(1)
    on_topic = [e for e in events if e[1] == "/topic"]
    assert on_topic[:3] == [
        ("added", "/topic", "Publisher"),
        ("added", "/topic", "Subscription"),
        ("removed", "/topic", "Subscription"),
    ]


class ShortLived(Node):
    """Publishes messages with a lifespan (0.1 s), latched, once a second."""

    def __init__(self) -> None:
        super().__init__("short_lived")
        from actors.ros.qos import DurabilityPolicy, QoSProfile
        from actors.ros.time import Duration

        qos = QoSProfile(depth=5, lifespan=Duration(seconds=0.1), durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.pub = self.create_publisher(String, "short", qos)
        self.n = 0
        self.create_timer(1.0, self.tick)

    def tick(self) -> None:
        self.pub.publish(String(data=f"s{self.n}"))
        self.n += 1


@pytest.mark.virtual_time
async def test_messages_with_a_lifespan_are_recorded_as_published(tmp_path):
    path = tmp_path / "short.mcap"
    async with Runtime(attach=[Recorder(path, topics=["/short"])]) as rt:
        rt.spawn(ShortLived)
        await anyio.sleep(3.5)
    got = [codec.decode_cdr(m.data, String).data for _, _, m in read_bag(path).iter_messages()]
    assert got == ["s0", "s1", "s2"]


def test_the_summary_kept_in_memory_costs_a_few_hundred_bytes_per_chunk(tmp_path):
    import tracemalloc

    # A recording flushed every second writes 60 chunks a minute, for as long as it runs: what the
    # writer keeps per chunk (the summary must index each one) is its memory's growth per minute.
    path = tmp_path / "chunks.mcap"
    writer = McapWriter(path.open("wb", buffering=0), compression="")
    schema = writer.add_schema("std_msgs/msg/String", "ros2msg", b"string data")
    channels = [writer.add_channel(f"/t{i}", schema, "cdr", {}) for i in range(12)]
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        for chunk in range(1_000):
            writer.add_messages([(channel, chunk, chunk, b"x") for channel in channels])
            writer.flush()
        per_chunk = (tracemalloc.get_traced_memory()[0] - before) / 1_000
    finally:
        tracemalloc.stop()
    writer.close()
    assert per_chunk < 300, f"{per_chunk:.0f} bytes kept per chunk"
    with path.open("rb") as stream:
        summary = mcap_reader.make_reader(stream).get_summary()
    assert summary is not None and summary.statistics is not None
    assert summary.statistics.chunk_count == len(summary.chunk_indexes) == 1_000
    assert summary.statistics.message_count == 12_000
    last = summary.chunk_indexes[-1]
    assert (last.message_start_time, last.message_end_time) == (999, 999)
    assert sorted(last.message_index_offsets) == channels
    with path.open("rb") as stream:
        messages = list(mcap_reader.make_reader(stream).iter_messages(starting_at=999))
    assert [(channel.id, message.log_time) for _, channel, message in messages] == [(c, 999) for c in channels]


def test_messages_given_as_a_generator_make_the_bytes_that_one_at_a_time_make(tmp_path):
    # The recorder hands its batch as a generator that encodes each message as it is taken.
    def bag(name: str, batches: bool) -> bytes:
        path = tmp_path / name
        writer = McapWriter(path.open("wb", buffering=0), chunk_size=700)
        schema = writer.add_schema("std_msgs/msg/String", "ros2msg", b"string data")
        channels = [writer.add_channel(f"/t{i}", schema, "cdr", {}) for i in range(3)]
        messages = [(channels[i % 3], i, i + 7, codec.encode_cdr(String(data="m" * (i % 40)))) for i in range(500)]
        if batches:
            for start in range(0, 500, 37):  # batches that end mid-chunk and span chunks
                writer.add_messages(m for m in messages[start : start + 37])
        else:
            for message in messages:
                writer.add_message(*message)
        writer.close()
        return path.read_bytes()

    one_at_a_time = bag("single.mcap", batches=False)
    assert bag("batched.mcap", batches=True) == one_at_a_time
    with open(tmp_path / "batched.mcap", "rb") as f:
        summary = mcap_reader.make_reader(f).get_summary()
    assert summary is not None and summary.statistics is not None
    assert summary.statistics.message_count == 500 and summary.statistics.chunk_count > 10


def test_a_generator_that_fills_the_disk_counts_what_it_still_held_as_lost():
    writer = McapWriter(_FillingDisk(room=3_000), chunk_size=1_000, compression="")
    channel = writer.add_channel("/t", writer.add_schema("std_msgs/msg/String", "ros2msg", b"string data"), "cdr", {})
    writer.add_messages((channel, i, i, bytes(100)) for i in range(50))
    assert writer.error is not None and 0 < writer.message_count < 50
    assert writer.message_count + writer.lost == 50


class Careless(Node):
    """Publishes, with every field trusted, one message that CDR cannot carry between two that it can."""

    def __init__(self) -> None:
        super().__init__("careless")
        self.pub = self.create_publisher(String, "careless", 10)
        self.pub.trust()
        self.create_timer(1.0, self.fire)

    def fire(self) -> None:
        for data in ("before", 5, "after"):
            self.pub.publish(String(data=data))  # type: ignore[arg-type]  # the 5 is the point


@pytest.mark.virtual_time
async def test_a_message_cdr_cannot_carry_is_counted_and_named_and_the_rest_recorded(tmp_path, caplog):
    path = tmp_path / "careless.mcap"
    recorder = Recorder(path, topics=["/careless"])
    async with Runtime(attach=[recorder]) as rt:
        rt.spawn(Careless)
        await anyio.sleep(1.5)
        info = rt.graph.topic("/careless")
    assert [e.dropped for e in info.subscriptions if e.node == "/_actors_recorder"] == [1]
    assert _recorded(path, "/careless") == ["before", "after"]
    warnings = [r.getMessage() for r in caplog.records if "cannot be written" in r.getMessage()]
    assert len(warnings) == 1 and "/careless" in warnings[0] and "data" in warnings[0], warnings


class BatchSizes(Recorder):
    """A recorder that notes how many messages each batch brings to its writer."""

    def __init__(self, *args, **kwargs) -> None:  # type: ignore[no-untyped-def]
        super().__init__(*args, **kwargs)
        self.sizes: list[int] = []

    def _write(self, batch):  # type: ignore[no-untyped-def]
        self.sizes.append(len(batch) // 3)  # tap, stamp, message per message
        return super()._write(batch)


async def _published(rt: Runtime, count: int, every: int) -> None:
    """Publish ``count`` Strings (m0, m1...) on /burst, ``every`` between turns of the loop."""
    publish = rt.spawn(Burst, 0).pub.publish
    for i in range(count):
        publish(String(data=f"m{i}"))
        if i % every == every - 1:
            await anyio.lowlevel.checkpoint()


async def test_on_the_wall_clock_the_writer_thread_gets_batches_worth_its_hop(tmp_path):
    # A quarter of the buffer (100 here) goes to the worker thread at a time, not what one turn
    # of the loop published (20): each hand-off is a hop to the thread and back.
    path = tmp_path / "batches.mcap"
    recorder = BatchSizes(path, topics=["/burst"], max_pending=400, flush_interval=600)
    async with Runtime(attach=[recorder]) as rt:
        await _published(rt, 3000, every=20)
    assert sum(recorder.sizes) == 3000 and recorder.dropped == 0
    assert all(size >= 100 for size in recorder.sizes[:-1]), recorder.sizes  # the last: what the close found
    assert _recorded(path, "/burst") == [f"m{i}" for i in range(3000)]


async def test_on_the_wall_clock_a_trickle_under_a_batch_reaches_the_file_within_the_flush_interval(tmp_path):
    path = tmp_path / "trickle.mcap"
    recorder = Recorder(path, topics=["/burst"], max_pending=400, flush_interval=0.05)
    async with Runtime(attach=[recorder]) as rt:
        await _published(rt, 3, every=3)
        with anyio.fail_after(30):  # only the wall clock can say when: the flush interval is its
            while recorder.message_count < 3:
                await anyio.sleep(0.01)
    assert _recorded(path, "/burst") == ["m0", "m1", "m2"]


@pytest.mark.virtual_time
async def test_a_topic_that_goes_and_comes_back_leaves_no_old_tap_behind(tmp_path):
    # Each time a topic's last publisher goes, its tap is retired; a new one comes with the next
    # publisher.  What the recorder keeps of a tap must go with it.
    path, recorder, gone = tmp_path / "cycle.mcap", Recorder(tmp_path / "cycle.mcap"), []
    async with Runtime(attach=[recorder]) as rt:
        node = rt.spawn(Burst, 0)
        node.destroy_publisher(node.pub)
        for i in range(5):
            pub = node.create_publisher(String, "again", 10)
            pub.publish(String(data=f"m{i}"))
            await anyio.sleep(2)  # past the flush interval: the batch is written
            gone += [weakref.ref(tap) for tap in recorder._taps.all() if tap.topic_name == "/again"]
            node.destroy_publisher(pub)
            await anyio.sleep(0.1)
        gc.collect()
        assert [tap() for tap in gone[:-1]] == [None] * 4  # each one that a newer tap replaced
    assert _recorded(path, "/again") == [f"m{i}" for i in range(5)]


def test_on_uvloop_each_message_of_a_burst_gets_its_own_receive_time(tmp_path):
    # uvloop's loop.time() is the millisecond of its last turn: a burst published in one turn
    # would share one log time.  rosbag2 stamps each message when it is received.
    pytest.importorskip("uvloop")
    path = tmp_path / "uv.mcap"

    async def main() -> None:
        async with Runtime(attach=[Recorder(path, topics=["/burst"])]) as rt:
            await _published(rt, 300, every=300)

    anyio.run(main, backend_options={"use_uvloop": True})
    times = [m.log_time for _, _, m in read_bag(path).iter_messages(topics=["/burst"])]
    assert len(times) == 300 and times == sorted(times)
    assert len(set(times)) > 1


@pytest.mark.virtual_time
async def test_what_a_transport_lost_on_the_way_is_not_counted_as_the_recorders_drop(tmp_path):
    path, recorder = tmp_path / "lost.mcap", Recorder(tmp_path / "lost.mcap")
    async with Runtime(attach=[recorder]) as rt:
        node = rt.spawn(Burst, 0)
        node.pub.publish(String(data="m0"))
        await anyio.sleep(2)
        subscriptions = rt.topics.topics["/burst"].subscriptions
        assert any(isinstance(sub, Tap) for sub in subscriptions)
        for sub in subscriptions:  # as the Zenoh bridge counts samples its backlog pushed out
            sub.lost(3)
        assert {tap.topic_name: tap.dropped for tap in recorder._taps.all()}["/burst"] == 0
    assert recorder.dropped == 0
    assert "dropped" not in format_info(Bag(path)).lower()


class Heard(Node):
    """Subscribes to /burst and keeps what it hears."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.heard: list[str] = []
        self.sub = self.create_subscription(String, "burst", lambda msg: self.heard.append(msg.data), 100)


@pytest.mark.virtual_time
async def test_a_recorded_topic_keeps_its_publishers_paths_and_every_message_reaches_all(tmp_path):
    # A tap is no feed: the publisher hands it each snapshot as it makes it, and keeps its one
    # queue or its batch for the subscriptions (a tap among the feeds used to take both away).
    path = tmp_path / "paths.mcap"
    async with Runtime(attach=[Recorder(path, topics=["/burst"])]) as rt:
        first = rt.spawn(Heard, "first")
        pub = rt.spawn(Burst, 0).pub
        pub.publish(String(data="m0"))
        assert pub._only is first.sub  # one subscription: fed inline, as without a recorder
        second = rt.spawn(Heard, "second")
        for i in range(1, 30):
            pub.publish(String(data=f"m{i}"))
            assert pub.state is PublisherState.BATCH_OPEN  # two: one append to the batch they hold
        assert pub.invariant_violations() == []
        await anyio.sleep(1)
    assert first.heard == [f"m{i}" for i in range(30)]
    assert second.heard == [f"m{i}" for i in range(1, 30)]
    assert _recorded(path, "/burst") == [f"m{i}" for i in range(30)]


@pytest.mark.virtual_time
async def test_a_publisher_that_trusts_its_fields_once_tapped_is_still_recorded(tmp_path):
    path = tmp_path / "trust.mcap"
    async with Runtime(attach=[Recorder(path, topics=["/burst"])]) as rt:
        rt.spawn(Heard, "heard")
        pub = rt.spawn(Burst, 0).pub
        pub.publish(String(data="m0"))
        pub.trust()  # new snapshot functions: the tap wraps them again
        pub.publish(String(data="m1"))
        await anyio.sleep(1)
    assert _recorded(path, "/burst") == ["m0", "m1"]


@pytest.mark.virtual_time
async def test_a_destroyed_publisher_is_not_recorded(tmp_path):
    path = tmp_path / "gone.mcap"
    async with Runtime(attach=[Recorder(path, topics=["/burst"])]) as rt:
        rt.spawn(Heard, "heard")
        node = rt.spawn(Burst, 0)
        pub = node.pub
        pub.publish(String(data="m0"))
        node.destroy_publisher(pub)
        pub.publish(String(data="late"))  # nobody receives it: the recorder no more than the rest
        await anyio.sleep(1)
    assert _recorded(path, "/burst") == ["m0"]


@pytest.mark.virtual_time
async def test_large_and_small_messages_in_one_batch_are_recorded_as_encode_cdr_makes_them(tmp_path):
    # The writer encodes every message of a batch into one buffer; an array over 64 KiB is kept
    # aside (a spill) and spends it.  Each recorded message must still be exactly its own CDR.
    from interfaces.std_msgs.msg import Float64MultiArray

    path = tmp_path / "arrays.mcap"
    sizes = [10_000, 3, 20_000, 0, 5, 9_000, 1]
    sent = [Float64MultiArray(data=[float(i + n) for i in range(n)]) for n in sizes]
    async with Runtime(attach=[Recorder(path)]) as rt:
        node = rt.spawn(Node, "arrays")
        pub = node.create_publisher(Float64MultiArray, "arrays", 10)
        for msg in sent:
            pub.publish(msg)
        await anyio.sleep(1)
    recorded = [bytes(m.data) for _, _, m in read_bag(path).iter_messages(topics=["/arrays"])]
    assert recorded == [codec.encode_cdr(msg) for msg in sent]
