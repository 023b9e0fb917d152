"""``actors run PKG EXE``: a package's executable as ``ros2 run`` runs it, with no build step (issue 31)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import TESTS, python_env

WORKSPACE = TESTS / "workspaces" / "greeter_ws"


def actors(*args: str, cwd: Path = WORKSPACE) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "actors", *args], cwd=cwd, env=python_env(), capture_output=True, text=True, timeout=60
    )


@pytest.mark.slow
def test_an_rclpy_entry_point_with_its_params_file_found_through_the_share_folder():
    share = actors("pkg", "prefix", "--share", "greeter").stdout.strip()
    done = actors(
        "run", "--clock", "virtual", "--duration", "1.2", "greeter", "greeter",
        "--ros-args", "--params-file", f"{share}/config/params.yaml", "-r", "__ns:=/robot1",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert done.stderr.splitlines() == [
        f"[INFO] [{t:.9f}] [robot1.greeter]: Hello from the params file #{i}" for i, t in enumerate((0.5, 1.0))
    ]


@pytest.mark.slow
def test_a_native_node_as_a_shipped_packages_executable_takes_its_ros_arguments():
    done = actors(
        "run", "--clock", "virtual", "--duration", "1.1", "actors_tutorials", "talker",
        "--ros-args", "-r", "__node:=speaker", "-r", "topic:=chatter",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert done.stderr.splitlines() == [
        f'[INFO] [{0.5 * (i + 1):.9f}] [speaker]: Publishing: "Hello World: {i}"' for i in range(2)
    ]


@pytest.mark.slow
def test_the_shipped_demo_talkers_count_and_quote_as_their_packages_do():
    for package, lines in (
        ("demo_nodes_cpp", ["Publishing: 'Hello World: 1'", "Publishing: 'Hello World: 2'"]),
        ("demo_nodes_py", ['Publishing: "Hello World: 0"', 'Publishing: "Hello World: 1"']),
    ):
        done = actors("run", "--clock", "virtual", "--duration", "2.5", package, "talker")
        assert done.returncode == 0, done.stderr
        assert done.stderr.splitlines() == [
            f"[INFO] [{t}.000000000] [talker]: {line}" for t, line in zip((1, 2), lines)
        ]


@pytest.mark.slow
def test_a_native_partner_of_a_native_program_stops_at_the_end_of_the_duration():
    # It used to go on for ten seconds more: stopping it waited for a thread that only the run's end ended.
    done = actors(
        "run", "--clock", "virtual", "--duration", "3", "--with", "turtlesim turtlesim_node", "turtlesim", "draw_square"
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    stamps = [float(line.split("] [")[1]) for line in done.stderr.splitlines() if line.startswith("[INFO] [")]
    assert any("[draw_square]: Reached goal" in line for line in done.stderr.splitlines())
    assert stamps and max(stamps) <= 3.0, done.stderr


@pytest.mark.slow
@pytest.mark.parametrize(
    ("args", "problem"),
    [
        (("nope", "x"), "error: package 'nope' not found"),
        (("greeter", "talker"), "error: no executable 'talker' in package 'greeter'"),
        (("greeter",), "error: actors run greeter: name one of package 'greeter''s executables after it"),
    ],
)
def test_no_such_package_or_executable_is_one_line_and_exit_2(args, problem):
    done = actors("run", *args)
    assert done.returncode == 2
    assert done.stderr.startswith(problem) and done.stderr.count("\n") == 1, done.stderr


@pytest.mark.slow
def test_a_package_ros2_pkg_create_lays_out_runs_with_no_build_step(tmp_path):
    (tmp_path / "ws" / "src").mkdir(parents=True)
    created = actors(
        "pkg",
        "create",
        "--build-type",
        "ament_python",
        "hello_pkg",
        "--node-name",
        "hello",
        cwd=tmp_path / "ws" / "src",
    )
    assert created.returncode == 0, created.stderr
    package = tmp_path / "ws" / "src" / "hello_pkg"
    assert sorted(str(p.relative_to(package)) for p in package.rglob("*") if p.is_file()) == [
        "hello_pkg/__init__.py",
        "hello_pkg/hello.py",
        "package.xml",
        "resource/hello_pkg",
        "setup.cfg",
        "setup.py",
    ]
    assert "build type: ament_python" in created.stdout.splitlines()
    assert actors("pkg", "executables", "hello_pkg", cwd=tmp_path / "ws").stdout == "hello_pkg hello\n"
    ran = actors("run", "hello_pkg", "hello", cwd=tmp_path / "ws")
    assert (ran.returncode, ran.stdout, ran.stderr) == (0, "Hi from hello_pkg.\n", "")
