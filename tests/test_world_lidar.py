"""The lidar: ranges against walls, obstacles and robots, as LaserScan reports them."""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pytest

from world.arena import load_world, posts, solids
from world.drive import RobotModel
from world.lidar import Lidar, LidarSpec, finish_ranges
from world.simulation import Simulation

BEAMS = 360


def test_forward_beam_reads_the_distance_to_a_wall() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("r", x=4.0, y=0.0)  # the wall's inner face is at x = 5
    ranges = sim.scan("r")
    assert ranges.shape == (BEAMS,) and ranges.dtype == np.float64
    assert ranges[0] == pytest.approx(1.0, abs=0.01)
    # 30 degrees off, the same wall is 1 / cos(30 deg) away.
    assert ranges[30] == pytest.approx(1.0 / math.cos(math.radians(30)), abs=0.01)
    assert ranges[330] == pytest.approx(ranges[30])


def test_beams_with_nothing_in_range_read_inf_and_the_own_body_is_not_seen() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("r")  # every wall is 5 m away, beyond the 3.5 m range
    assert np.all(sim.scan("r") == np.inf)


def test_beams_turn_counter_clockwise_from_the_heading() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("r", x=4.0, y=0.0, theta=math.pi / 2)
    ranges = sim.scan("r")
    assert ranges[270] == pytest.approx(1.0)  # the wall at +x is on the robot's right
    assert np.isinf(ranges[90])


def test_other_robots_appear_at_their_distance() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("me")
    sim.add_robot("ahead", x=2.0)
    sim.add_robot("left", y=1.0, model="asl_tb3")
    ranges = sim.scan("me")
    assert ranges[0] == pytest.approx(2.0 - 0.105)
    assert ranges[90] == pytest.approx(1.0 - 0.105)
    # Nothing else: 7 beams (+-3 deg) see the robot 2 m ahead, 13 (+-6 deg) the one 1 m away.
    assert np.count_nonzero(np.isfinite(ranges)) == 7 + 13
    assert sim.scan("ahead")[180] == pytest.approx(2.0 - 0.105)


def test_stop_sign_and_boxes_are_seen() -> None:
    sim = Simulation.from_file("signs")
    sim.add_robot("r", x=0.15, y=-1.0, theta=-math.pi / 2)
    ranges = sim.scan("r")
    assert ranges[0] == pytest.approx(1.0 - 0.05)  # the stop sign's post
    sim.add_robot("east", x=0.61, y=0.0)
    assert sim.scan("east")[0] == pytest.approx(1.36 - 0.61)  # the box's west face


def test_too_close_reads_minus_inf() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("a")
    sim.add_robot("b", x=0.215)  # touching: its surface is 0.11 m from a's centre
    assert sim.scan("a")[0] == -np.inf


def test_finish_ranges_marks_both_ends() -> None:
    spec = LidarSpec(range_min=0.1, range_max=2.0)
    ranges = finish_ranges(np.array([0.05, 0.1, 1.0, 2.0, 2.5, np.inf]), spec)
    assert ranges.tolist() == [-np.inf, 0.1, 1.0, 2.0, np.inf, np.inf]


def brute_force(space: pymunk.Space, x: float, y: float, heading: float, reach: float) -> np.ndarray:
    """One pymunk segment query per beam: slow, and independent of Lidar's arithmetic."""
    out = np.full(BEAMS, np.inf)
    for i in range(BEAMS):
        a = heading + i * 2 * math.pi / BEAMS
        hit = space.segment_query_first(
            (x, y), (x + reach * math.cos(a), y + reach * math.sin(a)), 0, pymunk.ShapeFilter()
        )
        if hit is not None:
            out[i] = hit.alpha * reach
    return out


def test_matches_a_beam_by_beam_query_and_batches_like_single_scans() -> None:
    world = load_world("signs")
    rng = np.random.default_rng(7)
    robots = np.c_[rng.uniform(-2.8, 2.8, (12, 2)), np.full(12, 0.105)]
    space = pymunk.Space()
    for solid in solids(world):
        space.add(pymunk.Poly(space.static_body, solid.vertices))
    for post in posts(world):
        space.add(pymunk.Circle(space.static_body, post.radius, post.center))
    for x, y, r in robots:
        space.add(pymunk.Circle(space.static_body, r, (x, y)))
    lidar = Lidar([s.vertices for s in solids(world)], [(*p.center, p.radius) for p in posts(world)])
    poses = []
    while len(poses) < 25:
        x, y = rng.uniform(-2.9, 2.9, 2)
        if not space.point_query((x, y), 0.0, pymunk.ShapeFilter()):
            poses.append((x, y, rng.uniform(-10, 10)))
    batch = lidar.distances(np.array(poses), BEAMS, 3.5, robots)
    for row, (x, y, heading) in zip(batch, poses):
        expected = brute_force(space, x, y, heading, 3.5)
        np.testing.assert_allclose(row, expected, atol=1e-9)
        np.testing.assert_array_equal(row, lidar.distances(np.array([(x, y, heading)]), BEAMS, 3.5, robots)[0])


def test_scan_all_gives_each_robots_scan() -> None:
    sim = Simulation.from_file("signs")
    for i in range(5):
        sim.add_robot(f"r{i}", x=-2.0 + i, y=1.5, theta=i)
    everything = sim.scan_all()
    assert list(everything) == list(sim.robots)
    for name, ranges in everything.items():
        np.testing.assert_array_equal(ranges, sim.scan(name))


def test_scans_keep_the_poses_they_were_taken_from() -> None:
    sim = Simulation.from_file("signs")
    sim.add_robot("a", x=-2.0, theta=3.0)
    sim.add_robot("b", RobotModel(name="wide", max_linear=1.0, max_angular=1.0, lidar=LidarSpec(beams=90)), x=1.0)
    for robot in sim.robots.values():
        robot.command(0.2, 1.0)
    for _ in range(200):  # past pi: a heading the pose wraps into [-pi, pi]
        sim.step()
    then = {name: robot.pose for name, robot in sim.robots.items()}
    scans = sim.scan_all()
    sim.step()
    assert scans.poses() == then and then["a"] != sim.robots["a"].pose
    assert all(type(value) is float for pose in scans.poses().values() for value in pose)


def test_other_beam_counts_and_ranges() -> None:
    lidar = Lidar([((1.0, -5.0), (2.0, -5.0), (2.0, 5.0), (1.0, 5.0))])
    ranges = lidar.distances(np.array([(0.0, 0.0, 0.0)]), 4, 10.0)[0]
    assert ranges.tolist() == [1.0, np.inf, np.inf, np.inf]
    assert lidar.distances(np.array([(0.0, 0.0, 0.0)]), 4, 0.5)[0].tolist() == [np.inf] * 4
