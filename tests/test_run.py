"""``python -m actors.run``: the demo graph, exit codes, escalation and signals."""

from __future__ import annotations

import contextlib
import re
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from conftest import ROOT, python_env


@pytest.mark.slow
def test_the_demo_graph_on_virtual_time_hears_every_message_in_order(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "virtual", "--duration", "10")
    assert result.returncode == 0, result.stderr
    heard = [int(n) for n in re.findall(r'I heard: "Hello World: (\d+)"', result.stdout)]
    assert heard[:19] == list(range(19))
    assert "Traceback" not in result.stdout + result.stderr
    # Stamps come from the virtual clock: the first message is published at 0.5 s.
    assert '[INFO] [0.500000000] [minimal_publisher]: Publishing: "Hello World: 0"' in result.stdout


@pytest.mark.slow
def test_a_malformed_graph_exits_2_with_one_line(run_module, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nparms = {}\n')
    result = run_module("actors.run", str(bad))
    assert result.returncode == 2
    assert result.stderr.strip() == f"error: {bad}: nodes[0].parms: unknown key (did you mean 'params'?)"
    assert result.stdout == ""


@pytest.mark.slow
def test_bad_options_exit_2(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "sundial")
    assert result.returncode == 2
    assert "invalid choice: 'sundial'" in result.stderr


@pytest.mark.slow
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
    fatal = [line for line in result.stderr.splitlines() if line.startswith("[FATAL]")]
    assert fatal == [
        "[FATAL] supervisor: node /always_crash crashed 3 times; more than 2 restarts within "
        "10.0 s, giving up (graph_nodes:AlwaysCrash, last error: RuntimeError('cannot handle 2'))"
    ]
    assert result.stdout.count("dead letter") == 3
    assert_only_users_frames(result.stderr, "graph_nodes.py")


@pytest.mark.slow
def test_a_crash_on_uvloop_shows_only_the_users_frames(run_module, tmp_path):
    pytest.importorskip("uvloop")
    (tmp_path / "quitter.py").write_text(
        "from actors import Node\n\n\n"
        "class Quits(Node):\n"
        "    def __init__(self):\n"
        '        super().__init__("quits")\n'
        "        self.create_timer(0.01, self.tick)\n\n"
        "    def tick(self):\n"
        "        raise SystemExit(3)\n"
    )
    graph = tmp_path / "quits.toml"
    graph.write_text('[[nodes]]\nuse = "quitter:Quits"\n')
    result = run_module("actors.run", str(graph), "--loop", "uvloop", "--duration", "5")
    assert "[FATAL]" in result.stderr, result.stderr
    assert_only_users_frames(result.stderr, "quitter.py")
    assert '.pyx"' not in result.stderr  # uvloop's own frames


def run_virtual(run_module, tmp_path, text: str) -> tuple[str, subprocess.CompletedProcess[str]]:
    """Write ``text`` as a graph file and run it for 5 s of virtual time; the file and the result."""
    graph = tmp_path / "graph_under_test.toml"
    graph.write_text(text)
    return str(graph), run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "5")


def assert_only_users_frames(stderr: str, source: str) -> None:
    """After the [FATAL] line come the frames of ``source`` only: none of the machinery's."""
    lines = stderr[stderr.index("[FATAL]") :].splitlines()[1:]
    files = re.findall(r'^  File "([^"]+)", line \d+, in \w+$', "\n".join(lines), re.MULTILINE)
    assert files and all(file.endswith(source) for file in files), stderr
    for word in ("Traceback", "ExceptionGroup", "anyio", "asyncio", "runpy", "actors/"):
        assert word not in stderr, stderr


@pytest.mark.parametrize("delay", [0.0, 1.0])
@pytest.mark.slow
def test_a_constructor_that_raises_at_start_is_one_fatal_line_and_its_frames(run_module, tmp_path, delay):
    _, result = run_virtual(
        run_module,
        tmp_path,
        f'[[nodes]]\nuse = "graph_nodes:Counter"\n\n[[nodes]]\nuse = "graph_nodes:FailsToStart"\ndelay = {delay}\n',
    )
    assert result.returncode == 1
    assert result.stderr.splitlines()[0] == (
        "[FATAL] node /fails_to_start (graph_nodes:FailsToStart) failed to start: ValueError: no calibration file"
    )
    assert result.stderr.count("[FATAL]") == 1
    assert_only_users_frames(result.stderr, "graph_nodes.py")
    assert '    raise ValueError("no calibration file")' in result.stderr.splitlines()


@pytest.mark.slow
def test_a_constructor_that_raises_on_restart_escalates_once_naming_node_class_and_error(run_module, tmp_path):
    _, result = run_virtual(
        run_module,
        tmp_path,
        '[supervisor]\nintensity = 2\nbackoff = 0.0\n\n[[nodes]]\nuse = "graph_nodes:FailsOnRestart"\n',
    )
    assert result.returncode == 1
    fatal = [line for line in result.stderr.splitlines() if line.startswith("[FATAL]")]
    assert fatal == [
        "[FATAL] supervisor: node /fails_on_restart crashed 3 times; more than 2 restarts "
        "within 5.0 s, giving up (graph_nodes:FailsOnRestart, "
        "last error: RuntimeError('cannot reopen the device'))"
    ]
    assert_only_users_frames(result.stderr, "graph_nodes.py")
    assert '    raise RuntimeError("cannot reopen the device")' in result.stderr.splitlines()
    assert "caused by" not in result.stderr  # each retry fails on its own, not chained


@pytest.mark.slow
def test_a_delayed_node_with_a_bad_override_is_a_graph_file_error_not_an_exception_group(run_module, tmp_path):
    graph, result = run_virtual(
        run_module,
        tmp_path,
        '[[nodes]]\nuse = "nodes.param_talker:MinimalParam"\nparams = { my_parameter = 3 }\ndelay = 1.0\n',
    )
    assert result.returncode == 2
    assert result.stderr == (
        f"error: {graph}: nodes[0] (nodes.param_talker:MinimalParam): parameter 'my_parameter' of "
        "/minimal_param_node: Wrong parameter type, expected 'Type.STRING' got 'Type.INTEGER'\n"
    )


def test_any_other_error_leaving_the_run_is_unwrapped_from_its_groups(capsys):
    from actors.run import _report

    def users_code() -> None:
        raise KeyError("left")

    try:
        try:
            users_code()
        except KeyError as exc:
            raise BaseExceptionGroup("outer", [ExceptionGroup("inner", [exc])]) from None
    except BaseExceptionGroup as group:
        assert _report(group, "g.toml") == 1
    err = capsys.readouterr().err
    assert err.splitlines()[0] == "[FATAL] KeyError: 'left'"
    assert "in users_code" in err and "ExceptionGroup" not in err and "Traceback" not in err


@pytest.mark.parametrize(
    ("contents", "args"),
    [
        ('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n', ("--clock", "virtual")),
        ('[runtime]\nclock = "virtual"\n\n[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n', ()),
    ],
)
@pytest.mark.slow
def test_virtual_time_without_a_duration_is_refused_with_a_hint(run_module, tmp_path, contents, args):
    graph = tmp_path / "endless.toml"
    graph.write_text(contents)
    result = run_module("actors.run", str(graph), *args)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == (
        f"error: {graph}: the virtual clock needs a duration, e.g. --duration 10 "
        "(virtual time runs as fast as it can, so nothing else would stop it)\n"
    )


@contextlib.contextmanager
def running_demo(*options: str) -> Iterator[subprocess.Popen[str]]:
    """``python -m actors.run graph.toml [OPTIONS]`` on the wall clock, once the talker has published."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graph.toml", *options],
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
@pytest.mark.slow
def test_a_signal_on_the_wall_clock_stops_gracefully_without_traceback(signum):
    with running_demo() as proc:
        proc.send_signal(signum)
        out, err = proc.communicate(timeout=5)
    assert proc.returncode == 0, err
    assert "Traceback" not in out + err


@pytest.mark.slow
def test_ctrl_c_while_the_graph_is_still_spawning_stops_it_gracefully(run_module, tmp_path):
    # The signal receiver is in place before the first node is made: a Ctrl-C that comes as
    # soon as a node exists (the README's test sends it once every node shows) is a graceful stop.
    graph = tmp_path / "interrupted.toml"
    graph.write_text('[runtime]\nduration = 60\n\n[[nodes]]\nuse = "graph_nodes:InterruptedAtStart"\n')
    result = run_module("actors.run", str(graph), timeout=30)
    assert (result.returncode, result.stderr) == (0, "")


@pytest.mark.parametrize("loop", ["uvloop", "asyncio"])
@pytest.mark.slow
def test_the_demo_runs_on_the_loop_asked_for_and_stops_gracefully(loop):
    pytest.importorskip(loop)
    with running_demo("--loop", loop) as proc:
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=5)
    assert proc.returncode == 0, err  # running_demo saw it publish before the signal
    assert "Traceback" not in out + err


@pytest.mark.slow
def test_a_loop_on_virtual_time_is_refused(run_module):
    result = run_module("actors.run", "graph.toml", "--clock", "virtual", "--duration", "1", "--loop", "uvloop")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == "error: --loop uvloop is for the wall clock; virtual time runs on its own loop\n"


def test_uvloop_missing_is_exit_2_with_the_install_hint(monkeypatch, capsys):
    from actors import run

    monkeypatch.setitem(sys.modules, "uvloop", None)  # as if not installed
    assert run.main(["graph.toml", "--loop", "uvloop"]) == 2
    assert capsys.readouterr().err == "error: --loop uvloop: uvloop is not installed: pip install 'actors[fast]'\n"


def test_a_uvloop_that_does_not_load_is_exit_2_saying_why(monkeypatch, capsys, tmp_path):
    from actors import run

    broken_uvloop(monkeypatch, tmp_path)
    assert run.main(["graph.toml", "--loop", "uvloop"]) == 2
    assert capsys.readouterr().err == (
        "error: --loop uvloop: uvloop does not load (libuv is missing here): pip install 'actors[fast]'\n"
    )


def broken_uvloop(monkeypatch: pytest.MonkeyPatch, folder: Path) -> None:
    """A uvloop that is installed but does not import (built for another Python, libuv missing)."""
    (folder / "uvloop").mkdir()
    (folder / "uvloop" / "__init__.py").write_text('raise ImportError("libuv is missing here")\n')
    monkeypatch.delitem(sys.modules, "uvloop", raising=False)
    monkeypatch.syspath_prepend(str(folder))


@pytest.mark.slow
def test_the_services_graph_waits_for_its_servers_then_succeeds(run_module):
    result = run_module("actors.run", "graphs/services.toml", "--clock", "virtual", "--duration", "5")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    waiting = out.index("[minimal_client_async]: service not available, waiting again...")
    answered = out.index("[minimal_client_async]: Result of add_two_ints: for 41 + 1 = 42")
    assert waiting < out.index("[minimal_service]: Incoming request\na: 41 b: 1") < answered
    assert "[add_three_ints_client]: Result of add_three_ints: for 2 + 3 + 1 = 6" in out


@pytest.mark.slow
def test_a_parameter_override_of_the_wrong_type_exits_2(run_module, tmp_path):
    graph = tmp_path / "params.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.param_talker:MinimalParam"\nparams = { my_parameter = 3 }\n')
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "1")
    assert result.returncode == 2
    assert result.stderr.strip() == (
        f"error: {graph}: nodes[0] (nodes.param_talker:MinimalParam): parameter 'my_parameter' of "
        "/minimal_param_node: Wrong parameter type, expected 'Type.STRING' got 'Type.INTEGER'"
    )


@pytest.mark.slow
def test_the_params_graph_with_an_override(run_module, tmp_path):
    graph = tmp_path / "params.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.param_talker:MinimalParam"\nparams = { my_parameter = "earth" }\n')
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "2.5")
    hellos = re.findall(r"\[minimal_param_node\]: (Hello \w+!)", result.stdout)
    assert hellos == ["Hello earth!", "Hello world!"]


@pytest.mark.slow
def test_actors_launch_is_python_m_actors_run(run_module, tmp_path):
    args = ("--clock", "virtual", "graphs/services.toml", "--duration", "3")
    launched = run_module("actors", "launch", *args)
    ran = run_module("actors.run", *args)
    assert (launched.returncode, launched.stdout) == (ran.returncode, ran.stdout) == (0, ran.stdout)
    assert "Result of add_two_ints: for 41 + 1 = 42" in launched.stdout
    usage = run_module("actors", "launch", "--clock", "sundial", "graph.toml")
    assert usage.returncode == 2 and usage.stderr.startswith("usage: actors launch ")
