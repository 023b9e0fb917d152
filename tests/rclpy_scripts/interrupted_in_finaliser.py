"""Ctrl-C lands while a finaliser runs inside a spin: the spin must still end by KeyboardInterrupt."""

import os
import signal
import time

import rclpy


class Dropped:
    def __del__(self) -> None:
        os.kill(os.getpid(), signal.SIGINT)  # Python runs the handler at its next check: in here
        time.sleep(0.01)  # a slow finaliser: other threads run meanwhile


def tick() -> None:
    Dropped()  # collected at once, inside the spin


rclpy.init()
node = rclpy.create_node("finalised")
node.create_timer(0.1, tick)
try:
    rclpy.spin(node)
    print("spin returned", flush=True)  # the context was shut down before the interrupt came
except KeyboardInterrupt:
    print("interrupted", flush=True)
