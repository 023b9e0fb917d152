"""The World as a 3D scene for Foxglove (a foxglove.SceneUpdate): walls, obstacles, robots and their latest scans.

Everything is in the ``world`` frame, the root of the robots' tf tree
(:mod:`world.frames`), so Foxglove's 3D panel places the scene and the
robots' ``/tf``, ``/odom`` and ``/scan`` together.  The simulation is flat:
heights are for the picture only.  Robots are drawn where the simulator has
them (ground truth, as ``sim/pose``); their odometry (``/tf``) drifts from it
when noise is on.  Each scan is drawn as points where its beams ended, from
the pose it was taken at.  Entities are replaced by id at each update: the
arena (``walls``, ``obstacles``), and per robot its name and ``<name>/scan``.

foxglove-sdk (the ``foxglove`` extra) is imported when a scene is drawn, which
only a live view asks for.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from . import frames
from .arena import World as Arena

if TYPE_CHECKING:
    from actors.recording.live import SceneHost
    from actors.runtime import Runtime

    from .sim import World

__all__ = [
    "SCENE_TOPIC",
    "WALL_HEIGHT",
    "OBSTACLE_HEIGHT",
    "POST_HEIGHT",
    "ROBOT_HEIGHT",
    "POINT_SIZE",
    "scene_update",
    "scene_hosts",
]

SCENE_TOPIC = "/scene"

WALL_HEIGHT = 0.3
OBSTACLE_HEIGHT = 0.25
POST_HEIGHT = 0.6
ROBOT_HEIGHT = 0.192  # a TurtleBot3 burger's
POINT_SIZE = 0.03  # metres across a scan point

_WALL = {"r": 0.55, "g": 0.55, "b": 0.6, "a": 1.0}
_OBSTACLE = {"r": 0.85, "g": 0.45, "b": 0.15, "a": 1.0}
_ROBOT = {"r": 0.15, "g": 0.35, "b": 0.85, "a": 1.0}
_HEADING = {"r": 1.0, "g": 1.0, "b": 1.0, "a": 1.0}
_SCAN = {"r": 0.9, "g": 0.1, "b": 0.1, "a": 1.0}

_XY = tuple[float, float]


def scene_update(world: World, now_ns: int) -> Any:
    """The whole scene now, stamped ``now_ns`` of the runtime clock: a ``foxglove.messages.SceneUpdate``."""
    import foxglove.messages as fm

    stamp = fm.Timestamp(now_ns // 1_000_000_000, now_ns % 1_000_000_000)
    sim = world.sim

    def entity(id: str, kind: str, **primitives: Any) -> Any:
        return fm.SceneEntity(
            timestamp=stamp,
            frame_id=frames.WORLD,
            id=id,
            metadata=[fm.KeyValuePair(key="kind", value=kind)],
            **primitives,
        )

    entities = [
        entity("walls", "walls", cubes=_walls(fm, sim.world)),
        entity("obstacles", "obstacles", **_obstacles(fm, sim.world)),
    ]
    for name, robot in sim.robots.items():
        x, y, theta = robot.pose
        radius = robot.model.radius
        body = _cylinder(fm, (x, y), radius, ROBOT_HEIGHT, _ROBOT)
        heading = fm.ArrowPrimitive(
            pose=_pose(fm, x, y, ROBOT_HEIGHT + 0.01, theta),
            shaft_length=radius,
            shaft_diameter=0.02,
            head_length=0.05,
            head_diameter=0.05,
            color=fm.Color(**_HEADING),
        )
        entities.append(entity(name, "robot", cylinders=[body], arrows=[heading]))
    for name, (pose, ranges) in world.latest_scans().items():
        entities.append(entity(f"{name}/scan", "scan", spheres=_scan_points(fm, pose, ranges)))
    return fm.SceneUpdate(entities=entities)


def _walls(fm: Any, arena: Arena) -> list[Any]:
    cubes = []
    for wall in arena.walls:
        (x1, y1), (x2, y2) = wall.start, wall.end
        length = math.hypot(x2 - x1, y2 - y1) + wall.thickness  # square caps close the corners, as simulated
        center, yaw = ((x1 + x2) / 2, (y1 + y2) / 2), math.atan2(y2 - y1, x2 - x1)
        cubes.append(_cube(fm, center, (length, wall.thickness), yaw, WALL_HEIGHT, _WALL))
    return cubes


def _obstacles(fm: Any, arena: Arena) -> dict[str, list[Any]]:
    cubes = [_cube(fm, box.center, box.size, box.angle, OBSTACLE_HEIGHT, _OBSTACLE) for box in arena.boxes]
    posts = [_cylinder(fm, sign.position, sign.radius, POST_HEIGHT, _OBSTACLE) for sign in arena.stop_signs]
    # A polygon is its outline at the floor and at the top, joined at every vertex.
    outlines = []
    for polygon in arena.polygons:
        corners = polygon.vertices
        points = []
        for i, (x, y) in enumerate(corners):
            nx, ny = corners[(i + 1) % len(corners)]
            for z in (0.0, OBSTACLE_HEIGHT):
                points += [fm.Point3(x=x, y=y, z=z), fm.Point3(x=nx, y=ny, z=z)]
            points += [fm.Point3(x=x, y=y, z=0.0), fm.Point3(x=x, y=y, z=OBSTACLE_HEIGHT)]
        outlines.append(
            fm.LinePrimitive(
                type=fm.LinePrimitiveLineType.LineList, thickness=0.02, points=points, color=fm.Color(**_OBSTACLE)
            )
        )
    return {"cubes": cubes, "cylinders": posts, "lines": outlines}


def _scan_points(fm: Any, pose: Any, ranges: np.ndarray) -> list[Any]:
    """A point where each beam that hit something ended (beam i at i * 2 pi / beams from the heading)."""
    angles = pose.theta + np.arange(len(ranges)) * (2 * math.pi / len(ranges))
    hit = np.isfinite(ranges)
    xs = pose.x + ranges[hit] * np.cos(angles[hit])
    ys = pose.y + ranges[hit] * np.sin(angles[hit])
    z = frames.BASE_LINK_Z + frames.SCAN_Z
    size = fm.Vector3(x=POINT_SIZE, y=POINT_SIZE, z=POINT_SIZE)
    color, level = fm.Color(**_SCAN), fm.Quaternion(w=1.0)
    return [
        fm.SpherePrimitive(pose=fm.Pose(position=fm.Vector3(x=x, y=y, z=z), orientation=level), size=size, color=color)
        for x, y in zip(xs.tolist(), ys.tolist())
    ]


def _cube(fm: Any, center: _XY, size: _XY, yaw: float, height: float, rgba: dict[str, float]) -> Any:
    """A box standing on the floor: ``size`` (length, width) about ``center``, turned ``yaw``."""
    return fm.CubePrimitive(
        pose=_pose(fm, *center, height / 2, yaw),
        size=fm.Vector3(x=size[0], y=size[1], z=height),
        color=fm.Color(**rgba),
    )


def _cylinder(fm: Any, center: _XY, radius: float, height: float, rgba: dict[str, float]) -> Any:
    """An upright cylinder standing on the floor."""
    return fm.CylinderPrimitive(
        pose=_pose(fm, *center, height / 2, 0.0),
        size=fm.Vector3(x=2 * radius, y=2 * radius, z=height),
        bottom_scale=1.0,
        top_scale=1.0,
        color=fm.Color(**rgba),
    )


def _pose(fm: Any, x: float, y: float, z: float, yaw: float) -> Any:
    """A pose turned ``yaw`` radians about z."""
    turn = fm.Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))
    return fm.Pose(position=fm.Vector3(x=x, y=y, z=z), orientation=turn)


def scene_hosts(runtime: Runtime) -> list[SceneHost]:
    """What beside the graph shows 3D scenes (a live view).

    The recording package is imported only when something is attached (it takes tens of ms).
    """
    if not runtime.attachments:
        return []
    from actors.recording.live import SceneHost

    return [host for host in runtime.attachments if isinstance(host, SceneHost)]
