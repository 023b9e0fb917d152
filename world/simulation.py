"""The simulated world: a top-down pymunk space built from a world file, its robots, and scans.

Deterministic by construction: no wall clock and no global random state. The
same world, the same robots added in the same order with the same seeds, and
the same commands at the same steps give bit-identical poses and scans.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from types import MappingProxyType

import numpy as np
import pymunk
import pymunk.autogeometry

from actors.core.explain import did_you_mean

from .arena import Post, Solid, World, load_world, posts, solids
from .drive import MODELS, Contact, Pose, Robot, RobotModel
from .lidar import Lidar, LidarSpec, finish_ranges
from .noise import Noise

__all__ = ["Scans", "Simulation"]

# Robots' sensor circles touch solid shapes only, never each other.
_SOLID = 0b01
_SENSING = 0b10
_SENSOR_TYPE = 1


class Simulation:
    """A world and the robots in it, advanced in fixed steps of simulated time.

    Units are SI throughout: metres, seconds, radians. Nothing here reads the
    wall clock; ``time`` is the sum of the steps taken.
    """

    def __init__(self, world: World, *, dt: float = 0.01) -> None:
        """Build the static world (walls, boxes, polygons, stop signs); ``dt`` (s) is the step."""
        if not dt > 0:
            raise ValueError(f"dt must be > 0 s, got {dt!r}")
        self.world = world
        self.dt = dt
        self.time = 0.0
        self.steps = 0
        self.space = pymunk.Space()
        self.space.collision_slop = 0.0005  # m; pymunk's default (0.1) suits pixels, not metres
        self._labels: dict[pymunk.Shape, Contact] = {}
        self._robots: dict[str, Robot] = {}
        self._by_sensor: dict[pymunk.Shape, Robot] = {}
        self._circles: np.ndarray | None = None  # robots as (x, y, r), cached for one step
        the_solids, the_posts = solids(world), posts(world)
        for solid in the_solids:
            self._add_solid(solid)
        for post in the_posts:
            self._add_post(post)
        self.lidar = Lidar([s.vertices for s in the_solids], [(*p.center, p.radius) for p in the_posts])
        self.space.on_collision(_SENSOR_TYPE, None, pre_solve=self._on_sensor)

    @classmethod
    def from_file(cls, source: str | os.PathLike[str], *, dt: float = 0.01) -> Simulation:
        """Load a world file (a path, or a shipped world's name); raises WorldFileError."""
        return cls(load_world(source), dt=dt)

    @property
    def robots(self) -> Mapping[str, Robot]:
        """The robots by name, in the order they were added (read-only)."""
        return MappingProxyType(self._robots)

    def add_robot(
        self,
        name: str,
        model: str | RobotModel = "burger",
        *,
        x: float = 0.0,
        y: float = 0.0,
        theta: float = 0.0,
        seed: int = 0,
        noise: Noise | None = None,
    ) -> Robot:
        """Place a robot at ``(x, y)`` m heading ``theta`` rad, standing still, and return it.

        ``model`` is a name from ``MODELS`` ("burger", "asl_tb3") or a RobotModel.
        ``seed`` seeds the robot's own noise generators; ``noise`` defaults to none.
        Raises ValueError if the name is taken, the model unknown, the pose not
        finite, or the robot would start outside the bounds or overlapping anything.
        """
        if name in self._robots:
            raise ValueError(f"a robot named {name!r} already exists")
        if isinstance(model, str):
            if model not in MODELS:
                raise ValueError(
                    f"unknown robot model {model!r}{did_you_mean(model, MODELS)}; the models are {', '.join(MODELS)}"
                )
            model = MODELS[model]
        if not all(math.isfinite(value) for value in (x, y, theta)):
            raise ValueError(f"robot {name!r}: start pose must be finite, got ({x}, {y}, {theta})")
        robot = Robot(name, model, Pose(x, y, theta), seed=seed, noise=noise or Noise())
        (x0, y0), (x1, y1) = self.world.bounds.min, self.world.bounds.max
        if not (x0 <= x <= x1 and y0 <= y <= y1):
            raise ValueError(f"robot {name!r} would start at ({x}, {y}), outside the world's bounds")
        # Query solids only: another robot's sensor circle is no obstacle.
        robot.shape.filter = pymunk.ShapeFilter(categories=_SOLID, mask=_SOLID)
        if hits := self.space.shape_query(robot.shape):
            raise ValueError(f"robot {name!r} would start overlapping {self._describe(hits[0].shape)}")
        robot.shape.filter = pymunk.ShapeFilter(categories=_SOLID)
        robot.sensor.collision_type = _SENSOR_TYPE
        robot.sensor.filter = pymunk.ShapeFilter(categories=_SENSING, mask=_SOLID)
        self.space.add(robot.body, robot.shape, robot.sensor)
        self._labels[robot.shape] = Contact("robot", name)
        self._by_sensor[robot.sensor] = robot
        self._robots[name] = robot
        self._circles = None
        return robot

    def remove_robot(self, name: str) -> None:
        """Take the robot out of the world; raises KeyError if there is none by that name."""
        robot = self._robots.pop(name)
        self.space.remove(robot.body, robot.shape, robot.sensor)
        del self._labels[robot.shape], self._by_sensor[robot.sensor]
        self._circles = None

    def step(self, dt: float | None = None) -> None:
        """Advance ``dt`` s (default ``self.dt``): apply every robot's command, then move it all."""
        dt = self.dt if dt is None else dt
        if not dt > 0:
            raise ValueError(f"dt must be > 0 s, got {dt!r}")
        for robot in self._robots.values():
            robot._drive(dt)
        self.space.step(dt)
        self.steps += 1
        self.time += dt
        self._circles = None

    def scan(self, name: str) -> np.ndarray:
        """One lidar sweep of the named robot, as sensor_msgs/LaserScan ranges (m).

        Beam i points ``i * 2 pi / beams`` rad counter-clockwise from the robot's
        heading. Its own body is not seen; other robots are. Readings carry the
        robot's range noise; no return within ``range_max`` is ``+inf``, a return
        nearer than ``range_min`` is ``-inf``. Raises KeyError for an unknown name.
        """
        return self._scan([self._robots[name]])[name]

    def scan_all(self) -> Scans:
        """A sweep of every robot by name, as ``scan`` gives it; cheaper than ``scan`` each."""
        return self._scan(list(self._robots.values()))

    def _scan(self, robots: list[Robot]) -> Scans:
        by_spec: dict[LidarSpec, list[Robot]] = {}
        for robot in robots:
            by_spec.setdefault(robot.model.lidar, []).append(robot)
        scans = Scans()
        for spec, group in by_spec.items():
            poses = np.array([(*robot.body.position, robot.body.angle) for robot in group])
            scans._origins.append((group, poses))
            rows = self.lidar.distances(poses, spec.beams, spec.range_max, self._robot_circles())
            for robot, row in zip(group, rows):
                scans[robot.name] = finish_ranges(robot.noise_source.ranges(row), spec)
        return scans

    def _robot_circles(self) -> np.ndarray:
        # The scanner's own circle contains the beam origin, which Lidar ignores.
        if self._circles is None:
            self._circles = np.array(
                [(*r.body.position, r.model.radius) for r in self._robots.values()], dtype=float
            ).reshape(-1, 3)
        return self._circles

    def _add_solid(self, solid: Solid) -> None:
        pieces = [solid.vertices]
        if not _convex(solid.vertices):
            closed = [*solid.vertices, solid.vertices[0]]
            pieces = [hull[:-1] for hull in pymunk.autogeometry.convex_decomposition(closed, 0.0)]
        for piece in pieces:
            self._add_static(pymunk.Poly(self.space.static_body, piece), Contact(solid.kind, solid.name))

    def _add_post(self, post: Post) -> None:
        shape = pymunk.Circle(self.space.static_body, post.radius, post.center)
        self._add_static(shape, Contact(post.kind, post.name))

    def _add_static(self, shape: pymunk.Shape, label: Contact) -> None:
        shape.elasticity = 0.0
        shape.friction = 0.0
        shape.filter = pymunk.ShapeFilter(categories=_SOLID)
        self.space.add(shape)
        self._labels[shape] = label

    def _on_sensor(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        sensor, other = arbiter.shapes
        self._by_sensor[sensor]._sense(arbiter, self._labels[other])

    def _describe(self, shape: pymunk.Shape) -> str:
        label = self._labels[shape]
        return f"{label.kind} {label.name!r}" if label.name else f"a {label.kind}"


class Scans(dict[str, np.ndarray]):
    """Ranges (m) by robot name, as ``Simulation.scan_all`` gives them, and the poses they were taken from."""

    __slots__ = ("_origins",)

    def __init__(self) -> None:
        super().__init__()
        # The robots of each lidar model and the lidar's (R, 3) array of their poses: the
        # Poses are made only when asked for (by a live view), not with every scan.
        self._origins: list[tuple[list[Robot], np.ndarray]] = []

    def poses(self) -> dict[str, Pose]:
        """The pose each robot was scanned from, as ``Robot.pose`` gave it then."""
        return {
            robot.name: Pose(x, y, math.remainder(theta, math.tau))
            for group, poses in self._origins
            for robot, (x, y, theta) in zip(group, poses.tolist())
        }


def _convex(vertices: tuple[tuple[float, float], ...]) -> bool:
    """Whether a counter-clockwise polygon turns left (or goes straight) at every vertex."""
    n = len(vertices)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]
        if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) < 0:
            return False
    return True
