"""turtle_teleop_key: drives turtle1 from the keyboard, as ROS 2's turtlesim teleop does, key for key.

Node ``teleop_turtle`` with parameters ``scale_linear`` and ``scale_angular``
(both 2.0) publishes ``turtle1/cmd_vel`` (depth 1) and sends goals to the
action ``turtle1/rotate_absolute``.  Keys are read one byte at a time, as the
real program reads its terminal in raw mode, so an arrow key's escape sequence
(ESC ``[`` ``A``) moves the turtle through its last byte: ``A`` forward, ``B``
back, ``C`` turn right, ``D`` turn left, one Twist per key (the turtle stops a
second after the last).  Lower-case ``g b v c d e r t`` send a rotation goal
to 0, -π/4, -π/2, -3π/4, π, 3π/4, π/2 and π/4 (the keys round F), ``f``
cancels the goal, ``q`` quits (the node ends).  Any other byte is ignored.

From a terminal, the terminal is put in raw mode (no echo, no line editing)
and restored at the end.  From a pipe, the bytes are read as they come; at the
end of the input the node stays until the run ends, so its last goal finishes.
Each read runs in a worker thread, so on the virtual clock time stands still
while a key is awaited: a pipe's keys all land at the same instant.
"""

from __future__ import annotations

import os
import sys
from typing import Any, BinaryIO

import anyio

from actors import Node
from actors.errors import ActionError
from interfaces.geometry_msgs.msg import Twist
from interfaces.turtlesim_msgs.action import RotateAbsolute

__all__ = ["BANNER", "GOALS", "TeleopTurtle"]

BANNER = (
    "Reading from keyboard\n"
    "---------------------------\n"
    "Use arrow keys to move the turtle.\n"
    "Use G|B|V|C|D|E|R|T keys to rotate to absolute orientations. 'F' to cancel a rotation.\n"
    "'Q' to quit."
)
MOVES = {b"A": (1.0, 0.0), b"B": (-1.0, 0.0), b"C": (0.0, -1.0), b"D": (0.0, 1.0)}  # (linear, angular)
GOALS = {
    b"g": 0.0,
    b"t": 0.7854,
    b"r": 1.5708,
    b"e": 2.3562,
    b"d": 3.1416,
    b"c": -2.3562,
    b"v": -1.5708,
    b"b": -0.7854,
}


class TeleopTurtle(Node):
    """Node ``teleop_turtle``: reads ``keys`` (stdin by default) and drives turtle1."""

    def __init__(self, keys: BinaryIO | None = None) -> None:
        super().__init__("teleop_turtle")
        self.scale_angular = self.declare_parameter("scale_angular", 2.0).value
        self.scale_linear = self.declare_parameter("scale_linear", 2.0).value
        self.twist_pub = self.create_publisher(Twist, "turtle1/cmd_vel", 1)
        self.rotate_client = self.create_action_client(RotateAbsolute, "turtle1/rotate_absolute")
        self.keys = keys if keys is not None else sys.stdin.buffer
        self.goal: Any = None
        self._cooked: Any = None

    def on_start(self) -> None:
        print(BANNER, flush=True)
        # A task of its own: the node's other work (goal answers) goes on while a key is awaited.
        self._core.start_task(self._read_keys, name="keys of teleop_turtle")

    async def _read_keys(self) -> None:
        self._raw()
        try:
            while True:
                # Abandoned on cancel: a shutdown must not wait for a key nobody will press.
                key = await anyio.to_thread.run_sync(self.keys.read, 1, abandon_on_cancel=True)
                if not key or not self.on_key(key):
                    break
        finally:
            self._restore()
        if key == b"q":
            self.destroy_node()

    def on_key(self, key: bytes) -> bool:
        """Act on one byte; False for ``q``."""
        if key == b"q":
            return False
        if key in MOVES:
            linear, angular = MOVES[key]
            twist = Twist()
            twist.linear.x, twist.angular.z = self.scale_linear * linear, self.scale_angular * angular
            self.twist_pub.publish(twist)
        elif key in GOALS:
            self._core.start_task(self._send_goal, GOALS[key], name=f"rotate to {GOALS[key]}")
        elif key == b"f" and self.goal is not None:
            self._core.start_task(self._cancel, self.goal, name="cancel the rotation")
        return True

    async def _send_goal(self, theta: float) -> None:
        self.goal = await self.rotate_client.send_goal(RotateAbsolute.Goal(theta=theta))

    async def _cancel(self, goal: Any) -> None:
        try:
            await goal.cancel()
        except ActionError:
            pass  # it ended meanwhile, as the real teleop's cancel may find

    def _raw(self) -> None:
        # A terminal gives its keys at once and without echo, as the real teleop sets it.
        fd = _fd(self.keys)
        if fd is None or not os.isatty(fd):
            return
        import termios

        self._cooked = termios.tcgetattr(fd)
        raw = termios.tcgetattr(fd)
        raw[3] &= ~(termios.ICANON | termios.ECHO)
        raw[6][termios.VMIN], raw[6][termios.VTIME] = 1, 0
        termios.tcsetattr(fd, termios.TCSANOW, raw)

    def _restore(self) -> None:
        fd = _fd(self.keys)
        if self._cooked is not None and fd is not None:
            import termios

            termios.tcsetattr(fd, termios.TCSANOW, self._cooked)
            self._cooked = None


def _fd(stream: BinaryIO) -> int | None:
    try:
        return stream.fileno()
    except (AttributeError, OSError, ValueError):
        return None
