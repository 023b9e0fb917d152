"""turtlesim as a 3D scene for Foxglove (a foxglove.SceneUpdate): the window's floor, the pens' trails, the turtles.

Drawn in turtlesim's own coordinates (metres, y up, the origin at the
window's lower left corner), in frame ``world``: the floor an 11×11 m tile
of the background colour, the trails as coloured lines just above it (the
latest :data:`~world.canvas.SEGMENTS` segments), each turtle a disc with an
arrow along its heading.  foxglove-sdk is imported only when a live view asks.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from .canvas import METER
from .turtlesim import WORLD_SIZE

if TYPE_CHECKING:
    from .turtlesim import Turtlesim

__all__ = ["TURTLESIM_TOPIC", "turtlesim_scene"]

TURTLESIM_TOPIC = "/turtlesim/scene"
_FRAME = "world"
_TURTLE = {"r": 0.29, "g": 0.61, "b": 0.33, "a": 1.0}


def _colour(fm: Any, rgb: tuple[int, int, int]) -> Any:
    return fm.Color(r=rgb[0] / 255, g=rgb[1] / 255, b=rgb[2] / 255, a=1.0)


def _pose(fm: Any, x: float, y: float, z: float, yaw: float) -> Any:
    turn = fm.Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))
    return fm.Pose(position=fm.Vector3(x=x, y=y, z=z), orientation=turn)


def turtlesim_scene(sim: Turtlesim, now_ns: int) -> Any:
    """The window now, stamped ``now_ns``: a ``foxglove.messages.SceneUpdate``."""
    import foxglove.messages as fm

    stamp = fm.Timestamp(now_ns // 1_000_000_000, now_ns % 1_000_000_000)

    def entity(id: str, **primitives: Any) -> Any:
        return fm.SceneEntity(timestamp=stamp, frame_id=_FRAME, id=id, **primitives)

    half = WORLD_SIZE / 2
    floor = fm.CubePrimitive(
        pose=_pose(fm, half, half, -0.005, 0.0),
        size=fm.Vector3(x=WORLD_SIZE, y=WORLD_SIZE, z=0.01),
        color=_colour(fm, sim.background()),
    )
    points, colours = [], []
    for x0, y0, x1, y1, rgb, _ in sim.canvas.segments:
        points += [fm.Point3(x=x0, y=WORLD_SIZE - y0, z=0.002), fm.Point3(x=x1, y=WORLD_SIZE - y1, z=0.002)]
        colours += [_colour(fm, rgb)] * 2
    trails = fm.LinePrimitive(
        type=fm.LinePrimitiveLineType.LineList,
        pose=_pose(fm, 0.0, 0.0, 0.0, 0.0),
        thickness=3 / METER,
        points=points,
        colors=colours,
    )
    entities = [entity("turtlesim/floor", cubes=[floor]), entity("turtlesim/trails", lines=[trails])]
    for name, turtle in sim.turtles.items():
        x, y, theta = turtle.x, WORLD_SIZE - turtle.y, turtle.theta
        body = fm.CylinderPrimitive(
            pose=_pose(fm, x, y, 0.05, 0.0),
            size=fm.Vector3(x=0.6, y=0.6, z=0.1),
            bottom_scale=1.0,
            top_scale=1.0,
            color=fm.Color(**_TURTLE),
        )
        heading = fm.ArrowPrimitive(
            pose=_pose(fm, x, y, 0.11, theta),
            shaft_length=0.3,
            shaft_diameter=0.06,
            head_length=0.15,
            head_diameter=0.15,
            color=fm.Color(r=1.0, g=1.0, b=1.0, a=1.0),
        )
        entities.append(entity(f"turtlesim/{name}", cylinders=[body], arrows=[heading]))
    return fm.SceneUpdate(entities=entities)
