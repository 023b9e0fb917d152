"""The tf frame tree as view_frames draws it: its Graphviz text, an SVG for when Graphviz is missing, the two files.

Shared by ``actors run tf2_tools view_frames`` (a node of the run) and
``actors tf frames`` (the command line, beside a running graph).  The table
drawn is :meth:`~actors.ros.tf_buffer.BufferCore.frame_table`'s.
"""

from __future__ import annotations

import datetime
import shutil
import subprocess
from html import escape
from pathlib import Path
from typing import Any

__all__ = ["frames_dot", "frames_svg", "frame_files", "output_problem", "write_frames"]


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


def frame_files(output: str) -> tuple[Path, Path]:
    """The Graphviz file and the picture for ``-o output`` ("" for the real tool's dated name).

    The picture is a ``.pdf`` when Graphviz's ``dot`` is installed (as the real tool makes it), else an ``.svg``.
    """
    stem = output or datetime.datetime.now().strftime("frames_%Y-%m-%d_%H.%M.%S")
    return Path(f"{stem}.gv"), Path(f"{stem}.pdf" if shutil.which("dot") else f"{stem}.svg")


def output_problem(output: str) -> str | None:
    """Why ``-o output`` cannot be written (checked before listening, so as not to listen in vain), or None."""
    folder = Path(output).parent
    if not folder.is_dir():
        return f"-o {output}: no folder {folder} to write into"
    return None


def write_frames(table: dict[str, dict[str, Any]], recorded_at: float, files: tuple[Path, Path]) -> None:
    """Write the tree to ``files`` (:func:`frame_files`'): Graphviz text, then the picture; OSError if either fails."""
    gv, picture = files
    gv.write_text(frames_dot(table, recorded_at))
    if picture.suffix == ".svg":
        picture.write_text(frames_svg(table, recorded_at))
        return
    dot = shutil.which("dot") or "dot"
    try:
        subprocess.run([dot, "-Tpdf", str(gv), "-o", str(picture)], check=True)
    except subprocess.CalledProcessError as exc:
        raise OSError(f"{dot} exited with status {exc.returncode} drawing {picture}") from None
