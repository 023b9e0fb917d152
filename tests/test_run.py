"""``python -m actors.run``: the demo graph, exit codes, escalation and signals."""

from __future__ import annotations

import re
import signal
import subprocess
import sys

from conftest import ROOT, python_env


def test_the_demo_graph_on_virtual_time_hears_every_message_in_order(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "virtual", "--duration", "10")
    assert result.returncode == 0, result.stderr
    heard = [int(n) for n in re.findall(r'I heard: "Hello World: (\d+)"', result.stdout)]
    assert heard[: 19] == list(range(19))
    assert "Traceback" not in result.stdout + result.stderr
    # Stamps come from the virtual clock: the first message is published at 0.5 s.
    assert '[INFO] [0.500000000] [minimal_publisher]: Publishing: "Hello World: 0"' in result.stdout


def test_a_malformed_graph_exits_2_with_one_line(run_module, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nparms = {}\n')
    result = run_module("actors.run", str(bad))
    assert result.returncode == 2
    assert result.stderr.strip() == f"error: {bad}: nodes[0].parms: unknown key"
    assert result.stdout == ""


def test_bad_options_exit_2(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "sundial")
    assert result.returncode == 2
    assert "invalid choice: 'sundial'" in result.stderr


def test_escalation_exits_1_with_the_cause_printed_once(run_module, tmp_path):
    graph = tmp_path / "crash.toml"
    graph.write_text(
        """
[runtime]
clock = "virtual"
duration = 30

[supervisor]
intensity = 2
period = 10.0
backoff = 0.0

[[nodes]]
use = "graph_nodes:AlwaysCrash"

[[nodes]]
use = "graph_nodes:Counter"
"""
    )
    result = run_module("actors.run", str(graph))
    assert result.returncode == 1
    fatal = [line for line in result.stderr.splitlines() if "giving up" in line]
    assert fatal == [
        "[FATAL] supervisor: node /always_crash crashed 3 times; more than 2 restarts within "
        "10.0 s, giving up (last error: RuntimeError('cannot handle 2'))"
    ]
    assert result.stdout.count("dead letter") == 3


def test_sigint_on_the_wall_clock_exits_0_quickly_without_traceback():
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graph.toml"],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert proc.stdout is not None
        first = proc.stdout.readline()  # the graph runs: the talker has published once
        assert "Publishing" in first
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=5)
    finally:
        proc.kill()
    assert proc.returncode == 0, err
    assert "Traceback" not in out + err


def test_sigterm_also_stops_gracefully():
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graph.toml"],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert proc.stdout is not None
        proc.stdout.readline()
        proc.send_signal(signal.SIGTERM)
        out, err = proc.communicate(timeout=5)
    finally:
        proc.kill()
    assert proc.returncode == 0 and "Traceback" not in out + err
