"""Sensor noise: Gaussian errors on odometry and lidar ranges, from per-robot seeded generators."""

from __future__ import annotations

import msgspec
import numpy as np

__all__ = ["Noise", "NoiseSource"]


class Noise(msgspec.Struct, frozen=True, kw_only=True):
    """Standard deviations of zero-mean Gaussian noise; all zero (no noise) by default.

    ``position`` (m) is added to odometry x and y, ``heading`` (rad) to its yaw,
    ``linear`` (m/s) and ``angular`` (rad/s) to its twist, ``ranges`` (m) to every
    lidar reading. Raises ValueError for a negative or non-finite value.
    """

    position: float = 0.0
    heading: float = 0.0
    linear: float = 0.0
    angular: float = 0.0
    ranges: float = 0.0

    def __post_init__(self) -> None:
        for field in self.__struct_fields__:
            value = getattr(self, field)
            if not 0.0 <= value < float("inf"):
                raise ValueError(f"noise {field} must be a finite standard deviation >= 0, got {value!r}")

    @property
    def odometry(self) -> bool:
        """Whether any odometry noise is on."""
        return bool(self.position or self.heading or self.linear or self.angular)


class NoiseSource:
    """Draws a robot's noise: same ``seed`` and same calls give the same numbers.

    Odometry and ranges use separate streams, so how often one is read does not
    change the other's numbers.
    """

    def __init__(self, noise: Noise, seed: int) -> None:
        self.noise = noise
        self._odometry = np.random.default_rng([seed, 0])
        self._ranges = np.random.default_rng([seed, 1])

    def odometry(
        self, x: float, y: float, theta: float, v: float, w: float
    ) -> tuple[float, float, float, float, float]:
        """The pose (m, m, rad) and twist (m/s, rad/s) plus noise, as Python floats; unchanged when it is off."""
        noise = self.noise
        if not noise.odometry:
            return x, y, theta, v, w
        scale = (noise.position, noise.position, noise.heading, noise.linear, noise.angular)
        dx, dy, dtheta, dv, dw = self._odometry.normal(0.0, scale).tolist()  # not numpy scalars
        return x + dx, y + dy, theta + dtheta, v + dv, w + dw

    def ranges(self, distances: np.ndarray) -> np.ndarray:
        """Add range noise to ``distances`` (m) in place and return them; infinities stay."""
        if self.noise.ranges:
            distances += self._ranges.normal(0.0, self.noise.ranges, distances.shape)
        return distances

    def skip_ranges(self, beams: int) -> None:
        """Draw one scan's range noise and drop it: the stream moves on as ``ranges`` of ``beams`` would."""
        if self.noise.ranges:
            self._ranges.normal(0.0, self.noise.ranges, beams)
