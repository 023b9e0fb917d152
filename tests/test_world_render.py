"""Rendering: PNG and GIF pictures of a recorded run, and the hint when Pillow is missing."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

from world.record import Recorder
from world.render import image_size, save_gif, save_png
from world.simulation import Simulation

Image = pytest.importorskip("PIL.Image")


def recorded_run(frame_every: int | None = None) -> Recorder:
    sim = Simulation.from_file("signs")
    sim.add_robot("a", x=-2.0, y=-2.0).command(0.2, 0.4)
    sim.add_robot("b", "asl_tb3", x=2.0, y=2.0, theta=math.pi).command(0.4, -0.3)
    recorder = Recorder(sim, every=5, frame_every=frame_every)
    for _ in range(500):
        sim.step()
        recorder.update()
    return recorder


def test_png_covers_the_bounds_at_the_scale(tmp_path: Path) -> None:
    recorder = recorded_run()
    path = save_png(recorder, tmp_path / "run.png", scale=50.0)
    assert image_size(recorder, 50.0) == (320, 320)  # 6.4 m square at 50 px/m
    with Image.open(path) as image:
        assert image.format == "PNG" and image.size == (320, 320)
        # The robot's colour where it stands now (behind its heading tick), a wall's, the floor's.
        (x0, _), (_, y1) = recorder.sim.world.bounds.min, recorder.sim.world.bounds.max
        x, y, theta = recorder.sim.robots["a"].pose
        at = lambda x, y: image.getpixel((int((x - x0) * 50), int((y1 - y) * 50)))  # noqa: E731
        assert at(x - 0.05 * math.cos(theta), y - 0.05 * math.sin(theta)) == pytest.approx((31, 119, 180), abs=30)
        assert at(-3.05, -3.05) == pytest.approx((70, 70, 76), abs=10)
        assert at(0.0, 2.5) == pytest.approx((246, 246, 242), abs=10)


def test_gif_has_a_frame_per_recorded_frame(tmp_path: Path) -> None:
    recorder = recorded_run(frame_every=50)
    path = save_gif(recorder, tmp_path / "run.gif", scale=20.0)
    with Image.open(path) as image:
        assert image.format == "GIF" and image.size == image_size(recorder, 20.0)
        assert image.n_frames == len(recorder.frames) == 11
        assert image.info["duration"] == 500  # real time: frames 0.5 s apart


def test_gif_needs_frames(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="frame_every"):
        save_gif(recorded_run(), tmp_path / "run.gif")


def test_missing_pillow_says_what_to_install(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    recorder = recorded_run()
    for name in [m for m in sys.modules if m == "PIL" or m.startswith("PIL.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "PIL", None)
    with pytest.raises(ImportError, match=r"pip install 'actors\[viz\]'"):
        save_png(recorder, tmp_path / "run.png")


def test_robots_added_since_the_last_sample_are_drawn(tmp_path: Path) -> None:
    recorder = recorded_run()
    recorder.sim.add_robot("late", x=0.0, y=2.5)
    with Image.open(save_png(recorder, tmp_path / "run.png", scale=50.0)) as image:
        # Just behind its centre (its heading tick points +x), in the third colour.
        assert image.getpixel((157, 35)) == pytest.approx((44, 160, 44), abs=30)
