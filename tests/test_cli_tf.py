"""``actors tf frames``: a running graph's frame tree, written as view_frames writes it, beside the graph."""

from __future__ import annotations

import re
import time

import anyio
import pytest
from test_tf_buffer import MovingWheel, StaticFrames, transform

from actors import Runtime
from actors.cli import main
from actors.ops.control import ControlEndpoint
from actors.ros.topics import Publisher, Subscription, Topic

STATIC = (transform("world", "base_link", 0.0), transform("base_link", "camera", 0.0, (0.1, 0.0, 0.2)))
LISTENING = ["Listening to tf data for {} seconds...", "Generating graph...", "Exporting graph in {} file..."]


@pytest.fixture(autouse=True)
def endpoints(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    monkeypatch.setattr("shutil.which", lambda name: None)  # the picture drawn here, not by Graphviz


async def actors(capsys, *argv: str) -> tuple[int, str, str]:
    """``actors ARGS`` in a thread (the command line blocks), beside the graph on this loop."""
    code = await anyio.to_thread.run_sync(main, list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def edges(dot: str) -> set[tuple[str, str]]:
    return set(re.findall(r'^"(\w+)" -> "(\w+)"\[', dot, re.M))


@pytest.mark.virtual_time
async def test_the_static_frames_published_before_it_came_are_in_the_tree(capsys, tmp_path):
    async with Runtime(name="tf_frames", attach=[ControlEndpoint()]) as rt:
        rt.spawn(StaticFrames, *STATIC)
        rt.spawn(MovingWheel)
        await anyio.sleep(2.0)
        # Virtual time stands still while the command line's thread runs: nothing new is
        # published, so the static frames can only come from /tf_static's latched history.
        code, out, err = await actors(capsys, "tf", "frames", "-t", "0.2", "-o", str(tmp_path / "frames"))
    assert (code, err) == (0, "")
    svg = tmp_path / "frames.svg"
    assert out.splitlines() == [LISTENING[0].format(0.2), LISTENING[1], LISTENING[2].format(svg)]
    dot = (tmp_path / "frames.gv").read_text()
    assert edges(dot) == {("world", "base_link"), ("base_link", "camera")}  # the wheel's past /tf is not latched
    assert '"base_link" -> "camera"[label=" Broadcaster: default_authority\\nAverage rate: 10000.0\\n' in dot
    # recorded at the graph's time on a virtual clock, not this process's
    assert dot.endswith('"Recorded at time: 2.0"[ shape=plaintext ] ;\n}->"world";\n}')
    assert "<svg" in svg.read_text() and ">camera</text>" in svg.read_text()


async def test_dynamic_frames_are_heard_for_the_wait_time(capsys, tmp_path):
    # On the wall clock, as ros2's view_frames listens: the wheel's 10 Hz /tf arrives meanwhile.
    async with Runtime(name="tf_frames_wall", attach=[ControlEndpoint()]) as rt:
        rt.spawn(StaticFrames, *STATIC)
        rt.spawn(MovingWheel)
        before = time.time()
        code, out, err = await actors(capsys, "tf", "frames", "-t", "0.5", "-o", str(tmp_path / "wall"))
    assert (code, err) == (0, ""), out
    dot = (tmp_path / "wall.gv").read_text()
    assert edges(dot) == {("world", "base_link"), ("base_link", "camera"), ("base_link", "wheel")}
    wheel = re.search(r'"base_link" -> "wheel"\[label=" Broadcaster: default_authority\\nAverage rate: ([\d.]+)', dot)
    assert wheel and float(wheel[1]) > 0
    recorded = re.search(r'"Recorded at time: ([\d.]+)"', dot)
    assert recorded and before < float(recorded[1]) < time.time()  # this process's wall clock


async def test_a_graph_that_stops_while_it_listens_gives_what_it_sent(capsys, tmp_path):
    subscribed = anyio.Event()

    class Watch:
        def endpoint_added(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
            if (
                topic.name == "/tf_static"
                and isinstance(endpoint, Subscription)
                and "_actors_cli_" in endpoint.node.fqn
            ):
                subscribed.set()

        def endpoint_removed(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
            pass

    result: list[tuple[int, str, str]] = []
    async with anyio.create_task_group() as tg, Runtime(name="tf_frames_stops", attach=[ControlEndpoint()]) as rt:
        rt.topics.listeners.append(Watch())
        rt.spawn(StaticFrames, *STATIC)

        async def listen() -> None:
            result.append(await actors(capsys, "tf", "frames", "-t", "60", "-o", str(tmp_path / "cut")))

        tg.start_soon(listen)
        await subscribed.wait()  # then the runtime ends, long before the 60 s
    ((code, out, err),) = result
    assert code == 0, err
    assert err == "stopped listening: graph tf_frames_stops closed the connection (did it stop?)\n"
    assert out.splitlines()[1:] == [LISTENING[1], LISTENING[2].format(tmp_path / "cut.svg")]
    assert (tmp_path / "cut.gv").read_text().startswith("digraph G {")


@pytest.mark.virtual_time
async def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path):
    (tmp_path / "taken").write_text("a file where the folder should be")
    (tmp_path / "folder.gv").mkdir()
    cases = [
        (["-t", "0"], "actors: --wait-time 0.0: not a positive number of seconds\n"),
        (["-t", "nan"], "actors: --wait-time nan: not a positive number of seconds\n"),
        (
            ["-o", str(tmp_path / "taken" / "frames")],
            f"actors: -o {tmp_path}/taken/frames: no folder {tmp_path}/taken to write into\n",
        ),
        ([], "actors: no running actors graph found (start one with: python -m actors.run graph.toml)\n"),
    ]
    for argv, said in cases:
        assert await actors(capsys, "tf", "frames", *argv) == (2, "", said)
    async with Runtime(name="tf_frames_bad", attach=[ControlEndpoint()]) as rt:
        rt.spawn(StaticFrames, *STATIC)
        code, _, err = await actors(capsys, "tf", "frames", "-t", "0.05", "-o", str(tmp_path / "folder"))
    assert (code, err) == (2, f"actors: cannot write the frame tree to {tmp_path}/folder.gv: Is a directory\n")
