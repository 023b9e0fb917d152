"""A recording killed outright loses at most its last second; ``bag reindex`` makes the rest a whole bag."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import anyio
import pytest
from conftest import ROOT, python_env
from test_signals import Command, own_env

from actors import Node, Runtime, codec
from actors.errors import BagError
from actors.recording import Recorder
from actors.recording.reader import Bag
from actors.recording.reindex import reindex
from interfaces.std_msgs.msg import String

pytest.importorskip("mcap")


class Ticker(Node):
    """Publishes ``t<n>`` ten times a second."""

    def __init__(self) -> None:
        super().__init__("ticker")
        self.pub = self.create_publisher(String, "ticks", 10)
        self.n = 0
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        self.pub.publish(String(data=f"t{self.n}"))
        self.n += 1


def killed_copy(path: Path, tmp_path: Path) -> Path:
    """The bag as ``kill -9`` would leave it now: the bytes on disk, never closed."""
    copy = tmp_path / "killed.mcap"
    shutil.copyfile(path, copy)
    return copy


@pytest.mark.virtual_time
@pytest.mark.parametrize("interval", [1.0, 0.25])
async def test_a_recording_killed_after_20_s_loses_at_most_its_flush_interval(tmp_path, interval):
    path = tmp_path / "run.mcap"
    async with Runtime(attach=[Recorder(path, flush_interval=interval)]) as rt:
        rt.spawn(Ticker)
        await anyio.sleep(20.05)
        now = rt.clock.now_ns()
        copy = killed_copy(path, tmp_path)
    with pytest.raises(BagError, match="without a footer"):
        Bag(copy)
    recovered = Bag(copy, recover=True)
    times = [m.log_time for m in recovered.messages(["/ticks"])]
    # Every message older than the interval is on disk (with 1 MiB chunks and nothing flushed
    # by time, all 200 would still be in the first chunk: nothing at all).
    published = [m.log_time for m in Bag(path).messages(["/ticks"])]  # the whole run, closed properly
    assert times == published[: len(times)]
    assert len(times) >= len([t for t in published if t < now - interval * 1e9])
    assert len(times) >= 200 - interval * 10 - 1

    kept, problems = reindex(copy)
    assert kept == recovered.message_count and problems != []
    whole = Bag(copy)  # no recover: a summary and a footer again
    assert whole.message_count == kept
    assert [m.log_time for m in whole.messages(["/ticks"])] == times
    ticks = [codec.decode_cdr(m.data, String).data for m in whole.messages(["/ticks"])]
    assert ticks == [f"t{i}" for i in range(len(times))]


@pytest.mark.virtual_time
async def test_a_quiet_graph_still_gets_its_last_messages_onto_the_disk(tmp_path):
    # The chunk in progress is written when it is due even if nothing else is published.
    path = tmp_path / "quiet.mcap"
    async with Runtime(attach=[Recorder(path)]) as rt:
        node = rt.spawn(Node, "once")
        pub = node.create_publisher(String, "once", 10)
        await anyio.sleep(0.5)
        pub.publish(String(data="only"))
        await anyio.sleep(1.5)
        copy = killed_copy(path, tmp_path)
    assert [m.data for m in Bag(copy, recover=True).messages(["/once"])] == [codec.encode_cdr(String(data="only"))]


def test_reindex_of_a_bag_directory_writes_its_metadata(tmp_path, run_module):
    bag = tmp_path / "dir_bag"
    result = run_module(
        "actors.run", "graphs/pubsub.toml", "--clock", "virtual", "--duration", "3", "--record", str(bag)
    )
    assert result.returncode == 0, result.stderr
    (bag / "metadata.yaml").unlink()
    before = Bag(bag)
    done = run_module("actors", "bag", "reindex", str(bag))
    assert done.returncode == 0, done.stderr
    assert f"reindexed {bag}: {before.message_count} message(s)" in done.stderr
    after = Bag(bag)
    assert (after.message_count, [t.name for t in after.topics]) == (
        before.message_count,
        [t.name for t in before.topics],
    )
    metadata = (bag / "metadata.yaml").read_text()
    assert "message_count" in metadata and "offered_qos_profiles" in metadata and "reliability" in metadata


def test_reindex_of_no_bag_is_one_line_exit_2(run_module, tmp_path):
    done = run_module("actors", "bag", "reindex", str(tmp_path / "nothing.mcap"))
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr


@pytest.mark.slow
def test_kill_9_of_a_turtlebot_recording_loses_at_most_the_last_second(tmp_path):
    # On the wall clock: the recorder writes in a worker thread, as a real recording does.
    bag = tmp_path / "turtle.mcap"
    command = Command(
        [sys.executable, "-m", "actors.run", "graphs/turtlebot.toml", "--record", str(bag)], own_env(tmp_path)
    )
    deadline = time.monotonic() + 60
    while (not bag.exists() or bag.stat().st_size < 20_000) and time.monotonic() < deadline:
        time.sleep(0.1)  # a file growing on disk: no event tells of it
    time.sleep(3)
    killed_at = time.time_ns()
    command.proc.kill()
    command.finish()
    kept, _ = reindex(bag)
    last = max(m.log_time for m in Bag(bag).messages())
    # One second of flush interval, and a little for a loaded machine to get round to it.
    assert killed_at - last <= 1.5e9, (killed_at - last) / 1e9
    assert kept > 100


@pytest.mark.slow
def test_sigterm_to_bag_record_keeps_every_message_received(tmp_path):
    env = own_env(tmp_path)
    name = f"rec{os.getpid()}"  # short: a control socket's path must fit in 104 bytes
    graph = tmp_path / f"{name}.toml"
    graph.write_text((ROOT / "graphs/pubsub.toml").read_text())
    running = Command([sys.executable, "-m", "actors.run", str(graph)], env)
    try:
        running.wait_for("I heard", timeout=60)  # bounds for a loaded machine
        out = tmp_path / "record.mcap"
        record = Command(
            [sys.executable, "-m", "actors", "bag", "record", "/topic", "-o", str(out), "--graph", name], env
        )
        record.wait_for("Recording to", timeout=60)
        seen = len(running.lines)
        running.wait_for("Publishing", after=seen, timeout=60)
        seen = len(running.lines)
        running.wait_for("Publishing", after=seen, timeout=60)  # a few messages in, at least
        published = [line for line in running.lines if "Publishing" in line]
        last = int(published[-1].rsplit(":", 1)[1].strip().strip('"'))
        record.proc.send_signal(signal.SIGTERM)
        output = record.finish()
    finally:
        running.proc.terminate()
        running.finish()
    assert record.proc.returncode == 0, output
    numbers = [int(codec.decode_cdr(m.data, String).data.rsplit(":", 1)[1]) for m in Bag(out).messages()]
    assert numbers == list(range(numbers[0], numbers[-1] + 1))  # none missing in between
    assert numbers[-1] >= last - 1  # the one published as the signal left may still be on its way
    assert f"Recorded {len(numbers)} message(s)" in output


@pytest.mark.slow
def test_bag_record_of_a_quiet_topic_on_virtual_time_still_flushes(tmp_path):
    # The graph's timers keep virtual time going; the recorded topic gets a few messages, then none:
    # no later stamp comes to tell the recording that its open chunk is old.
    env = own_env(tmp_path)
    name = f"quiet{os.getpid()}"
    graph = tmp_path / f"{name}.toml"
    graph.write_text((ROOT / "graphs/pubsub.toml").read_text().replace('clock = "wall"', 'clock = "virtual"'))
    running = Command([sys.executable, "-m", "actors.run", str(graph), "--duration", "1e9"], env)
    record = None
    try:
        running.wait_for("I heard", timeout=60)
        out = tmp_path / "quiet.mcap"
        argv = [sys.executable, "-m", "actors", "bag", "record", "/few", "-o", str(out), "--graph", name]
        record = Command([*argv, "--flush-interval", "0.2"], env)
        record.wait_for("Recording to", timeout=60)
        # A few: the first may go before the recording has seen the new topic and subscribed.
        pub = [sys.executable, "-m", "actors", "topic", "pub", "-t", "20", "-r", "20", "/few", "std_msgs/msg/String"]
        sent = subprocess.run([*pub, "{data: hi}", "--graph", name], env=env, capture_output=True, text=True)
        assert sent.returncode == 0, sent.stderr
        # Until the file has stopped growing (one second the same): then the recording's output
        # says how many it received, and every one of them must have been in the file already.
        deadline = time.monotonic() + 30  # bounds for a loaded machine
        counts = [0]
        while (counts[-1] == 0 or counts[-10:] != counts[-1:] * 10) and time.monotonic() < deadline:
            time.sleep(0.1)  # a file growing on disk: no event tells of it
            counts.append(sum(1 for _ in Bag(killed_copy(out, tmp_path), recover=True).messages()))
        assert record.proc.poll() is None  # written while still recording, not at its end
        record.proc.send_signal(signal.SIGTERM)
        assert f"Recorded {counts[-1]} message(s)" in record.finish()
        record = None
    finally:
        for command in (record, running):
            if command is not None:
                command.proc.terminate()
                command.finish()


def test_the_flush_interval_must_be_positive(tmp_path):
    with pytest.raises(ValueError, match="flush_interval must be > 0 seconds"):
        Recorder(tmp_path / "x.mcap", flush_interval=0)
    done = subprocess.run(
        [sys.executable, "-m", "actors", "bag", "record", "-a", "--flush-interval", "0"],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2 and "--flush-interval" in done.stderr


@pytest.mark.slow
def test_bag_record_keeps_a_latched_topics_only_message(tmp_path):
    # Published once, before the recording began: it reaches the recording as the latched history
    # that comes with the subscription's reply.
    env = own_env(tmp_path)
    name = f"latch{os.getpid()}"
    graph = tmp_path / f"{name}.toml"
    graph.write_text((ROOT / "graphs/pubsub.toml").read_text())
    running = Command([sys.executable, "-m", "actors.run", str(graph)], env)
    latched = record = None
    try:
        running.wait_for("I heard", timeout=60)
        pub = ["topic", "pub", "--once", "-w", "0", "--keep-alive", "60", "--qos-durability", "transient_local"]
        latched = Command(
            [sys.executable, "-m", "actors", *pub, "/latched", "std_msgs/msg/String", "data: kept", "--graph", name],
            env,
        )
        latched.wait_for("publishing #1", timeout=60)
        out = tmp_path / "latched.mcap"
        record = Command(
            [sys.executable, "-m", "actors", "bag", "record", "/latched", "-o", str(out), "--graph", name], env
        )
        record.wait_for("Recording to", timeout=60)
        deadline = time.monotonic() + 20  # the flush interval, and a loaded machine
        kept: list[str] = []
        while not kept and time.monotonic() < deadline:
            time.sleep(0.1)  # a file growing on disk: no event tells of it
            kept = [
                codec.decode_cdr(m.data, String).data for m in Bag(killed_copy(out, tmp_path), recover=True).messages()
            ]
        assert kept == ["kept"]
    finally:
        for command in (record, latched, running):
            if command is not None:
                command.proc.terminate()
                command.finish()
