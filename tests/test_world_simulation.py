"""The Simulation: building a world, adding and removing robots, stepping, and determinism."""

from __future__ import annotations

import math

import numpy as np
import pytest

from actors.errors import WorldFileError
from world.drive import MODELS, RobotModel
from world.noise import Noise
from world.simulation import Simulation


def test_steps_advance_time() -> None:
    sim = Simulation.from_file("empty")
    assert (sim.time, sim.steps, sim.dt) == (0.0, 0, 0.01)
    sim.step()
    sim.step(0.05)
    assert sim.steps == 2 and sim.time == pytest.approx(0.06)
    with pytest.raises(ValueError, match="dt must be > 0"):
        sim.step(0.0)
    with pytest.raises(ValueError, match="dt must be > 0"):
        Simulation.from_file("empty", dt=-1.0)


def test_bad_world_file_raises_world_file_error(tmp_path) -> None:
    with pytest.raises(WorldFileError):
        Simulation.from_file(tmp_path / "missing.toml")


def test_add_and_remove_robots() -> None:
    sim = Simulation.from_file("signs")
    a = sim.add_robot("a", x=-2.0)
    custom = RobotModel(name="big", radius=0.3, max_linear=1.0, max_angular=1.0)
    b = sim.add_robot("b", custom, x=2.0, y=2.0)
    assert list(sim.robots) == ["a", "b"] and sim.robots["b"] is b and b.model.radius == 0.3
    with pytest.raises(TypeError):
        sim.robots["c"] = a  # type: ignore[index]
    sim.remove_robot("a")
    assert list(sim.robots) == ["b"]
    with pytest.raises(KeyError):
        sim.scan("a")
    sim.add_robot("a", x=-2.0)  # the name and the place are free again
    sim.step()


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"name": "a"}, "a robot named 'a' already exists"),
        ({"name": "c", "model": "waffle"}, "unknown robot model 'waffle'; the models are burger, asl_tb3"),
        ({"name": "c", "x": 1.7}, "would start overlapping obstacle 'box_east'"),
        ({"name": "c", "x": 0.1, "y": -2.0}, "would start overlapping obstacle 'stop_sign'"),
        ({"name": "c", "x": 3.0}, "would start overlapping a wall"),
        ({"name": "c", "x": -2.0, "y": 0.1}, "would start overlapping robot 'a'"),
        ({"name": "c", "x": 9.0}, "outside the world's bounds"),
        ({"name": "c", "theta": float("nan")}, "start pose must be finite"),
    ],
)
def test_add_robot_rejects(kwargs: dict, message: str) -> None:
    sim = Simulation.from_file("signs")
    sim.add_robot("a", x=-2.0)
    with pytest.raises(ValueError, match=message):
        sim.add_robot(**kwargs)


def test_a_robot_may_start_near_another_robot() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("a")
    sim.add_robot("b", x=0.22)  # within a's sensing margin, but not touching
    assert sim.robots["a"].contacts == ()


NOISY = Noise(position=0.01, heading=0.01, linear=0.01, angular=0.01, ranges=0.01)


def run(seed_base: int, steps: int = 400) -> tuple[list, list, list]:
    """A busy run: robots on arcs meeting walls, boxes, each other; all poses, odometry, scans."""
    sim = Simulation.from_file("signs")
    for i in range(6):
        robot = sim.add_robot(
            f"r{i}",
            "asl_tb3" if i % 2 else "burger",
            x=-2.5 + i,
            y=1.0,
            theta=i,
            seed=seed_base + i,
            noise=NOISY,
        )
        robot.command(0.5, math.sin(i))
    poses, odometry, scans = [], [], []
    for k in range(steps):
        sim.step()
        poses.append([r.pose for r in sim.robots.values()])
        if k % 5 == 0:
            odometry.append([r.odometry() for r in sim.robots.values()])
        if k % 10 == 0:
            scans.append(np.stack(list(sim.scan_all().values())))
    return poses, odometry, scans


def test_same_seeds_give_identical_runs_and_other_seeds_other_noise() -> None:
    poses_a, odometry_a, scans_a = run(0)
    poses_b, odometry_b, scans_b = run(0)
    poses_c, odometry_c, scans_c = run(100)
    assert poses_a == poses_b and odometry_a == odometry_b
    assert all(np.array_equal(a, b) for a, b in zip(scans_a, scans_b))
    # Noise is in what sensors report, never in the physics.
    assert poses_a == poses_c
    assert odometry_a != odometry_c
    assert not any(np.array_equal(a, c) for a, c in zip(scans_a, scans_c))


def test_noise_is_off_by_default() -> None:
    sim = Simulation.from_file("signs")
    robot = sim.add_robot("r", seed=5)
    assert robot.noise == Noise()
    assert robot.odometry() == (*robot.pose, *robot.twist)


def test_models() -> None:
    assert set(MODELS) == {"burger", "asl_tb3"}
    assert MODELS["burger"].radius == 0.105 and MODELS["burger"].lidar.range_max == 3.5
