"""``topic echo``'s format options print what ros2 prints: goldens from rosidl_runtime_py, and the live flags."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest
from conftest import ROOT, python_env

from actors import codec
from actors.cli._format import csv_text, yaml_text

GOLDENS = json.loads((ROOT / "tests" / "goldens" / "echo.json").read_text())


@pytest.mark.parametrize("entry", GOLDENS, ids=lambda e: f"{e['message']} {e['flags']}")
def test_each_format_option_prints_what_ros2_topic_echo_prints(entry):
    # Made by tests/goldens/make_echo_goldens.py with ros2's own message_to_yaml and message_to_csv.
    msg = codec.convert(entry["value"], codec.get_type(entry["type"]))
    options = dict(entry["options"])
    if options.pop("csv", False):
        printed = csv_text(msg, **options) + "\n"
    else:
        printed = yaml_text(msg, **options) + "---\n"
    assert printed == entry["printed"]


def test_the_goldens_cover_every_format_option():
    flags = {word for entry in GOLDENS for word in entry["flags"].split() if word.startswith("-")}
    assert flags == {"-l", "-f", "--flow-style", "--no-arr", "--no-str", "--csv"}


@pytest.fixture(scope="module")
def graph(tmp_path_factory):
    """The talker graph on the wall clock, with a control socket of its own."""
    env = python_env()
    env["XDG_RUNTIME_DIR"] = str(tmp_path_factory.mktemp("run"))
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graphs/pubsub.toml"],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    assert proc.stdout is not None
    for line in proc.stdout:  # the first message is out: the graph is up
        if "Publishing" in line:
            break
    yield env
    proc.terminate()
    proc.wait(timeout=30)


def echo(env, *argv):
    return subprocess.run(
        [sys.executable, "-m", "actors", "topic", "echo", "/topic", *argv, "--graph", "pubsub"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )


@pytest.mark.slow
def test_filter_raw_and_timeout_on_a_running_graph(graph):
    # The talker says "Hello World: N" twice a second: the filter keeps the ones ending in 0.
    done = echo(graph, "--filter", "m.data.endswith('0')", "--once")
    assert done.returncode == 0, done.stderr
    assert re.fullmatch(r"data: 'Hello World: \d*0'\n---\n", done.stdout), done.stdout
    raw = echo(graph, "--raw", "--once")
    assert raw.returncode == 0, raw.stderr
    data = eval(raw.stdout.removesuffix("\n---\n"))  # the repr of bytes, as ros2 prints them
    assert codec.decode_cdr(data, codec.get_type("std_msgs/msg/String")).data.startswith("Hello World: ")
    # --timeout ends the command, messages or not, as ros2's timer ends its spin.
    timed = echo(graph, "--timeout", "1.2")
    assert timed.returncode == 0, timed.stderr
    assert 1 <= timed.stdout.count("---\n") <= 4, timed.stdout


@pytest.mark.parametrize(
    ("argv", "error"),
    [
        (["--filter", "m.data ==="], "--filter: not a Python expression: 'm.data ===' (invalid syntax)"),
        (["--truncate-length", "-1"], "--truncate-length: must be >= 0, got -1"),
        (["--raw", "--field", "data"], "--raw prints whole messages: leave out --field"),
    ],
)
def test_a_bad_option_is_one_line_exit_2(argv, error):
    done = subprocess.run(
        [sys.executable, "-m", "actors", "topic", "echo", "/topic", *argv, "--graph", "nograph"],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2 and error in done.stderr, done.stderr
    assert "Traceback" not in done.stderr
