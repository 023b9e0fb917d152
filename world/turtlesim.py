"""turtlesim, as ROS 2's turtlesim_node behaves: node ``turtlesim``, an 11×11 m window of turtles.

Seen from outside it is the real node (turtle_frame.cpp): parameters
``background_r``, ``background_g``, ``background_b`` (0..255) and ``holonomic``;
services ``spawn``, ``kill``, ``clear`` and ``reset``; ``turtle1`` spawned at
the centre (5.544445, 5.544445) at start; every turtle updated each 16 ms frame
with dt = 0.016 s (the first frame only starts the count), in name order; the
same log lines.  Each turtle's own topics, services and action are
:class:`world.turtle.Turtle`'s.

There is no window: the picture (:meth:`Turtlesim.picture`, the background,
the pens' trails and the turtles) is drawn on request, and written as a PNG (a
GIF for a name ending in ``.gif``) at shutdown when the parameter ``image`` names a file.  ``image`` is declared only
when given, so ``param list`` shows what the real node's shows.  Beside a live
view (``--foxglove``) the window is a 3D scene on ``/turtlesim/scene``
(:mod:`world.turtlesim_scene`).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from actors import Node
from actors.errors import InvalidNameError
from actors.ros.names import expand
from interfaces.rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from interfaces.std_srvs.srv import Empty
from interfaces.turtlesim_msgs.srv import Kill, Spawn

from .canvas import METER, SIZE, Canvas, write_picture
from .scene import scene_hosts
from .turtle import Turtle, f32

__all__ = ["BACKGROUND", "FRAME_PERIOD", "WORLD_SIZE", "Turtlesim"]

BACKGROUND = (0x45, 0x56, 0xFF)
FRAME_PERIOD = 0.016  # s: the Qt frame's update timer, also the dt of every update
WORLD_SIZE = (SIZE - 1) / METER  # metres: 11.0888...; the centre is 5.544445


class Turtlesim(Node):
    """Node ``turtlesim``: the turtles, their picture, and the services that make and remove them."""

    def __init__(self) -> None:
        super().__init__("turtlesim")
        channel = IntegerRange(from_value=0, to_value=255, step=1)
        for name, colour, default in zip("rgb", ("Red", "Green", "Blue"), BACKGROUND):
            self.declare_parameter(
                f"background_{name}",
                default,
                ParameterDescriptor(description=f"{colour} channel of the background color", integer_range=[channel]),
            )
        self.declare_parameter(
            "holonomic", False, ParameterDescriptor(description="If true, then turtles will be holonomic")
        )
        self._image = ""
        if "image" in self._core.params.overrides:
            self._image = self.declare_parameter(
                "image", "", ParameterDescriptor(description="PNG or GIF file the window is written to at exit")
            ).value
        self.canvas = Canvas()
        self.turtles: dict[str, Turtle] = {}
        self._id_counter = 0
        self._started = False
        self.create_service(Empty, "clear", self.on_clear)
        self.create_service(Empty, "reset", self.on_reset)
        self.create_service(Spawn, "spawn", self.on_spawn)
        self.create_service(Kill, "kill", self.on_kill)
        self.get_logger().info(f"Starting turtlesim with node name {self.get_fully_qualified_name()}")
        self.spawn("", WORLD_SIZE / 2, WORLD_SIZE / 2, 0.0)
        self.timer = self.create_timer(FRAME_PERIOD, self.on_frame)
        self._scene_hosts = scene_hosts(self._core.runtime)
        if self._scene_hosts:
            from .turtlesim_scene import TURTLESIM_TOPIC, turtlesim_scene

            for host in self._scene_hosts:
                host.add_scene(TURTLESIM_TOPIC, lambda now_ns: turtlesim_scene(self, now_ns))

    def spawn(self, name: str, x: float, y: float, theta: float) -> str:
        """Add a turtle at (x, y) facing ``theta`` (world metres, y up); its name, or '' if it cannot be."""
        if not all(math.isfinite(v) for v in (x, y, theta)):
            self.get_logger().error(f"Cannot spawn a turtle at x={x}, y={y}, theta={theta}: not finite")
            return ""
        if not name:
            while True:
                self._id_counter += 1
                name = f"turtle{self._id_counter}"
                if name not in self.turtles:
                    break
        elif name in self.turtles:
            self.get_logger().error(f"A turtle named [{name}] already exists")
            return ""
        else:
            # The real node dies on a name that makes no topic (rclcpp throws); here it is refused.
            try:
                expand(f"{name}/cmd_vel", self.get_namespace(), self.get_name())
            except InvalidNameError as exc:
                self.get_logger().error(f"Cannot spawn a turtle named [{name}]: {exc}")
                return ""
        x, y, theta = f32(x), f32(y), f32(theta)  # the real spawnTurtle takes floats
        self.turtles[name] = Turtle(self, name, x, WORLD_SIZE - y, theta)
        self.turtles = dict(sorted(self.turtles.items()))  # updated in name order, as std::map iterates
        self.get_logger().info(f"Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]")
        return name

    def on_spawn(self, request: Spawn.Request, response: Spawn.Response) -> Spawn.Response:
        response.name = self.spawn(request.name, request.x, request.y, request.theta)
        return response

    def on_kill(self, request: Kill.Request, response: Kill.Response) -> Kill.Response:
        turtle = self.turtles.pop(request.name, None)
        if turtle is None:
            self.get_logger().error(f"Tried to kill turtle [{request.name}], which does not exist")
        else:
            turtle.destroy()
        return response

    def on_clear(self, request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info("Clearing turtlesim.")
        self.canvas.clear()
        return response

    def on_reset(self, request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info("Resetting turtlesim.")
        for turtle in self.turtles.values():
            turtle.destroy()
        self.turtles.clear()
        self._id_counter = 0
        self.spawn("", WORLD_SIZE / 2, WORLD_SIZE / 2, 0.0)
        self.canvas.clear()
        return response

    def on_frame(self) -> None:
        """One frame: every turtle's update (the timer's callback); the first frame only starts the count."""
        if not self._started:
            self._started = True
            return
        for turtle in list(self.turtles.values()):
            turtle.update(FRAME_PERIOD, self.canvas, WORLD_SIZE, WORLD_SIZE)

    def background(self) -> tuple[int, int, int]:
        """The background colour the parameters hold now."""
        r, g, b = (self.get_parameter(f"background_{c}").value for c in "rgb")
        return r, g, b

    def picture(self) -> np.ndarray:
        """The window now, as an RGB array (500×500×3): background, trails, turtles."""
        turtles = [(t.x, t.y, t.theta) for t in self.turtles.values()]
        return self.canvas.picture(self.background(), turtles)

    def save_picture(self, path: str | os.PathLike[str]) -> Path:
        """Write :meth:`picture` to ``path``, a GIF if it ends in ``.gif``, else a PNG; returns the path."""
        return write_picture(self.picture(), path)

    def on_shutdown(self) -> None:
        """Write the window to the file ``image`` names, if any."""
        if self._image:
            self.get_logger().info(f"wrote {self.save_picture(self._image)}")

    def destroy_node(self) -> None:
        if self._scene_hosts:
            from .turtlesim_scene import TURTLESIM_TOPIC

            for host in self._scene_hosts:
                host.remove_scene(TURTLESIM_TOPIC)
        super().destroy_node()
