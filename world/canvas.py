"""turtlesim's window as pixels: the pen's path image, the background, the turtles, and PNG files of it.

The window is 500×500 pixels, 45 pixels to the metre, y pointing down, as the
real turtlesim's Qt frame is.  The path image starts transparent white (so a
colour sensor over paper nobody drew on reads 255, 255, 255, as ROS 2's does);
the background colour shows through it only in the picture.  Lines are drawn
without anti-aliasing, as a QPainter does by default: every pixel whose centre
lies within half the pen's width of the segment.  numpy only; the PNG writer
is a dozen lines of zlib.
"""

from __future__ import annotations

import math
import os
import struct
import zlib
from collections import deque
from collections.abc import Iterable
from pathlib import Path

import numpy as np

__all__ = ["SIZE", "METER", "SEGMENTS", "Segment", "Canvas", "png_bytes", "write_png"]

SIZE = 500
METER = 45  # pixels per metre: the height of turtlesim's turtle images
SEGMENTS = 20_000  # pen segments kept for the live view (the oldest go first); the pixels keep them all
_TURTLE_BODY = (73, 156, 84)
_TURTLE_HEAD = (32, 84, 40)
_RGB = tuple[int, int, int]
Segment = tuple[float, float, float, float, _RGB, int]  # x0, y0, x1, y1 (window metres), colour, width


class Canvas:
    """The path image the turtles' pens draw on (RGB plus a mask of what was drawn), and its latest segments."""

    __slots__ = ("rgb", "drawn", "segments")

    def __init__(self) -> None:
        self.rgb = np.full((SIZE, SIZE, 3), 255, dtype=np.uint8)
        self.drawn = np.zeros((SIZE, SIZE), dtype=bool)
        self.segments: deque[Segment] = deque(maxlen=SEGMENTS)

    def clear(self) -> None:
        """Make every pixel transparent white again (the ``/clear`` service)."""
        self.rgb[:] = 255
        self.drawn[:] = False
        self.segments.clear()

    def line(self, x0: float, y0: float, x1: float, y1: float, colour: _RGB, width: int) -> None:
        """A segment between two points in window metres (y down), ``width`` pixels wide.

        A segment with an end at infinity (a teleport far beyond the window, before the walls
        clamp it) is not drawn.
        """
        if not all(math.isfinite(v) for v in (x0, y0, x1, y1)):
            return
        self.segments.append((x0, y0, x1, y1, colour, width))
        ax, ay, bx, by = x0 * METER, y0 * METER, x1 * METER, y1 * METER
        half = max(width, 1) / 2
        left, right = max(0, math.floor(min(ax, bx) - half)), min(SIZE - 1, math.ceil(max(ax, bx) + half))
        top, bottom = max(0, math.floor(min(ay, by) - half)), min(SIZE - 1, math.ceil(max(ay, by) + half))
        if left > right or top > bottom:
            return
        # Offsets from the segment's start of the box's pixel centres: a row and a column, broadcast.
        px = (np.arange(left, right + 1) - ax)[None, :]
        py = (np.arange(top, bottom + 1) - ay)[:, None]
        dx, dy = bx - ax, by - ay
        length2 = dx * dx + dy * dy
        t = np.clip((px * dx + py * dy) / length2, 0.0, 1.0) if length2 > 0 else 0.0
        inside = (px - t * dx) ** 2 + (py - t * dy) ** 2 <= half * half
        self.rgb[top : bottom + 1, left : right + 1][inside] = colour
        self.drawn[top : bottom + 1, left : right + 1][inside] = True

    def pixel(self, x: float, y: float) -> _RGB:
        """The colour of the path image under a point in window metres (the colour sensor's reading)."""
        col = min(max(round(x * METER), 0), SIZE - 1)
        row = min(max(round(y * METER), 0), SIZE - 1)
        r, g, b = self.rgb[row, col]
        return int(r), int(g), int(b)

    def picture(self, background: _RGB, turtles: Iterable[tuple[float, float, float]]) -> np.ndarray:
        """The window as an RGB array: background, the path over it, each turtle (x, y down, heading) on top."""
        image = np.empty((SIZE, SIZE, 3), dtype=np.uint8)
        image[:] = background
        image[self.drawn] = self.rgb[self.drawn]
        rows, cols = np.mgrid[0:SIZE, 0:SIZE]
        for x, y, theta in turtles:
            cx, cy = x * METER, y * METER
            image[(cols - cx) ** 2 + (rows - cy) ** 2 <= (0.3 * METER) ** 2] = _TURTLE_BODY
            hx, hy = cx + math.cos(theta) * 0.32 * METER, cy - math.sin(theta) * 0.32 * METER
            image[(cols - hx) ** 2 + (rows - hy) ** 2 <= (0.12 * METER) ** 2] = _TURTLE_HEAD
        return image


def png_bytes(image: np.ndarray) -> bytes:
    """An RGB uint8 array (rows, columns, 3) as the bytes of a PNG file."""
    height, width, _ = image.shape
    raw = np.zeros((height, width * 3 + 1), dtype=np.uint8)  # each row: filter type 0, then its pixels
    raw[:, 1:] = image.reshape(height, width * 3)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB, no interlace
    pixels = zlib.compress(raw.tobytes())
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", pixels) + chunk(b"IEND", b"")


def write_png(image: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write ``image`` (see :func:`png_bytes`) to ``path``; returns the path."""
    path = Path(path)
    path.write_bytes(png_bytes(image))
    return path
