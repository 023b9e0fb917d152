"""``topic pub``'s options as ros2's: waiting for subscriptions, printing every N-th, stdin, stamped headers."""

from __future__ import annotations

import re
import subprocess
import sys
import threading

import pytest
from conftest import ROOT, python_env


@pytest.fixture(scope="module")
def graphs(tmp_path_factory):
    """The talker graph twice, on the wall clock (``wall``) and on the virtual clock (``virtual``)."""
    env = python_env()
    env["XDG_RUNTIME_DIR"] = str(tmp_path_factory.mktemp("run"))
    folder = tmp_path_factory.mktemp("graphs")
    text = (ROOT / "graphs/pubsub.toml").read_text()
    (folder / "wall.toml").write_text(text)
    (folder / "virtual.toml").write_text(text.replace('clock = "wall"', 'clock = "virtual"'))
    procs = []
    for name, extra in (("wall", []), ("virtual", ["--duration", "1e9"])):
        proc = subprocess.Popen(
            [sys.executable, "-m", "actors.run", str(folder / f"{name}.toml"), *extra],
            cwd=ROOT,
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        procs.append(proc)
        up = threading.Event()
        # Read all it prints (virtual time prints fast: a full pipe would stop the graph).
        threading.Thread(target=drain, args=(proc, up), daemon=True).start()
        assert up.wait(60), f"graph {name} did not start"
    yield env
    for proc in procs:
        proc.terminate()
        proc.wait(timeout=30)


def drain(proc: subprocess.Popen[str], up: threading.Event) -> None:
    assert proc.stdout is not None
    for line in proc.stdout:
        if "Publishing" in line:  # the first message is out: the graph is up
            up.set()


def actors(env, *argv, stdin=None):
    return subprocess.run(
        [sys.executable, "-m", "actors", *argv],
        cwd=ROOT,
        env=env,
        input=stdin,
        capture_output=True,
        text=True,
        timeout=60,
    )


def pub(env, graph, *argv, stdin=None):
    return actors(env, "topic", "pub", *argv, "--graph", graph, stdin=stdin)


@pytest.mark.slow
def test_once_waits_for_a_subscription_and_says_so_as_ros2_does(graphs):
    done = pub(graphs, "wall", "--once", "/nobody", "std_msgs/msg/String", "data: hi", "--max-wait-time-secs", "0.3")
    assert done.returncode == 1
    assert done.stdout == "Waiting for at least 1 matching subscription(s)...\n"
    assert done.stderr == "Timed out waiting for subscribers: Expected 1 subcribers but only got 0 subscribers\n"
    # -w 0 publishes at once; a subscribed topic needs no wait.
    for argv in (["-w", "0", "/nobody"], ["/topic"]):
        done = pub(graphs, "wall", "--once", *argv, "std_msgs/msg/String", "data: hi")
        assert done.returncode == 0, done.stderr
        assert done.stdout == "publisher: beginning loop\npublishing #1: std_msgs.msg.String(data='hi')\n\n"


@pytest.mark.slow
def test_print_every_nth_and_values_from_stdin(graphs):
    done = pub(graphs, "wall", "-t", "4", "-r", "50", "-p", "2", "/topic", "std_msgs/msg/String", "data: x")
    assert done.returncode == 0, done.stderr
    assert re.findall(r"publishing #(\d+)", done.stdout) == ["2", "4"]
    done = pub(graphs, "wall", "--once", "--stdin", "/topic", "std_msgs/msg/String", stdin="data: from stdin\n")
    assert done.returncode == 0, done.stderr
    assert "publishing #1: std_msgs.msg.String(data='from stdin')" in done.stdout


@pytest.mark.slow
def test_auto_headers_and_now_stamps_take_the_graphs_clock(graphs):
    # On the virtual clock: the stamps are the graph's time, not this machine's.
    argv = ["topic", "echo", "/ref", "sensor_msgs/msg/TimeReference", "--once", "--graph", "virtual"]
    echo = subprocess.Popen(
        [sys.executable, "-m", "actors", *argv],
        cwd=ROOT,
        env=graphs,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    # --once waits for the echo's subscription, as ros2's does.
    done = pub(graphs, "virtual", "--once", "/ref", "sensor_msgs/msg/TimeReference", "{header: auto, time_ref: now}")
    out, err = echo.communicate(timeout=60)
    assert done.returncode == 0 and echo.returncode == 0, done.stderr + err
    stamps = re.findall(r"sec: (\d+)\n\s+nanosec: (\d+)", out)
    assert len(stamps) == 2 and stamps[0] == stamps[1], out
    assert 0 < int(stamps[0][0]) < 1_000_000_000, out  # virtual seconds, not the epoch's
    sec, nanosec = stamps[0]
    printed = f"stamp=builtin_interfaces.msg.Time(sec={sec}, nanosec={nanosec})"
    assert printed in done.stdout, done.stdout  # the line printed shows the stamp sent


def test_max_wait_without_a_wait_is_refused(tmp_path):
    env = python_env()
    env["XDG_RUNTIME_DIR"] = str(tmp_path)
    done = pub(env, "nograph", "/topic", "std_msgs/msg/String", "--max-wait-time-secs", "1")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "--max-wait-time-secs works with --wait-matching-subscriptions, --once or --times" in done.stderr


@pytest.mark.slow
def test_qos_options_make_a_latched_publisher_and_a_subscription_that_asks_otherwise(graphs):
    argv = ["--once", "-w", "0", "--keep-alive", "60", "--qos-durability", "transient_local", "--graph", "wall"]
    latched = subprocess.Popen(
        [sys.executable, "-m", "actors", "topic", "pub", *argv, "/latched", "std_msgs/msg/String", "data: kept"],
        cwd=ROOT,
        env=graphs,
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert latched.stdout is not None
        assert "publishing #1" in latched.stdout.readline() + latched.stdout.readline()
        # Published before either echo subscribed: only a transient-local subscription gets it.
        late = ["topic", "echo", "/latched", "--once", "--timeout", "20", "--graph", "wall"]
        kept = actors(graphs, *late, "--qos-durability", "transient_local", "--qos-reliability", "reliable")
        assert kept.returncode == 0 and kept.stdout == "data: kept\n---\n", kept.stderr
        volatile = actors(graphs, *late[:-4], "--timeout", "1", "--graph", "wall", "--qos-durability", "volatile")
        assert volatile.returncode == 0 and volatile.stdout == "", volatile.stdout
    finally:
        latched.terminate()
        latched.wait(timeout=30)
