"""SIGINT, SIGTERM and SIGHUP stop every long-running command cleanly, at any moment of its start-up.

Each entry point gets a signal at 0.05, 0.2 and 0.4 s after it was started and
once it runs (a line it prints says so), the three signals taking turns so that
every pair of signal and moment comes up: exit code 0, no traceback, no control
socket left behind.  Before a process has its handlers the system's defaults
apply and nothing of ours could help, so a moment is never earlier than the
handlers (read from ``/proc/PID/status``): on a loaded machine 0.05 s can come
before the interpreter itself is up.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from conftest import ROOT, python_env
from test_cli_live import GraphProcess

from actors import codec
from actors.recording.bag_writer import BagWriter
from interfaces.std_msgs.msg import String

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads handlers from /proc"),
]

SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
MOMENTS = (0.05, 0.2, 0.4, "running")


class Command(GraphProcess):
    """A command in the background, its output (stdout and stderr) collected line by line."""

    def __init__(self, argv: list[str], env: dict[str, str]) -> None:
        self.started = time.monotonic()
        self.lines = []
        self._changed = threading.Condition()
        self.proc = subprocess.Popen(
            argv, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
        )
        threading.Thread(target=self._read, daemon=True).start()

    def wait_for_handlers(self, timeout: float = 30) -> None:
        """Until the process catches all three signals (each is a bit of SigCgt, signal n at n-1)."""
        wanted = sum(1 << (s - 1) for s in SIGNALS)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                status = Path(f"/proc/{self.proc.pid}/status").read_text()
            except FileNotFoundError:
                break
            caught = int(next(line for line in status.splitlines() if line.startswith("SigCgt:")).split()[1], 16)
            if caught & wanted == wanted:
                return
            time.sleep(0.002)  # a poll of the kernel's view: no event tells when a handler goes in
        raise AssertionError(f"the handlers never went in:\n{''.join(self.lines[-20:])}")

    def finish(self, timeout: float = 30) -> str:
        try:
            self.proc.wait(timeout=timeout)
        finally:
            self.proc.kill()
        with self._changed:
            self._changed.wait_for(lambda: self.lines[-1:] == ["<exited>"], 5)
            return "".join(self.lines[:-1])


def stop_at(command: Command, moment: float | str, ready: str, signum: int, watch: Command | None = None) -> str:
    """Send ``signum`` at ``moment``: seconds after the start, or once ``ready`` shows (in ``watch``'s output)."""
    command.wait_for_handlers()
    if moment == "running":
        (watch or command).wait_for(ready)
    else:
        assert isinstance(moment, float)
        time.sleep(max(0.0, command.started + moment - time.monotonic()))  # a moment of start-up, by the wall clock
    command.proc.send_signal(signum)
    return command.finish()


def cases(entry: int) -> list[tuple[float | str, signal.Signals]]:
    # The signals take turns over moments and entry points: every pair comes up in the module.
    return [(moment, SIGNALS[(entry + i) % 3]) for i, moment in enumerate(MOMENTS)]


def check(command: Command, output: str, runtime_dir: Path | None = None) -> None:
    assert command.proc.returncode == 0, output
    assert "Traceback" not in output
    if runtime_dir is not None:
        assert list(runtime_dir.glob("actors/*.sock")) == [], output


def own_env(tmp_path: Path) -> dict[str, str]:
    env = python_env()
    env["XDG_RUNTIME_DIR"] = str(tmp_path)  # where the control socket goes: this test's alone
    return env


# --------------------------------------------------------------------------- commands that run a graph


@pytest.mark.parametrize(("moment", "signum"), cases(0))
def test_python_m_actors_run(tmp_path, moment, signum):
    command = Command([sys.executable, "-m", "actors.run", "graphs/pubsub.toml"], own_env(tmp_path))
    check(command, stop_at(command, moment, "I heard", signum), tmp_path)


@pytest.mark.parametrize(("moment", "signum"), cases(1))
def test_actors_launch(tmp_path, moment, signum):
    command = Command([sys.executable, "-m", "actors", "launch", "graphs/pubsub.toml"], own_env(tmp_path))
    check(command, stop_at(command, moment, "I heard", signum), tmp_path)


@pytest.mark.parametrize(("moment", "signum"), cases(2))
def test_actors_run_an_rclpy_script(tmp_path, moment, signum):
    command = Command([sys.executable, "-m", "actors", "run", "scripts/talker.py"], own_env(tmp_path))
    check(command, stop_at(command, moment, "sent count", signum), tmp_path)


# --------------------------------------------------------------------------- commands against a running graph


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[str, dict[str, str], Command]]:
    folder = tmp_path_factory.mktemp("signals")
    path = folder / f"signals_{os.getpid()}.toml"
    path.write_text((ROOT / "graphs/pubsub.toml").read_text())
    env = own_env(folder)
    running = Command([sys.executable, "-m", "actors.run", str(path)], env)
    try:
        running.wait_for("I heard")
        yield path.stem, env, running
    finally:
        running.proc.terminate()
        running.finish()


def cli(graph: tuple[str, dict[str, str], Command], *argv: str) -> Command:
    name, env, _ = graph
    return Command([sys.executable, "-m", "actors", *argv, "--graph", name], env)


@pytest.mark.parametrize(("moment", "signum"), cases(0))
def test_topic_echo(graph, moment, signum):
    command = cli(graph, "topic", "echo", "/topic")
    check(command, stop_at(command, moment, "data:", signum))


@pytest.mark.parametrize(("moment", "signum"), cases(1))
def test_topic_hz(graph, moment, signum):
    command = cli(graph, "topic", "hz", "/topic")
    check(command, stop_at(command, moment, "average rate", signum))


@pytest.mark.parametrize(("moment", "signum"), cases(2))
def test_bag_record(graph, tmp_path, moment, signum):
    command = cli(graph, "bag", "record", "/topic", "-o", str(tmp_path / "run.mcap"))
    output = stop_at(command, moment, "Recording to", signum)
    check(command, output)


def test_bag_record_keeps_its_bag_whole_through_a_second_ctrl_c_as_it_closes(graph, tmp_path, monkeypatch, capsys):
    from actors.cli import main
    from actors.recording.bag_writer import BagWriter

    write, close = BagWriter.write, BagWriter.close
    written = 0

    def first_press_at_the_third(self, *args):
        # Counted here: the writer's message_count goes by whole chunks, and may step over 3.
        nonlocal written
        write(self, *args)
        written += 1
        if written == 3:
            signal.raise_signal(signal.SIGINT)

    def second_press_as_it_closes(self, **kwargs):
        signal.raise_signal(signal.SIGINT)
        close(self, **kwargs)

    monkeypatch.setattr(BagWriter, "write", first_press_at_the_third)
    monkeypatch.setattr(BagWriter, "close", second_press_as_it_closes)
    monkeypatch.setenv("XDG_RUNTIME_DIR", graph[1]["XDG_RUNTIME_DIR"])
    bag = tmp_path / "run.mcap"
    try:
        code = main(["bag", "record", "/topic", "-o", str(bag), "--graph", graph[0]])
    except KeyboardInterrupt:
        pytest.fail("the second Ctrl-C cut the bag's closing short")
    assert code in (0, None)
    recorded = int(capsys.readouterr().err.rpartition("Recorded ")[2].split()[0])
    assert recorded >= 3  # the first press lands within a message or two of the third
    monkeypatch.undo()
    assert main(["bag", "info", str(bag)]) in (0, None)
    assert f"Messages:          {recorded}\n" in capsys.readouterr().out


@pytest.mark.parametrize(("moment", "signum"), cases(0))
def test_bag_play(graph, tmp_path, moment, signum):
    bag = BagWriter(tmp_path / "played.mcap")
    channel = bag.add_topic(
        "/topic", "std_msgs/msg/String", definition=codec.definition_text(String), type_hash=codec.type_hash(String)
    )
    for i in range(100):  # ten seconds of messages: still playing when the signal comes
        bag.write(channel, 1_000_000_000 + i * 100_000_000, codec.encode_cdr(String(data=f"played {i}")))
    bag.close()
    command = cli(graph, "bag", "play", str(tmp_path / "played.mcap"))
    # Running once the graph's listener hears what the bag holds.
    check(command, stop_at(command, moment, 'I heard: "played', signum, watch=graph[2]))


SIGNALLED_IMPORT = """\
import os, signal, time
os.kill(os.getpid(), signal.SIGHUP)  # lands while this module is being imported
time.sleep(0.05)
DONE = True
"""

IMPORTER = """\
import sys, time
from actors.core.signals import raise_stops
raise_stops()
try:
    import signalled
    print("imported", signalled.DONE)
    time.sleep(30)
    print("never interrupted")
except KeyboardInterrupt:
    print("interrupted", "after the import" if "signalled" in sys.modules else "inside the import")
"""


def import_signalled(tmp_path, module: str) -> subprocess.CompletedProcess[str]:
    """Run IMPORTER with ``module`` as the module it imports; what it printed."""
    (tmp_path / "signalled.py").write_text(module)
    (tmp_path / "importer.py").write_text(IMPORTER)
    env = python_env()
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), env.get("PYTHONPATH", "")])
    return subprocess.run(
        [sys.executable, str(tmp_path / "importer.py")], env=env, capture_output=True, text=True, timeout=60
    )


def test_a_stop_signal_inside_an_import_stops_the_command_once_the_import_is_done(tmp_path):
    # Raised inside an import it would break what the import was building: importlib's module
    # locks (a later import hung) or an extension's state (msgspec crashed making a decoder).
    done = import_signalled(tmp_path, SIGNALLED_IMPORT)
    assert done.stdout == "imported True\ninterrupted after the import\n", done.stdout + done.stderr


STUCK_IMPORT = """\
import os, signal, time
os.kill(os.getpid(), signal.SIGHUP)
while True:  # a module that never finishes importing
    time.sleep(0.01)
"""


def test_a_stop_inside_an_import_that_never_ends_still_stops_the_command(tmp_path):
    done = import_signalled(tmp_path, STUCK_IMPORT)
    assert done.stdout == "interrupted inside the import\n", done.stdout + done.stderr


def test_a_stop_while_the_options_are_parsed_ends_the_run_quietly(monkeypatch, tmp_path):
    # parse_intermixed_args changes argparse's actions for the while: a KeyboardInterrupt inside
    # left them half-changed (AttributeError: save_nargs).  The stop is noted, then honoured.
    import argparse

    import actors.run

    parse = argparse.ArgumentParser.parse_known_args
    parsed = []

    def interrupted(self, *args, **kwargs):
        os.kill(os.getpid(), signal.SIGINT)  # as a Ctrl-C in the middle of parsing
        result = parse(self, *args, **kwargs)
        parsed.append(True)  # the parse went on to its end
        return result

    monkeypatch.setattr(argparse.ArgumentParser, "parse_known_args", interrupted)
    previous = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
    try:
        assert actors.run.main([str(tmp_path / "never.toml"), "--clock", "virtual"]) == 0
        assert parsed  # and then the stop ended the run, before the graph (there is none) was read
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
