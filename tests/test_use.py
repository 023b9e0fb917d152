"""Where a graph's ``use`` comes from (issue 15, name clashes): the graph's folder, the working
directory, installed code.

Each case runs in a child Python (one process can hold one ``nodes``), with
nothing of the repository on its path: only the installed ``actors``.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT

from actors.errors import GraphFileError
from actors.launch.graph_file import load_graph
from actors.launch.importing import shipped_graphs

WHICH = (
    "import sys; from actors.launch.graph_file import load_graph; "
    "_, classes = load_graph(sys.argv[1]); "
    "print(*[f'{c.__module__}={sys.modules[c.__module__].__file__}' for c in classes])"
)


def child_env() -> dict[str, str]:
    """This environment without the repository on the path (the tests' own is pytest's, not the env's)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONUNBUFFERED"] = "1"
    return env


def which(graph: Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    """Load ``graph`` from ``cwd`` in a child Python; its stdout says ``module=file`` for each node class."""
    return subprocess.run(
        [sys.executable, "-c", WHICH, str(graph)], cwd=cwd, env=child_env(), capture_output=True, text=True, timeout=60
    )


def node_file(folder: Path, module: str, words: str) -> Path:
    """A module ``folder/module.py`` defining a node class ``Mine`` that logs ``words``."""
    path = folder / f"{module.replace('.', '/')}.py"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(
        "from actors import Node\n\n\nclass Mine(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('mine')\n"
        f"        self.get_logger().info({words!r})\n"
    )
    return path


def graph_file(folder: Path, use: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "graph.toml"
    path.write_text(f'[[nodes]]\nuse = "{use}"\n')
    return path


@pytest.mark.slow
def test_the_graph_folder_comes_before_the_working_directory(tmp_path):
    in_graph_folder = node_file(tmp_path / "project", "nodes.mine", "the graph folder's")
    node_file(tmp_path / "elsewhere", "nodes.mine", "the working directory's")
    graph = graph_file(tmp_path / "project", "nodes.mine:Mine")
    done = which(graph, cwd=tmp_path / "elsewhere")
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == [f"nodes.mine={in_graph_folder}"]


@pytest.mark.slow
def test_the_working_directory_comes_before_installed_code(tmp_path):
    mine = node_file(tmp_path / "work", "nodes.talker", "a talker of my own")  # the shipped one has this name too
    graph = graph_file(tmp_path / "graphs", "nodes.talker:Mine")
    done = which(graph, cwd=tmp_path / "work")
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == [f"nodes.talker={mine}"]


@pytest.mark.slow
def test_installed_nodes_and_world_are_the_shipped_ones_when_nothing_else_has_them(tmp_path):
    graph = tmp_path / "graph.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n[[nodes]]\nuse = "world.sim:World"\n')
    done = which(graph, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    import actors.nodes.talker
    import actors.world.sim

    assert done.stdout.split() == [
        f"actors.nodes.talker={actors.nodes.talker.__file__}",
        f"actors.world.sim={actors.world.sim.__file__}",
    ]


@pytest.mark.slow
def test_a_shipped_graph_uses_the_shipped_code_beside_a_users_own_nodes_and_world(tmp_path):
    node_file(tmp_path, "nodes.constant_control", "not the shipped controller")
    (tmp_path / "world.py").write_text("raise SystemExit('the student world.py was imported')\n")
    done = which(shipped_graphs() / "turtlebot.toml", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    modules = [pair.partition("=")[0] for pair in done.stdout.split()]
    assert modules == ["actors.world.sim", "actors.world.robot", "actors.nodes.constant_control"]
    assert str(tmp_path) not in done.stdout


@pytest.mark.slow
def test_a_module_missing_from_a_users_nodes_package_names_both_paths(tmp_path):
    (tmp_path / "nodes").mkdir()
    (tmp_path / "nodes" / "__init__.py").write_text("")
    node_file(tmp_path, "nodes.mine", "mine")
    graph = graph_file(tmp_path, "nodes.talker:MinimalPublisher")
    done = which(graph, cwd=tmp_path)
    import actors.nodes.talker

    assert done.returncode == 1
    (last,) = done.stderr.strip().splitlines()[-1:]
    assert last.endswith(
        f"{graph}: nodes[0].use: nodes.talker is not in your nodes ({tmp_path / 'nodes'}), which hides the shipped "
        f"nodes.talker ({actors.nodes.talker.__file__}): write actors.nodes.talker to use the shipped one, "
        "or rename yours"
    )


@pytest.mark.slow
def test_a_users_world_py_hiding_the_shipped_world_names_both_paths_and_exits_2(tmp_path):
    (tmp_path / "world.py").write_text("raise SystemExit('never imported to find out')\n")
    graph = graph_file(tmp_path, "world.sim:World")
    done = subprocess.run(
        [sys.executable, "-m", "actors.run", str(graph), "--clock", "virtual", "--duration", "1"],
        cwd=tmp_path,
        env=child_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    import actors.world

    assert done.returncode == 2
    assert done.stderr == (
        f"error: {graph}: nodes[0].use: world.sim: your world.py ({tmp_path / 'world.py'}) hides the shipped "
        f"package world ({Path(actors.world.__file__).parent}): rename yours, or write actors.world.sim\n"
    )


def test_a_shipped_graph_by_its_bare_name_and_an_unknown_one_listing_the_shipped(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _graph, classes = load_graph("pubsub")
    assert [c.__name__ for c in classes] == ["MinimalPublisher", "MinimalSubscriber", "Heartbeat"]
    with pytest.raises(GraphFileError) as caught:
        load_graph("turtlebt")
    known = ", ".join(sorted(p.stem for p in shipped_graphs().glob("*.toml")))
    assert str(caught.value) == (
        f"no graph file 'turtlebt' here, nor a shipped graph of that name (did you mean 'turtlebot'?); "
        f"the shipped graphs are {known}"
    )


@pytest.mark.slow
def test_the_repositorys_graph_toml_runs_the_shipped_demo_from_the_repositorys_files():
    # graph.toml includes graphs/demo.toml, a shipped graph: its nodes and world are the shipped
    # actors.nodes and actors.world, which an editable install takes from the repository's folders.
    done = which(ROOT / "graph.toml", cwd=ROOT)
    assert done.returncode == 0, done.stderr
    pairs = [pair.partition("=") for pair in done.stdout.split()]
    assert pairs and all(m.split(".")[:2] in (["actors", "nodes"], ["actors", "world"]) for m, _, _ in pairs)
    assert all(Path(f).is_relative_to(ROOT) for _, _, f in pairs)


@pytest.mark.slow
@pytest.mark.parametrize("where", ["graph folder", "installed"])
def test_a_node_module_whose_import_fails_is_one_line_naming_its_line_and_exits_2(tmp_path, where):
    # In the graph's folder the module is run from its file; otherwise it is imported by name.
    home = tmp_path / "home"
    home.mkdir()
    module = f"needs_missing_{where.split()[0]}"
    folder = tmp_path if where == "graph folder" else home
    (folder / f"{module}.py").write_text("import rclpy_helpers_nobody_installed\n")
    graph = graph_file(tmp_path, f"{module}:Mine")
    env = child_env()
    if where == "installed":
        env["PYTHONPATH"] = str(home)
    done = subprocess.run(
        [sys.executable, "-m", "actors.run", str(graph), "--clock", "virtual", "--duration", "1"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2
    assert done.stderr == (
        f"error: {graph}: nodes[0].use: cannot import '{module}': No module named "
        f"'rclpy_helpers_nobody_installed' ({folder / module}.py, line 1)\n"
    )
