"""turtlesim's window as pixels: the pen's path image, the background, the turtles, and PNG/GIF files of it.

The window is 500×500 pixels, 45 pixels to the metre, y pointing down, as the
real turtlesim's Qt frame is.  The path image starts transparent white (so a
colour sensor over paper nobody drew on reads 255, 255, 255, as ROS 2's does);
the background colour shows through it only in the picture.  Lines are drawn
without anti-aliasing, as a QPainter does by default: every pixel whose centre
lies within half the pen's width of the segment.  numpy only; the PNG writer
is a dozen lines of zlib, the GIF writer a palette and GIF's LZW.
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

__all__ = ["SIZE", "METER", "SEGMENTS", "Segment", "Canvas", "png_bytes", "gif_bytes", "write_picture"]

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


def _palette(image: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A palette of at most 256 colours and each pixel's index into it."""
    colours, index = np.unique(image.reshape(-1, 3), axis=0, return_inverse=True)
    if len(colours) > 256:  # many pen colours: snap to a 6x7x6 cube, which a GIF can hold
        levels = np.array([5, 6, 5])
        snapped = np.rint(image.reshape(-1, 3) / 255.0 * levels).astype(np.int64)
        index = (snapped[:, 0] * 7 + snapped[:, 1]) * 6 + snapped[:, 2]
        cube = np.stack(np.meshgrid(range(6), range(7), range(6), indexing="ij"), axis=-1).reshape(-1, 3)
        colours = np.rint(cube / levels * 255.0).astype(np.uint8)
    return colours.astype(np.uint8), index.reshape(-1)


def _lzw(indices: np.ndarray) -> bytes:
    """GIF's LZW of 8-bit indices: variable-width codes packed least significant bit first."""
    clear, end = 256, 257
    table: dict[tuple[int, int], int] = {}
    next_code, width = 258, 9
    out, bits, nbits = bytearray(), 0, 0

    def emit(code: int) -> None:
        nonlocal bits, nbits
        bits |= code << nbits
        nbits += width
        while nbits >= 8:
            out.append(bits & 0xFF)
            bits >>= 8
            nbits -= 8

    emit(clear)
    pixels = indices.tolist()
    prefix = pixels[0]
    for value in pixels[1:]:
        code = table.get((prefix, value))
        if code is not None:
            prefix = code
            continue
        emit(prefix)
        if next_code == 4096:  # the table is full: start afresh, as decoders expect
            emit(clear)
            table.clear()
            next_code, width = 258, 9
        else:
            table[(prefix, value)] = next_code
            next_code += 1
            if next_code > 1 << width and width < 12:
                width += 1
        prefix = value
    emit(prefix)
    emit(end)
    if nbits:
        out.append(bits & 0xFF)
    return bytes(out)


def gif_bytes(image: np.ndarray) -> bytes:
    """An RGB uint8 array (rows, columns, 3) as the bytes of a GIF file (one frame, 256-colour palette)."""
    height, width, _ = image.shape
    colours, index = _palette(image)
    table = np.zeros((256, 3), dtype=np.uint8)
    table[: len(colours)] = colours
    data = _lzw(index)
    blocks = b"".join(bytes([len(part)]) + part for part in (data[i : i + 255] for i in range(0, len(data), 255)))
    screen = struct.pack("<HHBBB", width, height, 0xF7, 0, 0)  # a global table of 2^(7+1) colours
    frame = b"," + struct.pack("<HHHHB", 0, 0, width, height, 0)
    return b"GIF89a" + screen + table.tobytes() + frame + bytes([8]) + blocks + b"\x00;"


def write_picture(image: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write ``image`` to ``path``: a GIF if its name ends in ``.gif``, else a PNG; returns the path."""
    path = Path(path)
    path.write_bytes(gif_bytes(image) if path.suffix.lower() == ".gif" else png_bytes(image))
    return path
