"""World files: the TOML schema of an arena, its loader, and the static geometry it describes.

A world file lists the arena's bounds, its walls, boxes, polygons and stop signs::

    description = "a walled 6 x 6 m arena"

    [bounds]                  # the area that renders show and robots start in (metres)
    min = [-3.2, -3.2]
    max = [3.2, 3.2]

    [[walls]]                 # a straight wall along its centre line
    start = [-3.0, -3.0]
    end = [3.0, -3.0]
    thickness = 0.1           # metres (default 0.05); the ends are square caps

    [[boxes]]                 # a rectangle turned by ``angle`` radians about its centre
    center = [1.61, 0.0]
    size = [0.5, 0.4]
    angle = 0.0
    name = "box_a"            # optional; contacts report it

    [[polygons]]              # any simple polygon, convex or not, in either winding
    vertices = [[0, 0], [1, 0], [0, 1]]

    [[stop_signs]]            # a thin post that also shows in renders
    position = [0.15, -2.0]

Everything is decoded into frozen msgspec Structs that reject unknown keys. Every
problem (missing file, TOML syntax, unknown key, wrong type, bad value) raises
:class:`~actors.errors.WorldFileError` with one line naming the file and the key path.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Annotated, NamedTuple

import msgspec

from actors.core.explain import did_you_mean
from actors.core.tomlfile import load_toml
from actors.errors import WorldFileError

__all__ = [
    "WORLDS_DIR",
    "Bounds",
    "Box",
    "Polygon",
    "Post",
    "Solid",
    "StopSign",
    "Wall",
    "World",
    "load_world",
    "shipped_worlds",
    "posts",
    "solids",
]

#: Where the shipped worlds live; ``load_world("signs")`` reads ``WORLDS_DIR / "signs.toml"``.
WORLDS_DIR = Path(__file__).with_name("worlds")

# Finite and not absurd: TOML allows inf and nan, and a world beyond 10 km is a typo.
Coord = Annotated[float, msgspec.Meta(ge=-1e4, le=1e4)]
Length = Annotated[float, msgspec.Meta(gt=0.0, le=1e4)]
Point = tuple[Coord, Coord]
XY = tuple[float, float]


class _Spec(msgspec.Struct, frozen=True, forbid_unknown_fields=True, kw_only=True):
    """Base of the world-file tables: immutable, and unknown keys are errors."""


class Bounds(_Spec):
    """The axis-aligned area (metres) that renders show and robots must start in."""

    min: Point
    max: Point

    def __post_init__(self) -> None:
        if not (self.min[0] < self.max[0] and self.min[1] < self.max[1]):
            raise ValueError("min must be below max on both axes")


class Wall(_Spec):
    """A straight wall from ``start`` to ``end`` (its centre line), ``thickness`` metres wide."""

    start: Point
    end: Point
    thickness: Length = 0.05

    def __post_init__(self) -> None:
        if self.start == self.end:
            raise ValueError("start and end are the same point")


class Box(_Spec):
    """A ``size`` = (length, width) rectangle centred on ``center``, turned ``angle`` radians."""

    center: Point
    size: tuple[Length, Length]
    angle: Coord = 0.0
    name: str | None = None


class Polygon(_Spec):
    """A simple polygon (its edges do not cross), convex or not, in either winding."""

    vertices: Annotated[list[Point], msgspec.Meta(min_length=3)]
    name: str | None = None

    def __post_init__(self) -> None:
        if _edges_cross(self.vertices):
            raise ValueError("vertices: edges cross each other")
        if abs(_signed_area(self.vertices)) < 1e-9:
            raise ValueError("vertices: they enclose no area")


class StopSign(_Spec):
    """A stop sign: a post of ``radius`` metres at ``position``."""

    position: Point
    radius: Length = 0.05
    name: str | None = None


class World(_Spec):
    """A whole world file.

    ``load_world`` checks every value; building one in code checks only the
    relations between fields (``__post_init__``), as msgspec checks value
    constraints when decoding.
    """

    bounds: Bounds
    description: str = ""
    walls: list[Wall] = []
    boxes: list[Box] = []
    polygons: list[Polygon] = []
    stop_signs: list[StopSign] = []


def load_world(source: str | os.PathLike[str]) -> World:
    """Read and validate a world file.

    ``source`` is a path, or the bare name of a shipped world (``"empty"``,
    ``"signs"``: a name without a suffix or a directory part). Raises
    :class:`WorldFileError` whose one-line message names the file and, for a bad
    value, the key path (``boxes[1].size: expected an array of 2 numbers, got 3 items``).
    """
    path = Path(source)
    if path.suffix == "" and path.parent == Path("."):
        known = shipped_worlds()
        if path.name not in known:
            raise WorldFileError(
                f"unknown world {path.name!r}{did_you_mean(path.name, known)}; the shipped worlds are "
                f"{', '.join(known)} (or give the path of a world file)"
            )
        path = WORLDS_DIR / f"{path.name}.toml"
    return load_toml(path, World, WorldFileError)


def shipped_worlds() -> list[str]:
    """The names of the shipped worlds, sorted."""
    return sorted(p.stem for p in WORLDS_DIR.glob("*.toml"))


# --- static geometry -------------------------------------------------------------


class Solid(NamedTuple):
    """A static polygon: ``kind`` is "wall" or "obstacle"; its vertices wind counter-clockwise."""

    kind: str
    name: str | None
    vertices: tuple[XY, ...]


class Post(NamedTuple):
    """A static circle of the world (a stop sign's post); ``kind`` is "obstacle"."""

    kind: str
    name: str | None
    center: XY
    radius: float


def solids(world: World) -> list[Solid]:
    """The world's walls, boxes and polygons as counter-clockwise polygons, in file order."""
    out = [Solid("wall", None, _wall_outline(wall)) for wall in world.walls]
    out += [Solid("obstacle", box.name, _box_outline(box)) for box in world.boxes]
    out += [Solid("obstacle", poly.name, _ccw(poly.vertices)) for poly in world.polygons]
    return out


def posts(world: World) -> list[Post]:
    """The world's stop signs as circles, in file order."""
    return [Post("obstacle", sign.name, sign.position, sign.radius) for sign in world.stop_signs]


def _wall_outline(wall: Wall) -> tuple[XY, ...]:
    (x1, y1), (x2, y2) = wall.start, wall.end
    length = math.hypot(x2 - x1, y2 - y1)
    center = ((x1 + x2) / 2, (y1 + y2) / 2)
    # Square caps (length + thickness) so that walls meeting at a corner close it.
    size = (length + wall.thickness, wall.thickness)
    return _rectangle(center, size, math.atan2(y2 - y1, x2 - x1))


def _box_outline(box: Box) -> tuple[XY, ...]:
    return _rectangle(box.center, box.size, box.angle)


def _rectangle(center: XY, size: XY, angle: float) -> tuple[XY, ...]:
    cx, cy = center
    hx, hy = size[0] / 2, size[1] / 2
    c, s = math.cos(angle), math.sin(angle)
    corners = ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))
    return tuple((cx + c * x - s * y, cy + s * x + c * y) for x, y in corners)


def _ccw(vertices: Sequence[XY]) -> tuple[XY, ...]:
    points = tuple((float(x), float(y)) for x, y in vertices)
    return points if _signed_area(points) > 0 else points[::-1]


def _signed_area(vertices: Sequence[XY]) -> float:
    n = len(vertices)
    return 0.5 * sum(
        vertices[i][0] * vertices[(i + 1) % n][1] - vertices[(i + 1) % n][0] * vertices[i][1] for i in range(n)
    )


def _edges_cross(vertices: Sequence[XY]) -> bool:
    """Whether any two non-adjacent edges of the closed polygon intersect."""
    n = len(vertices)
    edges = [(vertices[i], vertices[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # the closing edge shares a vertex with the first
            if _segments_intersect(*edges[i], *edges[j]):
                return True
    return False


def _segments_intersect(a: XY, b: XY, c: XY, d: XY) -> bool:
    """Whether the closed segments a-b and c-d share a point."""
    d1, d2, d3, d4 = _orient(c, d, a), _orient(c, d, b), _orient(a, b, c), _orient(a, b, d)
    if d1 * d2 < 0 and d3 * d4 < 0:
        return True
    return (
        (d1 == 0 and _within(c, d, a))
        or (d2 == 0 and _within(c, d, b))
        or (d3 == 0 and _within(a, b, c))
        or (d4 == 0 and _within(a, b, d))
    )


def _orient(p: XY, q: XY, r: XY) -> float:
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def _within(p: XY, q: XY, r: XY) -> bool:
    """Whether r, known to be collinear with p-q, lies on the segment."""
    return min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])
