"""Ctrl-C lands while a finaliser runs: the script must still get its KeyboardInterrupt."""

import os
import signal

import rclpy


class Dropped:
    def __del__(self) -> None:
        os.kill(os.getpid(), signal.SIGINT)  # Python runs the handler at its next check: in here
        for _ in range(100):
            pass


rclpy.init()
node = rclpy.create_node("finalised")
try:
    Dropped()  # collected at once
    while True:
        pass
except KeyboardInterrupt:
    print("interrupted", flush=True)
