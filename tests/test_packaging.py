"""What a non-editable install holds, and that it runs beside a user's own ``world.py`` and ``nodes/`` (issue 15).

pyproject.toml lists every package by name (nodes/, world/ and graphs/ install
as actors.nodes, actors.world and actors.graphs); the first test fails when a
package of the tree is missing there, the second installs the project for real.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from conftest import ROOT

SETUPTOOLS = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]


def installed_name(folder: Path) -> str:
    """The package name a folder of the tree installs as."""
    dotted = ".".join(folder.relative_to(ROOT).parts)
    for name, source in SETUPTOOLS["package-dir"].items():
        if dotted == source or dotted.startswith(source + "."):
            return name + dotted[len(source) :]
    return dotted


def test_every_package_of_the_tree_is_listed_in_pyproject():
    tops = ["actors", "interfaces", *SETUPTOOLS["package-dir"].values()]
    folders = {p.parent for top in tops for p in (ROOT / top).rglob("__init__.py")}
    folders |= {p.parent for p in (ROOT / "world" / "worlds").glob("*.toml")}  # data only: no __init__.py
    expected = sorted(installed_name(f) for f in folders if "__pycache__" not in f.parts)
    assert sorted(SETUPTOOLS["packages"]) == expected


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    """The project installed (not editable) into a folder of its own, from a copy of this tree."""
    tmp = tmp_path_factory.mktemp("install")
    source = tmp / "source"
    shutil.copytree(
        ROOT,
        source,
        ignore=shutil.ignore_patterns(".git", ".venv*", "build", "dist", "*.egg-info", "__pycache__", ".*cache"),
    )
    target = tmp / "site"
    done = subprocess.run(
        [sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(target), str(source)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    return target


@pytest.mark.slow
def test_installed_shipped_graphs_and_a_users_own_graph_each_run_their_own_code(installed, tmp_path):
    student = tmp_path / "student"
    (student / "nodes").mkdir(parents=True)
    (student / "world.py").write_text("print('the student world.py ran')\n")
    (student / "nodes" / "__init__.py").write_text("")
    (student / "nodes" / "constant_control.py").write_text(
        "from actors import Node\n\n\nclass Mine(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('mine')\n"
        "        import world  # the student's own world.py\n"
        "        self.get_logger().info('the student node runs')\n"
    )
    (student / "graph.toml").write_text('[[nodes]]\nuse = "nodes.constant_control:Mine"\n')
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env |= {"PYTHONPATH": str(installed), "PYTHONUNBUFFERED": "1", "XDG_RUNTIME_DIR": str(tmp_path)}

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", "actors.run", *args, "--clock", "virtual", "--duration", "3"],
            cwd=student,
            env=env,
            capture_output=True,
            text=True,
            timeout=60,
        )

    where = subprocess.run(
        [sys.executable, "-c", "import actors; print(actors.__file__)"],
        cwd=student,
        env=env,
        capture_output=True,
        text=True,
    )
    assert Path(where.stdout.strip()).is_relative_to(installed)  # this copy, not the repository's editable one

    shipped = run("turtlebot")  # a shipped graph by its name
    assert shipped.returncode == 0, shipped.stderr
    assert "[constant_control]: sending constant control..." in shipped.stdout
    assert "student" not in shipped.stdout + shipped.stderr

    demo = run("demo")  # the headline demo, the repository's graph.toml, by name from anywhere
    assert demo.returncode == 0, demo.stderr
    assert all(
        f"[{node}]" in demo.stdout for node in ("minimal_publisher", "add_three_ints_client", "constant_control")
    )
    assert "student" not in demo.stdout + demo.stderr

    also_shipped = run(str(installed / "actors" / "graphs" / "pubsub.toml"))  # and by its path
    assert also_shipped.returncode == 0, also_shipped.stderr
    assert "[minimal_publisher]: Publishing: " in also_shipped.stdout

    own = run("graph.toml")
    assert own.returncode == 0, own.stderr
    assert "the student world.py ran" in own.stdout
    assert "[mine]: the student node runs" in own.stdout
