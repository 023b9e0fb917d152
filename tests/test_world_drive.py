"""Differential-drive robots: limits, unicycle accuracy, stopping at walls, obstacles, robots."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import pytest

from world.arena import World, posts, solids
from world.drive import MODELS, Contact, Robot
from world.simulation import Simulation

DT = 0.01
MINUTE = 6000  # steps of DT


def gap_to_polygon(robot: Robot, vertices: tuple[tuple[float, float], ...]) -> float:
    """Distance (m) from the robot's edge to the polygon's surface; negative when they overlap."""
    x, y, _ = robot.pose
    nearest, inside = math.inf, False
    for (ax, ay), (bx, by) in zip(vertices, vertices[1:] + vertices[:1]):
        ex, ey = bx - ax, by - ay
        s = min(max(((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey), 0.0), 1.0)
        nearest = min(nearest, math.hypot(ax + s * ex - x, ay + s * ey - y))
        if (ay > y) != (by > y) and x < ax + (y - ay) * ex / ey:
            inside = not inside
    return (-nearest if inside else nearest) - robot.model.radius


def gap_between(a: Robot, b: Robot) -> float:
    return math.dist(a.pose[:2], b.pose[:2]) - a.model.radius - b.model.radius


def gap_to(robot: Robot, name: str, world: World) -> float:
    """Distance (m) from the robot's edge to the named obstacle; negative when they overlap."""
    for solid in solids(world):
        if solid.name == name:
            return gap_to_polygon(robot, solid.vertices)
    (post,) = [p for p in posts(world) if p.name == name]
    return math.dist(robot.pose[:2], post.center) - post.radius - robot.model.radius


def drive_for(sim: Simulation, steps: int, watch: Callable[[], float] = lambda: 0.0) -> float:
    """Step ``steps`` times and return the smallest value ``watch()`` took after any step."""
    smallest = math.inf
    for _ in range(steps):
        sim.step()
        smallest = min(smallest, watch())
    return smallest


def assert_stops_flush(sim: Simulation, gap: Callable[[], float]) -> None:
    """Drive a simulated minute: the gap never goes below -1 mm, and ends within 2 mm of zero."""
    assert drive_for(sim, MINUTE, gap) > -0.001, "went into it"
    assert abs(gap()) < 0.002, "did not come to rest against it"


# --- limits -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("model", "command", "expected"),
    [
        ("burger", (1.0, 5.0), (0.22, 2.84)),
        ("burger", (-1.0, -5.0), (-0.22, -2.84)),
        ("burger", (0.1, -1.0), (0.1, -1.0)),
        ("asl_tb3", (1.0, 5.0), (0.5, 1.0)),
        ("asl_tb3", (-1.0, -5.0), (-0.5, -1.0)),
    ],
)
def test_commands_are_clipped(model: str, command: tuple[float, float], expected: tuple[float, float]) -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", model)
    robot.command(*command)
    drive_for(sim, 200)
    assert robot.twist == pytest.approx(expected)
    assert robot.commanded == command


def test_burger_has_no_acceleration_limit() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", "burger")
    robot.command(0.22, -2.84)
    sim.step()
    assert robot.twist == (pytest.approx(0.22), -2.84)
    robot.command(-0.22, 2.84)
    sim.step()
    assert robot.twist == (pytest.approx(-0.22), 2.84)


def test_asl_tb3_ramps_at_its_accelerations() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", "asl_tb3")
    robot.command(0.5, -1.0)
    seen = []
    for _ in range(60):
        sim.step()
        seen.append(robot.twist)
    # 1 m/s^2 and 2 rad/s^2: +0.01 m/s and -0.02 rad/s per step until the limits.
    assert seen[0] == (pytest.approx(0.01), pytest.approx(-0.02))
    assert seen[24] == (pytest.approx(0.25), pytest.approx(-0.5))
    assert seen[49] == (pytest.approx(0.5), pytest.approx(-1.0))
    assert seen[59] == (pytest.approx(0.5), pytest.approx(-1.0))
    robot.command(-0.5, 1.0)  # reversing ramps down through zero at the same rates
    sim.step()
    assert robot.twist == (pytest.approx(0.49), pytest.approx(-0.98))


@pytest.mark.parametrize("bad", [float("nan"), float("inf")])
def test_non_finite_commands_are_refused(bad: float) -> None:
    robot = Simulation.from_file("empty").add_robot("r")
    robot.command(0.1, 0.2)
    with pytest.raises(ValueError, match="robot 'r': command must be finite"):
        robot.command(bad, 0.0)
    assert robot.commanded == (0.1, 0.2)


def test_limits_are_pure() -> None:
    model = MODELS["asl_tb3"]
    assert model.limit(2.0, 0.0, 0.0, 0.0, 0.1) == pytest.approx((0.1, 0.0))
    assert model.limit(0.3, 0.5, 0.25, 0.4, 0.1) == pytest.approx((0.3, 0.5))
    assert MODELS["burger"].limit(0.2, 0.0, -0.2, 0.0, 0.01) == (0.2, 0.0)


# --- free motion ------------------------------------------------------------------


def test_arc_follows_exact_unicycle_kinematics() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", x=-1.0, y=0.5, theta=0.3)
    v, w = 0.2, 0.5
    robot.command(v, w)
    for k in range(1, 1001):
        sim.step()
        t = k * DT
        theta = 0.3 + w * t
        x = -1.0 + v / w * (math.sin(theta) - math.sin(0.3))
        y = 0.5 - v / w * (math.cos(theta) - math.cos(0.3))
        pose = robot.pose
        # 5 mm is the requirement; moving along the chord of each step's arc makes it exact,
        # where the heading at the start of each step would be about 1 mm off.
        assert math.hypot(pose.x - x, pose.y - y) < 1e-6, f"off the arc at t={t:.2f} s"
        assert abs(math.remainder(pose.theta - theta, math.tau)) < 1e-6
    assert robot.twist == (pytest.approx(v), w)
    assert not robot.in_contact and robot.contacts == ()


def test_straight_line_and_turn_in_place() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", theta=math.pi / 2)
    robot.command(0.2, 0.0)
    drive_for(sim, 500)
    assert robot.pose == pytest.approx((0.0, 1.0, math.pi / 2), abs=1e-9)
    robot.command(0.0, -1.0)
    drive_for(sim, 100)
    assert robot.pose == pytest.approx((0.0, 1.0, math.pi / 2 - 1.0), abs=1e-9)


def test_theta_is_wrapped_to_pi() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", theta=3.0)
    robot.command(0.0, 1.0)
    drive_for(sim, 100)
    assert robot.pose.theta == pytest.approx(4.0 - math.tau)


# --- stopping -----------------------------------------------------------------------


@pytest.mark.parametrize("model", ["burger", "asl_tb3"])
def test_stops_at_a_wall_without_passing_or_creeping(model: str) -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", model, x=4.0, y=0.0)
    robot.command(1.0, 0.0)
    assert_stops_flush(sim, lambda: 5.0 - robot.pose.x - robot.model.radius)  # the inner face is at x = 5
    assert robot.contacts == (Contact("wall", None),) and robot.in_contact
    assert robot.pose == (pytest.approx(4.895, abs=0.002), 0.0, 0.0)  # no bounce, no spin, no drift
    resting = robot.pose
    drive_for(sim, 100)
    assert robot.pose == resting  # no jitter either
    assert robot.twist == (pytest.approx(0.0, abs=1e-9), 0.0)


def test_stalls_at_a_wall_met_at_an_angle_until_it_turns_away() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", x=4.5, y=3.0, theta=0.4)
    robot.command(0.22, 0.0)
    assert_stops_flush(sim, lambda: 5.0 - robot.pose.x - robot.model.radius)
    # Wheels do not slip sideways: no sliding along the wall.
    assert robot.pose.y == pytest.approx(3.0 + (4.895 - 4.5) * math.tan(0.4), abs=0.002)
    assert robot.twist == (pytest.approx(0.0, abs=1e-9), 0.0) and robot.pose.theta == 0.4
    robot.command(0.22, 2.0)
    drive_for(sim, 100)
    assert robot.contacts == () and robot.pose.x < 4.87  # free again once it faces away


def test_pushing_while_turning_keeps_the_heading_rate_and_the_wall() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", x=4.8, y=0.0)
    robot.command(0.22, 0.5)
    before = robot.pose.theta
    assert drive_for(sim, 100, lambda: 5.0 - robot.pose.x - robot.model.radius) > -0.001
    assert robot.pose.theta == pytest.approx(before + 0.5, abs=1e-9)


@pytest.mark.parametrize(
    ("name", "start"),
    [
        ("box_east", (0.5, 0.0, 0.0)),
        ("box_west", (-1.0, -1.5, math.pi / 2)),  # turned 1.2 rad: met on a corner-ish face
        ("stop_sign", (0.15, -1.0, -math.pi / 2)),
    ],
)
def test_stops_at_an_obstacle(name: str, start: tuple[float, float, float]) -> None:
    sim = Simulation.from_file("signs")
    x, y, theta = start
    robot = sim.add_robot("r", x=x, y=y, theta=theta)
    robot.command(0.22, 0.0)
    assert_stops_flush(sim, lambda: gap_to(robot, name, sim.world))
    assert robot.contacts == (Contact("obstacle", name),)


def test_stops_in_a_concave_polygon_corner(tmp_path: Path) -> None:
    path = tmp_path / "ell.toml"
    path.write_text(
        "bounds = { min = [-3, -3], max = [3, 3] }\n"
        "[[polygons]]\nname = 'ell'\nvertices = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]\n"
    )
    sim = Simulation.from_file(path)
    # Into the inner corner at (1, 1) along the diagonal: it must stop against both edges.
    robot = sim.add_robot("r", x=2.0, y=2.0, theta=-3 * math.pi / 4)
    robot.command(0.22, 0.0)
    assert_stops_flush(sim, lambda: gap_to(robot, "ell", sim.world))
    assert robot.pose[:2] == pytest.approx((1.105, 1.105), abs=0.002)


def test_stops_at_a_standing_robot_without_pushing_it() -> None:
    sim = Simulation.from_file("empty")
    mover = sim.add_robot("mover", "asl_tb3", x=0.0, y=0.0)
    still = sim.add_robot("still", x=1.0, y=0.05)
    mover.command(0.5, 0.0)
    assert_stops_flush(sim, lambda: gap_between(mover, still))
    assert still.pose == pytest.approx((1.0, 0.05, 0.0), abs=1e-6)
    assert mover.contacts == (Contact("robot", "still"),)
    assert still.contacts == (Contact("robot", "mover"),)


def test_robots_meeting_head_on_both_stop() -> None:
    sim = Simulation.from_file("empty")
    a = sim.add_robot("a", x=-1.0)
    b = sim.add_robot("b", x=1.0, theta=math.pi)
    a.command(0.22, 0.0)
    b.command(0.22, 0.0)
    assert_stops_flush(sim, lambda: gap_between(a, b))
    assert a.pose.x == pytest.approx(-b.pose.x)


@pytest.mark.slow
def test_a_crowd_never_overlaps() -> None:
    sim = Simulation.from_file("signs")
    rows = (-2.5, 1.0, 2.2)
    robots = [
        sim.add_robot(
            f"r{i}",
            "asl_tb3" if i % 2 else "burger",
            x=-2.4 + 0.6 * (i % 9),
            y=rows[i // 9],
            theta=i,
        )
        for i in range(27)
    ]
    for i, robot in enumerate(robots):
        robot.command(0.5, 0.3 * math.sin(i))

    def worst() -> float:
        return min(gap_between(a, b) for i, a in enumerate(robots) for b in robots[i + 1 :])

    assert drive_for(sim, 1000, worst) > -0.001


def test_twist_reports_blocked_motion_and_odometry_is_the_truth_without_noise() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r", x=4.8)
    robot.command(0.2, 0.1)
    drive_for(sim, 200)
    assert robot.twist == (pytest.approx(0.0, abs=1e-9), 0.1)  # stalled at the wall, turning
    assert robot.odometry() == (*robot.pose, *robot.twist)
