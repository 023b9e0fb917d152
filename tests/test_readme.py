"""The README's examples run as written: its code blocks are read from README.md when the tests run.

- ``sh`` blocks: every ``python -m actors.run ...`` / ``python -m actors launch ...``
  line runs a graph (virtual time to its end; the wall clock until its first
  line, then Ctrl-C); every other ``python -m actors ...`` line runs, in README
  order, against a graph started as the README starts it: the demo's
  (``graph.toml``), or the one a ``<!-- graph: FILE -->`` comment above the
  block names, up to the next such comment.
  Set-up and ``python -m bench`` lines are not run (they install packages or
  take minutes); a path under ``~/`` stands for the reader's own files.
  A command whose comment says ``exits N`` must exit N; every other must exit 0.
- ``python`` blocks: one with ``@pytest.mark`` or a ``def test_`` is a test file, run by
  pytest from the repository root in strict and in auto mode; one that calls ``anyio.run(`` is a script, run as
  one (its nodes must be heard on stderr); one that is lines from inside a
  method (a bare ``await``) must compile there; any other defines nodes, which
  are spawned on virtual time and must run without crashing.
- ``toml`` blocks are graph files, run on virtual time.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import os
import re
import shlex
import signal
import subprocess
import sys
import textwrap
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import NamedTuple

import anyio
import pytest
from conftest import ROOT, python_env

from actors import Node, Runtime
from actors.errors import ActorsError
from actors.ros.names import is_hidden

README = ROOT / "README.md"
FENCE = re.compile(r"^```(?P<lang>[a-z]*)\n(?P<body>.*?)^```$", re.MULTILINE | re.DOTALL)
GRAPH = re.compile(r"^<!-- graph: (\S+) -->$", re.MULTILINE)


def blocks(lang: str) -> list[str]:
    return [m["body"] for m in FENCE.finditer(README.read_text()) if m["lang"] == lang]


class Command(NamedTuple):
    words: list[str]
    expected: int  # the exit code
    graph: str  # the graph file it talks to
    line: str  # as written, for a shell


def commands() -> list[Command]:
    """Each ``python -m actors...`` line of the sh blocks, in README order.

    The graph a command talks to is the demo's, ``graph.toml``, unless a
    ``<!-- graph: FILE -->`` comment above its block names another.
    """
    text = README.read_text()
    found = []
    for match in FENCE.finditer(text):
        if match["lang"] != "sh":
            continue
        named = GRAPH.findall(text, 0, match.start())
        graph = named[-1] if named else "graph.toml"
        for line in match["body"].splitlines():
            words = shlex.split(line, comments=True)
            if words[:2] != ["python", "-m"] or not words[2].startswith("actors"):
                continue
            if any(word.startswith("~/") for word in words):
                continue
            expected = re.search(r"\bexits (\d)\b", line.partition(" #")[2])
            found.append(Command(words, int(expected[1]) if expected else 0, graph, line))
    return found


def runs_a_graph(words: list[str]) -> bool:
    """A graph file (or an rclpy script) run in the foreground, not a verb talking to one."""
    return words[2] == "actors.run" or words[2:4] in (["actors", "launch"], ["actors", "run"])


def until_interrupted(words: list[str]) -> bool:
    """A graph file run without a duration: on the wall clock, until Ctrl-C (``--show-args`` runs nothing)."""
    return words[2:4] != ["actors", "run"] and "--duration" not in words and "--show-args" not in words


def streams(words: list[str]) -> bool:
    """Whether the command runs until interrupted (as ros2's echo, hz, bw and pub do)."""
    verb = words[3:5]
    if verb in (["topic", "echo"],):
        return "--once" not in words
    if verb in (["topic", "hz"], ["topic", "bw"]):
        return "--count" not in words
    if verb == ["topic", "pub"]:
        return not {"--once", "-1", "-t", "--times"} & set(words)
    return False


@pytest.fixture
def private_endpoints(tmp_path_factory, monkeypatch) -> dict[str, str]:
    """A control-socket directory of the test's own: only the graphs it starts are found."""
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path_factory.mktemp("xdg")))
    return python_env()


def python(*args: str, env: dict[str, str], cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` to its end (bounded), output captured."""
    return subprocess.run([sys.executable, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def start(words: list[str], env: dict[str, str], cwd: Path = ROOT) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, *words[1:]],
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def first_line_then_interrupt(proc: subprocess.Popen[str]) -> tuple[str, str]:
    """Read stdout's first line (a streaming command's first report), then Ctrl-C."""
    assert proc.stdout is not None
    guard = threading.Timer(30, proc.kill)  # a command that never prints fails, not hangs
    guard.start()
    try:
        line = proc.stdout.readline()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        guard.cancel()
        proc.kill()
    return line + out, err


def test_the_readme_has_examples_of_every_kind():
    assert len(commands()) > 20
    assert blocks("python") and blocks("toml")


@pytest.mark.slow
def test_the_graph_commands_run_as_written(private_endpoints):
    seen = set()
    for words, expected, _, _ in commands():
        if not runs_a_graph(words) or tuple(words) in seen:
            continue
        seen.add(tuple(words))
        if not until_interrupted(words):
            result = python(*words[1:], env=private_endpoints)
            code, out, err = result.returncode, result.stdout, result.stderr
            assert "Traceback" not in out + err and "[FATAL]" not in err, (words, err)
            assert code == expected, (words, out[-2000:], err[-2000:])
        else:  # on the wall clock until Ctrl-C, as the README says: `running` checks the exit
            with running(words, private_endpoints):
                pass


@contextlib.contextmanager
def running(words: list[str], env: dict[str, str]) -> Iterator[subprocess.Popen[str]]:
    """A wall-clock graph started by ``words``, once every node of its file runs; then Ctrl-C."""
    from actors.cli._client import connect
    from actors.launch.graph_file import load_graph

    graph = next(word for word in words[3:] if word.endswith(".toml"))
    wanted = len(load_graph(ROOT / graph)[0].nodes)
    proc = start(words, env)
    try:
        deadline = time.monotonic() + 30
        while True:  # delayed nodes included: poll the graph until they are all there
            assert proc.poll() is None and time.monotonic() < deadline, proc.stderr
            with contextlib.suppress(ActorsError), connect(None) as conn:
                if len([n for n in conn.graph().nodes if not is_hidden(n.name)]) >= wanted:
                    break
            time.sleep(0.05)
        yield proc
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            out, err = proc.communicate(timeout=30)
        finally:
            proc.kill()
    assert proc.returncode == 0 and "Traceback" not in out + err, (words, err)


SHELL = {"&&", "||", "|", ">", ">>", "<", ";", "cd"}


def run_in_process(words: list[str]) -> tuple[int, str, str]:
    """``python -m actors ARGS`` through the same main() the command runs, its output captured."""
    from actors.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(words[3:])
        except SystemExit as exc:  # argparse's usage errors
            code = exc.code if isinstance(exc.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def run_in_a_shell(line: str, env: dict[str, str], cwd: Path) -> tuple[int, str, str]:
    """A line with shell syntax (``&&``, ``>``, ``cd``) as bash runs it, ``python`` being this one."""
    path = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    result = subprocess.run(
        ["bash", "-c", line], cwd=cwd, env={**env, "PATH": path}, capture_output=True, text=True, timeout=300
    )
    return result.returncode, result.stdout, result.stderr


@pytest.mark.slow
def test_the_second_terminal_commands_run_as_written(private_endpoints, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # what they write (graph.dot, a new package) lands here
    verbs = [c for c in commands() if not runs_a_graph(c.words)]
    assert len(verbs) > 15
    first = {c.graph: i for i, c in reversed(list(enumerate(verbs)))}
    verbs.sort(key=lambda c: first[c.graph])  # each graph started once; README order within it
    for graph, group in itertools.groupby(verbs, key=lambda c: c.graph):
        with running(["python", "-m", "actors.run", graph], private_endpoints):
            for words, expected, _, line in group:
                if SHELL & set(words):
                    code, out, err = run_in_a_shell(line, private_endpoints, tmp_path)
                elif streams(words):
                    proc = start(words, private_endpoints, cwd=tmp_path)
                    out, err = first_line_then_interrupt(proc)
                    code = proc.returncode
                else:
                    code, out, err = run_in_process(words)
                assert code == expected, (line, out[-3000:], err[-3000:])
                assert (err if expected == 0 else "") == "", (line, out[-3000:], err)
                assert out or err or ">" in words, line  # it said something (or wrote a file)


@pytest.mark.slow
def test_the_graph_file_examples_run(private_endpoints, tmp_path):
    example, with_arguments = blocks("toml")
    for name, text, argv, said in [
        ("example", example, [], ["[talker]: Publishing"]),
        ("args", with_arguments, ["who:=grace"], ["[talker_grace]: Publishing", "[robot1.constant_control]: sending"]),
    ]:
        graph = tmp_path / f"{name}.toml"
        graph.write_text(text)
        result = python(
            "-m", "actors.run", str(graph), *argv, "--clock", "virtual", "--duration", "2", env=private_endpoints
        )
        assert result.returncode == 0, result.stderr
        assert all(words in result.stdout for words in said), result.stdout


def python_blocks(kind: str) -> list[str]:
    def kind_of(body: str) -> str:
        try:
            compile(body, "README.md", "exec")
        except SyntaxError:
            return "fragment"  # lines from inside a method, e.g. with a bare await
        if "@pytest.mark" in body or re.search(r"^def test_", body, re.MULTILINE):
            return "test"
        return "script" if "anyio.run(" in body else "nodes"

    return [body for body in blocks("python") if kind_of(body) == kind]


@pytest.mark.parametrize("body", python_blocks("fragment"))
def test_the_fragments_are_python_inside_an_async_method(body):
    compile("async def method(self):\n" + textwrap.indent(body, "    "), "README.md", "exec")


@pytest.mark.parametrize("body", python_blocks("script"))
@pytest.mark.slow
def test_the_scripts_run_and_their_nodes_are_heard(body, private_endpoints, tmp_path):
    # Outside the repository, as a reader runs it: the shipped nodes come from the installed actors.
    script = tmp_path / "example.py"
    script.write_text(body)
    outside = {**private_endpoints, "PYTHONPATH": ""}
    result = python(str(script), env=outside, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert re.search(r"^\[INFO\] \[\d+\.\d{9}\] \[\w+\]: ", result.stderr, re.MULTILINE), result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("mode", ["strict", "auto"])
@pytest.mark.parametrize("body", python_blocks("test"))
@pytest.mark.slow
def test_the_test_examples_pass_in_any_asyncio_mode(body, mode, private_endpoints, tmp_path):
    (tmp_path / "test_example.py").write_text(body)
    options = ("-p", "no:cacheprovider", "-p", "no:hypothesispytest", "-o", f"asyncio_mode={mode}")
    # From the repository root: an example may name its files from there (the grading example).
    result = python("-m", "pytest", "-q", *options, str(tmp_path / "test_example.py"), env=private_endpoints)
    assert result.returncode == 0, result.stdout[-3000:]
    assert re.search(r"^\d+ passed", result.stdout, re.MULTILINE)


@pytest.mark.virtual_time
@pytest.mark.parametrize("body", python_blocks("nodes"))
async def test_the_node_examples_run_without_crashing(body):
    namespace: dict[str, object] = {"__name__": "readme_example"}
    exec(compile(body, "README.md", "exec"), namespace)
    classes = [v for v in namespace.values() if isinstance(v, type) and issubclass(v, Node) and v is not Node]
    assert classes
    async with Runtime(name="readme") as rt:
        for cls in classes:
            rt.spawn(cls)
        await anyio.sleep(3)
        infos = rt.graph.nodes()
    assert len(infos) == len(classes) and all(info.crashes == 0 for info in infos), infos
