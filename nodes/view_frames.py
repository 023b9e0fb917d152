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
import math
import sys
from pathlib import Path

from actors import Node
from actors.ops.tf_frames import frame_files, output_problem, write_frames

from .tf_feed import feed

__all__ = ["ViewFrames", "main"]


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
        sec, nanosec = divmod(self.get_clock().now().nanoseconds, 1_000_000_000)
        files = frame_files(self.output)
        self.get_logger().info(f"Exporting graph in {files[1]} file...")
        try:
            write_frames(self.buffer.frame_table(), sec + nanosec / 1e9, files)
        except OSError as exc:
            # One line, and the node ends: a restart would only listen and fail again.
            self.get_logger().error(f"cannot write the frame tree: {exc}")
        else:
            self.written = list(files)
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
    problem = output_problem(options.output)
    if problem is not None:
        print(f"view_frames: {problem}", file=sys.stderr)
        return 2
    run_native(ViewFrames, "view_frames", {"wait_time": options.wait_time, "output": options.output})
    return 0
