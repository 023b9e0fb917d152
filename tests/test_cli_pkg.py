"""``actors pkg create``: the package it writes runs and passes its test as made (acceptance 3)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import python_env

from actors.cli import main


def run(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` in ``cwd`` as a user would run it: the installed actors, not the checkout's path."""
    env = {**python_env(), "PYTHONPATH": ""}
    return subprocess.run([sys.executable, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def create(capsys, *args: str) -> tuple[int, str, str]:
    """``actors pkg create ARGS`` in this process (the folder is the working directory): code, stdout, stderr."""
    code = main(["pkg", "create", *args])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.slow
def test_a_created_package_runs_its_node_and_passes_its_test(tmp_path):
    created = run(tmp_path, "-m", "actors", "pkg", "create", "my_pkg", "--node-name", "my_node")
    assert (created.returncode, created.stderr) == (0, ""), created.stderr
    lines = created.stdout.splitlines()
    assert lines[:4] == [
        "going to create a new package",
        "package name: my_pkg",
        f"destination directory: {tmp_path}",
        "node_name: my_node",
    ]
    package = tmp_path / "my_pkg"
    assert f"creating {Path('my_pkg') / 'my_pkg' / 'my_node.py'}" in lines
    assert sorted(str(p.relative_to(package)) for p in package.rglob("*") if p.is_file()) == [
        "README.md",
        "graph.toml",
        "my_pkg/__init__.py",
        "my_pkg/my_node.py",
        "pyproject.toml",
        "tests/test_my_node.py",
    ]

    ran = run(package, "-m", "actors.run", "graph.toml", "--clock", "virtual", "--duration", "3")
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout.splitlines() == [
        f'[INFO] [{t}.000000000] [my_node]: Publishing: "Hello from my_node: {t - 1}"' for t in (1, 2, 3)
    ]

    tested = run(package, "-m", "pytest")
    assert tested.returncode == 0, tested.stdout[-3000:]
    assert "1 passed" in tested.stdout


def test_the_package_readme_says_how_to_run_and_test_it(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert create(capsys, "rover")[0] == 0
    readme = (tmp_path / "rover" / "README.md").read_text()
    assert "python -m actors.run graph.toml --clock virtual --duration 3" in readme
    assert "python -m pytest" in readme
    assert (tmp_path / "rover" / "rover" / "rover_node.py").exists()  # the default node name
    assert 'use = "rover.rover_node:RoverNode"' in (tmp_path / "rover" / "graph.toml").read_text()


@pytest.mark.parametrize(
    ("args", "error"),
    [
        (("My-Pkg",), "invalid package name 'My-Pkg'"),
        (("ok_pkg", "--node-name", "9lives"), "invalid node name '9lives'"),
        (("json",), "a module named 'json' can already be imported"),
        (("tests",), "package name 'tests' cannot be a Python module's"),
        (("twin", "--node-name", "twin"), "the node cannot be named as its package ('twin')"),
    ],
)
def test_a_bad_name_is_one_line_exit_2_and_writes_nothing(tmp_path, monkeypatch, capsys, args, error):
    monkeypatch.chdir(tmp_path)
    code, out, err = create(capsys, *args)
    assert code == 2 and out == ""
    assert err.startswith(f"actors: {error}") and len(err.splitlines()) == 1
    assert os.listdir(tmp_path) == []


def test_an_existing_folder_is_left_alone(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "my_pkg").mkdir()
    (tmp_path / "my_pkg" / "mine.txt").write_text("keep")
    code, _, err = create(capsys, "my_pkg")
    assert code == 2
    assert err.startswith("actors: my_pkg already exists")
    assert os.listdir(tmp_path / "my_pkg") == ["mine.txt"]
