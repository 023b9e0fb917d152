"""``actors graph [--output FILE]``: the node/topic graph, as rqt_graph draws it, in Graphviz DOT.

Nodes are ellipses, topics boxes, edges run publisher -> topic -> subscriber.
``/rosout``, ``/parameter_events`` and hidden endpoints are left out unless
``--all``.  For a ``.png`` or ``.svg`` FILE the DOT text goes beside it
(``FILE.dot``) and the image is drawn by Graphviz's ``dot`` when it is on PATH,
else (``.png`` only) by a simple layered drawing with Pillow; with neither, the
DOT file is written and a note says why there is no image.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from actors.cli._client import add_verb, graph_snapshot
from actors.errors import ControlError

if TYPE_CHECKING:
    from actors.ops.control import GraphSnapshot

__all__ = ["register", "to_dot"]

_IMAGES = (".png", ".svg")


def register(subparsers: Any) -> None:
    """Add the ``graph`` command."""
    parser = add_verb(
        subparsers,
        "graph",
        write_graph,
        help="write the node/topic graph as Graphviz DOT (and an image)",
    )
    parser.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        type=Path,
        help="a .dot file, or a .png/.svg image with its .dot beside it (default: <graph name>.dot)",
    )
    parser.add_argument("--all", action="store_true", help="include /rosout, /parameter_events and hidden endpoints")


def write_graph(args: argparse.Namespace) -> int:
    """Write the DOT file (and the image, when asked and possible); print each file written."""
    graph = graph_snapshot(args)
    output: Path = args.output or Path(f"{graph.name}.dot")
    image = output if output.suffix.lower() in _IMAGES else None
    dot_path = output.with_suffix(".dot") if image else output
    try:
        dot_path.write_text(to_dot(graph, everything=args.all))
        print(f"wrote {dot_path}")
        if image is None:
            return 0
        problem = _draw(graph, args.all, dot_path, image)
    except OSError as exc:
        raise ControlError(f"cannot write {exc.filename or output}: {exc.strerror or exc}") from None
    if problem is not None:
        print(f"actors: no image written: {problem}", file=sys.stderr)
        return 1
    print(f"wrote {image}")
    return 0


def _draw(graph: GraphSnapshot, everything: bool, dot_path: Path, image: Path) -> str | None:
    """Draw ``image`` with Graphviz, else with Pillow; the reason when neither can."""
    import shutil
    import subprocess

    kind = image.suffix[1:].lower()
    if shutil.which("dot"):
        try:
            done = subprocess.run(
                ["dot", f"-T{kind}", str(dot_path), "-o", str(image)],
                capture_output=True,
                text=True,
                timeout=60,
            )
        except subprocess.TimeoutExpired:
            return "dot did not finish within 60 s"
        return f"dot failed: {done.stderr.strip()}" if done.returncode else None
    if kind == "png" and _draw_png(graph, everything, image):
        return None
    return "install Graphviz (the dot program)" + (" or Pillow" if kind == "png" else "")


def _edges(graph: GraphSnapshot, everything: bool) -> tuple[list[str], list[str], list[tuple[str, str, bool]]]:
    """Node names, topic names and edges ``(node, topic, node_publishes)`` to draw."""
    from actors.ops.doctor import IGNORED_TOPICS
    from actors.ros.names import is_hidden

    nodes = {n.name for n in graph.nodes if everything or not is_hidden(n.name)}
    topics, edges = [], []
    for topic in graph.topics:
        if not everything and topic.name in IGNORED_TOPICS:
            continue
        ends = [(e.node, True) for e in topic.publishers]
        ends += [(e.node, False) for e in topic.subscriptions]
        ends = [(node, pub) for node, pub in ends if everything or not is_hidden(node)]
        if ends:
            topics.append(topic.name)
            edges += [(node, topic.name, pub) for node, pub in ends]
            nodes.update(node for node, _ in ends)
    return sorted(nodes), topics, edges


def to_dot(graph: GraphSnapshot, *, everything: bool = False) -> str:
    """The graph as Graphviz DOT text (see the module docstring for what is drawn)."""
    nodes, topics, edges = _edges(graph, everything)
    lines = [f'digraph "{graph.name}" {{', "  rankdir=LR;"]
    lines += [f'  "n:{name}" [label="{name}", shape=ellipse];' for name in nodes]
    lines += [f'  "t:{name}" [label="{name}", shape=box];' for name in topics]
    # By topic: the edges into it, then those out of it.
    for node, topic, publishes in sorted(set(edges), key=lambda e: (e[1], not e[2], e[0])):
        a, b = (f"n:{node}", f"t:{topic}") if publishes else (f"t:{topic}", f"n:{node}")
        lines.append(f'  "{a}" -> "{b}";')
    lines.append("}")
    return "\n".join(lines) + "\n"


def _arrowhead(a: tuple[float, float], b: tuple[float, float]) -> list[tuple[float, float]]:
    """The triangle at ``b`` of an arrow from ``a``: 12 px long, 12 px wide, its point on ``b``."""
    length = math.dist(a, b) or 1.0
    ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length  # along the arrow
    back = (b[0] - 12 * ux, b[1] - 12 * uy)
    return [b, (back[0] - 6 * uy, back[1] + 6 * ux), (back[0] + 6 * uy, back[1] - 6 * ux)]


def _draw_png(graph: GraphSnapshot, everything: bool, path: Path) -> bool:
    """Draw columns (publishing nodes, topics, other nodes) with Pillow; False without it."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        return False
    nodes, topics, edges = _edges(graph, everything)
    publishers = {node for node, _, publishes in edges if publishes}
    columns = [
        [n for n in nodes if n in publishers],
        topics,
        [n for n in nodes if n not in publishers],
    ]
    column_width, row_height, margin = 300, 60, 30
    height = margin * 2 + row_height * max(1, *(len(c) for c in columns))
    image = Image.new("RGB", (margin * 2 + column_width * 3, height), "white")
    draw = ImageDraw.Draw(image)
    boxes: dict[tuple[str, str], tuple[float, float, float, float]] = {}
    for index, names in enumerate(columns):
        kind = "t" if index == 1 else "n"
        for row, name in enumerate(names):
            width = draw.textlength(name) + 24
            x = margin + index * column_width + (column_width - width) / 2
            y = margin + row * row_height + 10
            box = boxes[kind, name] = (x, y, x + width, y + 30)
            (draw.rectangle if kind == "t" else draw.ellipse)(box, outline="black", width=2)
            draw.text((x + 12, y + 9), name, fill="black")
    for node, topic, publishes in edges:
        start, end = (boxes["n", node], boxes["t", topic]) if publishes else (boxes["t", topic], boxes["n", node])
        a = (start[2], (start[1] + start[3]) / 2) if start[0] < end[0] else (start[0], (start[1] + start[3]) / 2)
        b = (end[0], (end[1] + end[3]) / 2) if start[0] < end[0] else (end[2], (end[1] + end[3]) / 2)
        draw.line([a, b], fill="gray", width=2)
        draw.polygon(_arrowhead(a, b), fill="black")
    image.save(path)
    return True
