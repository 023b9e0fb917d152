"""view_frames, as tf2_tools's: listens to tf for a while, then writes the frame tree as Graphviz and a picture.

``actors run tf2_tools view_frames [-t SECONDS] [-o NAME]`` listens to ``/tf`` and
``/tf_static`` for ``wait_time`` seconds of the run's clock (5 by default),
then writes ``NAME.gv`` (by default ``frames_<YYYY-MM-DD_HH.MM.SS>``: the real tool's graph: one
edge per frame, labelled with its broadcaster, rate, buffer length and
stamps) and beside it the picture: ``.pdf`` through Graphviz's ``dot`` where
it is installed, as the real tool does, else an ``.svg`` drawn here (frames
in rows by depth, so it needs nothing).
"""

from __future__ import annotations

import argparse
import datetime
import math
import shutil
import subprocess
import sys
from html import escape
from pathlib import Path
from typing import Any

from actors import Node

from .tf_feed import feed

__all__ = ["ViewFrames", "frames_dot", "frames_svg", "main"]


def _as_yaml_reads(value: float, decimals: int) -> str:
    # The real tool reads tf2's YAML (rounded) back into floats and prints those with str().
    return str(float(f"{value:.{decimals}f}"))


def frames_dot(table: dict[str, dict[str, Any]], recorded_at: float) -> str:
    """The Graphviz text of a frame table (:meth:`BufferCore.frame_table`), numbers as view_frames prints them."""
    if not table:
        return 'digraph G { "No tf data received" }'
    lines = ["digraph G {"]
    root = ""
    for child, info in table.items():
        label = (
            f"Broadcaster: {info['broadcaster']}\\nAverage rate: {_as_yaml_reads(info['rate'], 3)}\\n"
            f"Buffer length: {_as_yaml_reads(info['buffer_length'], 3)}\\n"
            f"Most recent transform: {_as_yaml_reads(info['most_recent_transform'], 6)}\\n"
            f"Oldest transform: {_as_yaml_reads(info['oldest_transform'], 6)}\\n"
        )
        lines.append(f'"{info["parent"]}" -> "{child}"[label=" {label}"];')
        if info["parent"] not in table:
            root = info["parent"]  # the legend hangs above the last root found, as in the real tool
    lines.append("edge [style=invis];")
    lines.append(' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";')
    lines.append(f'"Recorded at time: {recorded_at}"[ shape=plaintext ] ;')
    lines.append(f'}}->"{root}";')
    return "\n".join([*lines, "}"])


_BOX_W, _BOX_H, _GAP_X, _ROW = 160, 36, 40, 110


def frames_svg(table: dict[str, dict[str, Any]], recorded_at: float) -> str:
    """An SVG picture of the tree: roots on top, each frame's children in the row under it."""
    children: dict[str, list[str]] = {}
    for child, info in table.items():
        children.setdefault(info["parent"], []).append(child)
    roots = sorted({info["parent"] for info in table.values()} - set(table))
    place: dict[str, tuple[float, int]] = {}
    next_leaf = 0

    def lay(frame: str, depth: int, seen: frozenset[str]) -> float:
        nonlocal next_leaf
        kids = [k for k in sorted(children.get(frame, [])) if k not in seen]  # a loop is drawn once
        if kids:
            xs = [lay(k, depth + 1, seen | {frame}) for k in kids]
            x = (xs[0] + xs[-1]) / 2
        else:
            x, next_leaf = float(next_leaf), next_leaf + 1
        place[frame] = (x, depth)
        return x

    for root in roots:
        lay(root, 0, frozenset())
    width = max(next_leaf, 1) * (_BOX_W + _GAP_X) + _GAP_X
    height = (max((d for _, d in place.values()), default=0) + 1) * _ROW + 60

    def centre(frame: str) -> tuple[float, float]:
        x, depth = place[frame]
        return _GAP_X + x * (_BOX_W + _GAP_X) + _BOX_W / 2, 40 + depth * _ROW + _BOX_H / 2

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height}" font-family="sans-serif">',
        f'<text x="{_GAP_X}" y="20" font-size="12">view_frames Result: recorded at time {recorded_at:.3f}</text>',
    ]
    for child, info in table.items():
        if child not in place or info["parent"] not in place:
            continue
        (x1, y1), (x2, y2) = centre(info["parent"]), centre(child)
        out.append(
            f'<line x1="{x1:.0f}" y1="{y1 + _BOX_H / 2:.0f}" x2="{x2:.0f}" y2="{y2 - _BOX_H / 2:.0f}" stroke="black"/>'
        )
        out.append(
            f'<text x="{(x1 + x2) / 2 + 6:.0f}" y="{(y1 + y2) / 2 + 4:.0f}" font-size="10">'
            f"{escape(str(info['broadcaster']))} · {info['rate']:.1f} Hz</text>"
        )
    for frame in place:
        x, y = centre(frame)
        out.append(
            f'<rect x="{x - _BOX_W / 2:.0f}" y="{y - _BOX_H / 2:.0f}" width="{_BOX_W}" height="{_BOX_H}" '
            'rx="18" fill="white" stroke="black"/>'
        )
        out.append(f'<text x="{x:.0f}" y="{y + 5:.0f}" font-size="14" text-anchor="middle">{escape(frame)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


class ViewFrames(Node):
    """Node ``view_frames``: gathers tf for ``wait_time`` seconds, writes the files, and ends the run."""

    def __init__(self) -> None:
        super().__init__("view_frames")
        wait = self.declare_parameter("wait_time", 5.0).value
        self.output = self.declare_parameter("output", "").value
        self.buffer = feed(self)
        self.written: list[Path] = []
        self.get_logger().info(f"Listening to tf data for {wait} seconds...")
        self.timer = self.create_timer(wait, self.write)

    def write(self) -> None:
        self.timer.cancel()
        self.get_logger().info("Generating graph...")
        table = self.buffer.frame_table()
        sec, nanosec = divmod(self.get_clock().now().nanoseconds, 1_000_000_000)
        stem = self.output or datetime.datetime.now().strftime("frames_%Y-%m-%d_%H.%M.%S")
        dot = shutil.which("dot")
        gv, picture = Path(f"{stem}.gv"), Path(f"{stem}.pdf" if dot else f"{stem}.svg")
        self.get_logger().info(f"Exporting graph in {picture} file...")
        try:
            gv.write_text(frames_dot(table, sec + nanosec / 1e9))
            if dot is not None:
                subprocess.run([dot, "-Tpdf", str(gv), "-o", str(picture)], check=True)
            else:
                picture.write_text(frames_svg(table, sec + nanosec / 1e9))
        except (OSError, subprocess.CalledProcessError) as exc:
            # One line, and the node ends: a restart would only listen and fail again.
            self.get_logger().error(f"cannot write the frame tree: {exc}")
        else:
            self.written = [gv, picture]
        self.destroy_node()


def main() -> int:
    """``view_frames [-t SECONDS]`` under ``actors run``; 2 for bad arguments."""
    from actors.compat.programs import run_native
    from actors.launch.rosargs import parse

    _, args = parse(sys.argv[1:])
    parser = argparse.ArgumentParser(prog="view_frames", description="Writes the tf frame tree to a picture.")
    parser.add_argument("-t", "--wait-time", type=float, default=5.0, help="seconds to listen to tf (default 5)")
    parser.add_argument("-o", "--output", default="", help="output file name, without .gv/.pdf")
    options = parser.parse_args(args)
    if not 0 < options.wait_time < math.inf:
        print(f"view_frames: wait time {options.wait_time} is not a positive number of seconds", file=sys.stderr)
        return 2
    folder = Path(options.output).parent
    if not folder.is_dir():
        print(f"view_frames: -o {options.output}: no folder {folder} to write into", file=sys.stderr)
        return 2
    run_native(ViewFrames, "view_frames", {"wait_time": options.wait_time, "output": options.output})
    return 0
