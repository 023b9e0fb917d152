"""A 2D lidar: ranges along evenly spaced beams, cast at every edge and circle at once with numpy.

Beams are not pymunk queries. Seen from a scanner, each edge or circle covers
an arc of angles, so only the few beams inside that arc can hit it: the cast
lists those (scanner, thing, beam) triples, solves every one in a single array
operation and keeps the nearest hit per beam. Scanning many robots in one call
shares the numpy call overhead, which dominates at these sizes.

Static geometry becomes arrays once, when the Lidar is built; only the circles
of the robots change from scan to scan. Edges belong to closed
counter-clockwise polygons, so an edge whose outer side faces away from the
scanner can never be the nearest hit and is skipped, as is anything wholly
beyond the maximum range.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import msgspec
import numpy as np

__all__ = ["Lidar", "LidarSpec", "finish_ranges"]


class LidarSpec(msgspec.Struct, frozen=True, kw_only=True):
    """A scanner: ``beams`` beams over a full turn, beam i at ``i * 2 pi / beams`` rad from heading.

    ``range_min`` and ``range_max`` are in metres, as in sensor_msgs/LaserScan.
    """

    beams: int = 360
    range_min: float = 0.12
    range_max: float = 3.5


class Lidar:
    """Casts beams against fixed polygons and circles, plus circles given per scan."""

    def __init__(
        self,
        polygons: Sequence[Sequence[tuple[float, float]]],
        circles: Sequence[tuple[float, float, float]] = (),
    ) -> None:
        """Take closed counter-clockwise ``polygons`` (vertex lists) and ``(x, y, r)`` circles."""
        starts = [p for poly in polygons for p in poly]
        ends = [poly[(i + 1) % len(poly)] for poly in polygons for i in range(len(poly))]
        self._p = np.array(starts, dtype=float).reshape(-1, 2)
        self._e = np.array(ends, dtype=float).reshape(-1, 2) - self._p
        self._length2 = np.einsum("ij,ij->i", self._e, self._e)
        self._circles = np.array(circles, dtype=float).reshape(-1, 3)

    def distances(
        self,
        poses: np.ndarray,
        beams: int,
        range_max: float,
        others: np.ndarray | None = None,
    ) -> np.ndarray:
        """Distances (m) to the nearest surface along each beam of each scanner.

        ``poses`` is an (R, 3) array of scanner poses ``(x, y, heading)``; beam i
        of a scanner points ``heading + i * 2 pi / beams`` rad. ``others`` is an
        optional (K, 3) array of extra ``(x, y, radius)`` circles; a circle that
        contains a scanner is not seen by it (it is the scanner's own body). A
        beam with nothing within ``range_max`` reads ``inf``. Returns a new
        (R, beams) float64 array.
        """
        fan = _Fan(np.asarray(poses, dtype=float).reshape(-1, 3), beams)
        best = np.full(fan.dx.size, np.inf)
        self._cast_edges(best, fan, range_max)
        circles = self._circles if others is None else np.concatenate((self._circles, others))
        if len(circles):
            _cast_circles(best, fan, circles, range_max)
        best[best > range_max] = np.inf
        return best.reshape(-1, beams)

    def _cast_edges(self, best: np.ndarray, fan: _Fan, reach: float) -> None:
        qx = self._p[:, 0] - fan.x[:, None]  # (scanner, edge): from the scanner to the edge's start
        qy = self._p[:, 1] - fan.y[:, None]
        ex, ey = self._e[:, 0], self._e[:, 1]
        # (q x e) < 0: the edge's outer side (its outward normal is (ey, -ex)) faces the scanner.
        t_num = qx * ey - qy * ex
        s = np.clip(-(qx * ex + qy * ey) / self._length2, 0.0, 1.0)
        near = (qx + s * ex) ** 2 + (qy + s * ey) ** 2 <= reach * reach
        scanner, edge = np.nonzero((t_num < 0) & near)
        if not len(edge):
            return
        qx, qy, t_num = qx[scanner, edge], qy[scanner, edge], t_num[scanner, edge]
        ex, ey = ex[edge], ey[edge]
        # Seen from the scanner a facing edge sweeps counter-clockwise from its end to its start.
        first = np.arctan2(qy + ey, qx + ex)
        width = (np.arctan2(qy, qx) - first) % (2 * math.pi)
        pair, beam = fan.spread(scanner, first, width)
        dx, dy = fan.dx[beam], fan.dy[beam]
        ex, ey, qx, qy = ex[pair], ey[pair], qx[pair], qy[pair]
        # Solve origin + t * d = p + s * e per (pair, beam): t = t_num / den, s = s_num / den.
        # A beam entering a facing edge has den < 0, so t >= 0 already holds and 0 <= s <= 1
        # can be checked on the numerators without dividing.
        den = dx * ey - dy * ex
        s_num = qx * dy - qy * dx
        hit = (den < 0) & (s_num <= 0) & (s_num >= den)
        np.minimum.at(best, beam[hit], t_num[pair[hit]] / den[hit])


class _Fan:
    """The beams of a batch of scanners: directions flattened to (scanner * beams + beam)."""

    def __init__(self, poses: np.ndarray, beams: int) -> None:
        self.x, self.y, self.heading = poses[:, 0], poses[:, 1], poses[:, 2]
        self.beams = beams
        angles = self.heading[:, None] + np.arange(beams) * (2 * math.pi / beams)
        self.dx = np.cos(angles).ravel()
        self.dy = np.sin(angles).ravel()

    def spread(self, scanner: np.ndarray, first: np.ndarray, width: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(item, flat beam) pairs: each beam of ``scanner[item]`` in ``[first, first + width]``.

        May include a beam either side of each interval: callers test each pair exactly.
        """
        step = 2 * math.pi / self.beams
        start = np.floor(((first - self.heading[scanner]) % (2 * math.pi)) / step).astype(np.intp)
        count = np.floor(width / step).astype(np.intp) + 2
        item = np.repeat(np.arange(len(count)), count)
        offset = np.arange(len(item)) - np.repeat(np.cumsum(count) - count, count)
        return item, scanner[item] * self.beams + (start[item] + offset) % self.beams


def _cast_circles(best: np.ndarray, fan: _Fan, circles: np.ndarray, reach: float) -> None:
    cx = circles[:, 0] - fan.x[:, None]  # (scanner, circle): from the scanner to the centre
    cy = circles[:, 1] - fan.y[:, None]
    r = circles[:, 2]
    dist2 = cx * cx + cy * cy
    scanner, circle = np.nonzero((dist2 > r * r) & (dist2 <= (reach + r) ** 2))
    if not len(circle):
        return
    cx, cy, dist2, r = cx[scanner, circle], cy[scanner, circle], dist2[scanner, circle], r[circle]
    half = np.arcsin(r / np.sqrt(dist2))  # half the angle the circle subtends
    pair, beam = fan.spread(scanner, np.arctan2(cy, cx) - half, 2 * half)
    cx, cy, r, dist2 = cx[pair], cy[pair], r[pair], dist2[pair]
    along = fan.dx[beam] * cx + fan.dy[beam] * cy  # distance to the point of the beam nearest the centre
    half_chord2 = r * r - (dist2 - along * along)
    hit = (along > 0) & (half_chord2 >= 0)
    np.minimum.at(best, beam[hit], along[hit] - np.sqrt(half_chord2[hit]))


def finish_ranges(distances: np.ndarray, spec: LidarSpec) -> np.ndarray:
    """Mark out-of-range readings in place as sensor_msgs/LaserScan does (REP 117) and return them.

    A reading above ``range_max`` (no return) becomes ``+inf``; one below
    ``range_min`` (too close to measure) becomes ``-inf``.
    """
    distances[distances > spec.range_max] = np.inf
    distances[distances < spec.range_min] = -np.inf
    return distances
