"""Pictures of a recorded run as PNG or GIF: the arena, obstacles, stop signs, robots, trajectories.

Pillow is an optional dependency (the ``viz`` extra), imported only when a
picture is drawn. North is up: +y points to the top of the image.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .arena import posts, solids
from .drive import Pose
from .record import Recorder

if TYPE_CHECKING:
    from PIL.Image import Image

__all__ = ["image_size", "pillow", "save_gif", "save_png"]

_SUPERSAMPLE = 2  # draw larger, then shrink: Pillow's drawing has no anti-aliasing
_FLOOR = (246, 246, 242)
_WALL = (70, 70, 76)
_OBSTACLE = (166, 124, 82)
_SIGN = (200, 30, 36)
_ROBOTS = [
    (31, 119, 180),
    (255, 127, 14),
    (44, 160, 44),
    (214, 39, 40),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (127, 127, 127),
    (188, 189, 34),
    (23, 190, 207),
]


def image_size(recorder: Recorder, scale: float) -> tuple[int, int]:
    """The (width, height) in pixels of a picture of the world's bounds at ``scale`` px/m."""
    (x0, y0), (x1, y1) = recorder.sim.world.bounds.min, recorder.sim.world.bounds.max
    return max(1, round((x1 - x0) * scale)), max(1, round((y1 - y0) * scale))


def save_png(recorder: Recorder, path: str | os.PathLike[str], *, scale: float = 100.0) -> Path:
    """Draw the world, every trajectory recorded so far and every robot where it is now, to a PNG.

    ``scale`` is in pixels per metre; the image covers the world's bounds (see
    ``image_size``). Returns the path. Raises ImportError when Pillow is missing.
    """
    canvas = _Canvas(recorder, scale)
    poses = {name: robot.pose for name, robot in recorder.sim.robots.items()}
    image = canvas.picture(poses, until=math.inf)
    path = Path(path)
    image.save(path, format="PNG")
    return path


def save_gif(
    recorder: Recorder,
    path: str | os.PathLike[str],
    *,
    scale: float = 50.0,
    frame_ms: int | None = None,
) -> Path:
    """Animate the recorded frames, each showing the trajectories up to its time, to a looping GIF.

    ``frame_ms`` is each picture's duration; by default the animation plays in
    real time. Returns the path. Raises ValueError when no frames were recorded
    (the Recorder needs ``frame_every``) and ImportError when Pillow is missing.
    """
    frames = recorder.frames
    if not frames:
        raise ValueError("no frames recorded: create the Recorder with frame_every=N steps")
    if frame_ms is None:
        spacing = frames[1].t - frames[0].t if len(frames) > 1 else recorder.sim.dt
        frame_ms = max(20, round(spacing * 1000))  # GIF viewers slow anything faster to 100 ms
    canvas = _Canvas(recorder, scale)
    images = [canvas.picture(frame.poses, until=frame.t) for frame in frames]
    path = Path(path)
    images[0].save(path, format="GIF", save_all=True, append_images=images[1:], duration=frame_ms, loop=0)
    return path


class _Canvas:
    """Draws pictures of one recorder's world, whose static part is drawn once."""

    def __init__(self, recorder: Recorder, scale: float) -> None:
        if not scale > 0:
            raise ValueError(f"scale must be > 0 pixels per metre, got {scale!r}")
        self._pil = pillow()
        self.recorder = recorder
        self.size = image_size(recorder, scale)
        self._scale = scale * _SUPERSAMPLE
        self._origin = (recorder.sim.world.bounds.min[0], recorder.sim.world.bounds.max[1])
        live = {name: robot.model.radius for name, robot in recorder.sim.robots.items()}
        self._radii = {**recorder.radii, **live}  # robots ever recorded, and any added since
        self._colours = {name: _ROBOTS[i % len(_ROBOTS)] for i, name in enumerate(self._radii)}
        self._background = self._draw_world()

    def picture(self, poses: Mapping[str, Pose], *, until: float) -> Image:
        """The world with each trajectory up to time ``until`` (s) and each robot at ``poses``."""
        image = self._background.copy()
        draw = self._pil.ImageDraw.Draw(image)
        width = max(1, round(0.015 * self._scale))
        for name, samples in self.recorder.trajectories.items():
            points = [self._px(s.x, s.y) for s in samples if s.t <= until]
            if name in poses:
                points.append(self._px(poses[name].x, poses[name].y))
            if len(points) > 1:
                draw.line(points, fill=self._colours[name], width=width, joint="curve")
        for name, pose in poses.items():
            self._draw_robot(draw, name, pose)
        return image.resize(self.size, self._pil.Image.Resampling.LANCZOS)

    def _draw_world(self) -> Image:
        size = (self.size[0] * _SUPERSAMPLE, self.size[1] * _SUPERSAMPLE)
        image = self._pil.Image.new("RGB", size, _FLOOR)
        draw = self._pil.ImageDraw.Draw(image)
        for solid in solids(self.recorder.sim.world):
            colour = _WALL if solid.kind == "wall" else _OBSTACLE
            draw.polygon([self._px(x, y) for x, y in solid.vertices], fill=colour)
        for post in posts(self.recorder.sim.world):
            # Drawn larger than the post itself, like the sign on top of it.
            radius = max(post.radius, 0.08) * self._scale
            draw.regular_polygon(
                (*self._px(*post.center), radius),
                8,
                rotation=22.5,
                fill=_SIGN,
                outline=(255, 255, 255),
                width=max(1, round(radius / 6)),
            )
        return image

    def _draw_robot(self, draw: Any, name: str, pose: Pose) -> None:
        radius = self._radii[name]
        cx, cy = self._px(pose.x, pose.y)
        r = radius * self._scale
        draw.ellipse(
            (cx - r, cy - r, cx + r, cy + r),
            fill=self._colours[name],
            outline=(20, 20, 20),
            width=max(1, round(r / 10)),
        )
        tip = self._px(pose.x + radius * math.cos(pose.theta), pose.y + radius * math.sin(pose.theta))
        draw.line([(cx, cy), tip], fill=(255, 255, 255), width=max(1, round(r / 5)))

    def _px(self, x: float, y: float) -> tuple[float, float]:
        return (x - self._origin[0]) * self._scale, (self._origin[1] - y) * self._scale


def pillow() -> Any:
    """Import Pillow's Image and ImageDraw, or say how to install it."""
    try:
        import PIL.Image
        import PIL.ImageDraw
    except ImportError as exc:
        raise ImportError("drawing a world needs Pillow: pip install 'actors[viz]'") from exc
    return PIL
