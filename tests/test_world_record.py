"""The Recorder: trajectories and frames sampled at fixed step intervals, in bounded memory."""

from __future__ import annotations

from itertools import pairwise

import pytest

from world.record import Recorder
from world.simulation import Simulation


def stepped(sim: Simulation, recorder: Recorder, steps: int) -> None:
    for _ in range(steps):
        sim.step()
        recorder.update()


def test_samples_every_n_steps_from_creation() -> None:
    sim = Simulation.from_file("empty")
    robot = sim.add_robot("r")
    robot.command(0.2, 0.0)
    recorder = Recorder(sim, every=10)
    stepped(sim, recorder, 100)
    samples = recorder.trajectories["r"]
    assert [round(s.t, 6) for s in samples] == [round(0.1 * k, 6) for k in range(11)]
    assert samples[-1][1:] == tuple(robot.pose)
    assert recorder.frames == [] and recorder.radii == {"r": 0.105}


def test_robots_added_later_and_removed_keep_their_trajectories() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("a")
    recorder = Recorder(sim, every=1, frame_every=5)
    stepped(sim, recorder, 3)
    sim.add_robot("b", x=1.0)
    stepped(sim, recorder, 3)
    sim.remove_robot("a")
    stepped(sim, recorder, 4)
    # a: at creation and after steps 1-6; b: after steps 4-10.
    assert len(recorder.trajectories["a"]) == 7 and len(recorder.trajectories["b"]) == 7
    assert [sorted(frame.poses) for frame in recorder.frames] == [["a"], ["a", "b"], ["b"]]


def test_memory_is_bounded_and_the_whole_run_stays_covered() -> None:
    sim = Simulation.from_file("empty")
    sim.add_robot("r")
    recorder = Recorder(sim, every=1, frame_every=1, max_samples=100, max_frames=10)
    stepped(sim, recorder, 1000)
    samples = recorder.trajectories["r"]
    assert len(samples) <= 100 and len(recorder.frames) <= 10
    assert samples[0].t == 0.0 and samples[-1].t > 0.9 * sim.time
    spacing = {round(b.t - a.t, 6) for a, b in pairwise(samples)}
    assert len(spacing) == 1  # still evenly spaced, just coarser


@pytest.mark.parametrize("kwargs", [{"every": 0}, {"frame_every": 0}, {"max_samples": 1}])
def test_rejects_bad_settings(kwargs: dict) -> None:
    with pytest.raises(ValueError):
        Recorder(Simulation.from_file("empty"), **kwargs)
