"""Sensor noise: off by default, validated, and reproducible from a seed."""

from __future__ import annotations

import numpy as np
import pytest

from world.noise import Noise, NoiseSource


def test_off_by_default_changes_nothing() -> None:
    source = NoiseSource(Noise(), seed=1)
    assert not Noise().odometry
    assert source.odometry(1.0, 2.0, 0.5, 0.2, 0.1) == (1.0, 2.0, 0.5, 0.2, 0.1)
    ranges = np.array([1.0, np.inf])
    assert source.ranges(ranges) is ranges and ranges.tolist() == [1.0, np.inf]


@pytest.mark.parametrize("field", ["position", "heading", "linear", "angular", "ranges"])
@pytest.mark.parametrize("value", [-0.1, float("inf"), float("nan")])
def test_rejects_bad_deviations(field: str, value: float) -> None:
    with pytest.raises(ValueError, match=f"noise {field} must be a finite standard deviation"):
        Noise(**{field: value})


def test_same_seed_same_numbers_and_streams_are_independent() -> None:
    noise = Noise(position=0.01, heading=0.02, linear=0.03, angular=0.04, ranges=0.05)
    a, b, c = NoiseSource(noise, 3), NoiseSource(noise, 3), NoiseSource(noise, 4)
    b.odometry(0, 0, 0, 0, 0)  # reading odometry must not shift the range noise
    ranges = [s.ranges(np.ones(360)) for s in (a, b, c)]
    np.testing.assert_array_equal(ranges[0], ranges[1])
    assert not np.array_equal(ranges[0], ranges[2])
    assert np.std(ranges[0]) == pytest.approx(0.05, rel=0.2)
    odometry = a.odometry(1.0, 2.0, 0.0, 0.2, 0.1)
    assert odometry != (1.0, 2.0, 0.0, 0.2, 0.1) and odometry == pytest.approx((1.0, 2.0, 0.0, 0.2, 0.1), abs=0.3)
    assert {type(value) for value in odometry} == {float}  # what a message field takes as it is


def test_infinite_ranges_stay_infinite() -> None:
    ranges = NoiseSource(Noise(ranges=0.1), 0).ranges(np.array([np.inf, -np.inf, 1.0]))
    assert ranges[0] == np.inf and ranges[1] == -np.inf and ranges[2] != 1.0
