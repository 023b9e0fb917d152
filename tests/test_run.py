"""``python -m actors.run``: the demo graph, exit codes, escalation and signals."""

from __future__ import annotations

import contextlib
import re
import signal
import subprocess
import sys
from collections.abc import Iterator

import pytest

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


@contextlib.contextmanager
def running_demo() -> Iterator[subprocess.Popen[str]]:
    """``python -m actors.run graph.toml`` on the wall clock, once the talker has published."""
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
        for _ in range(200):
            if "Publishing" in proc.stdout.readline():
                break
        else:
            raise AssertionError("the demo graph never published")
        yield proc
    finally:
        proc.kill()


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_on_the_wall_clock_stops_gracefully_without_traceback(signum):
    with running_demo() as proc:
        proc.send_signal(signum)
        out, err = proc.communicate(timeout=5)
    assert proc.returncode == 0, err
    assert "Traceback" not in out + err


def test_the_services_graph_waits_for_its_servers_then_succeeds(run_module):
    result = run_module("actors.run", "graphs/services.toml", "--clock", "virtual", "--duration", "5")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    waiting = out.index("[minimal_client_async]: service not available, waiting again...")
    answered = out.index("[minimal_client_async]: Result of add_two_ints: for 41 + 1 = 42")
    assert waiting < out.index("[minimal_service]: Incoming request\na: 41 b: 1") < answered
    assert "[add_three_ints_client]: Result of add_three_ints: for 2 + 3 + 1 = 6" in out


def test_a_parameter_override_of_the_wrong_type_exits_2(run_module, tmp_path):
    graph = tmp_path / "params.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.param_talker:MinimalParam"\nparams = { my_parameter = 3 }\n')
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "1")
    assert result.returncode == 2
    assert result.stderr.strip() == (
        f"error: {graph}: nodes[0] (nodes.param_talker:MinimalParam): parameter 'my_parameter' of "
        "/minimal_param_node: wrong type: expected STRING, got INTEGER (3)"
    )


def test_the_params_graph_with_an_override(run_module, tmp_path):
    graph = tmp_path / "params.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.param_talker:MinimalParam"\nparams = { my_parameter = "earth" }\n')
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "2.5")
    hellos = re.findall(r"\[minimal_param_node\]: (Hello \w+!)", result.stdout)
    assert hellos == ["Hello earth!", "Hello world!"]
