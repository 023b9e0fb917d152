"""Nodes used by the tests' graph files and runtime tests."""

from __future__ import annotations

import os
import signal
from typing import ClassVar

from actors import Node
from interfaces.std_msgs.msg import Int64


class Counter(Node):
    """Publishes 0, 1, 2, ... on ``numbers`` every 0.1 s."""

    def __init__(self) -> None:
        super().__init__("counter")
        self.pub = self.create_publisher(Int64, "numbers", 100)
        self.timer = self.create_timer(0.1, self.tick)
        self.n = 0

    def tick(self) -> None:
        self.pub.publish(Int64(data=self.n))
        self.n += 1


class PoisonEveryFifth(Node):
    """Records what it hears on ``numbers``; raises on every fifth message (4, 9, 14, ...)."""

    heard: ClassVar[list[int]] = []
    instances = 0

    def __init__(self) -> None:
        super().__init__("poisoned")
        type(self).instances += 1
        self.create_subscription(Int64, "numbers", self.on_number, 100)

    def on_number(self, msg: Int64) -> None:
        if msg.data % 5 == 4:
            raise ValueError(f"poison {msg.data}")
        type(self).heard.append(msg.data)


class AlwaysCrash(Node):
    """Raises on every message on ``numbers``."""

    def __init__(self) -> None:
        super().__init__("always_crash")
        self.create_subscription(Int64, "numbers", self.on_number, 10)

    def on_number(self, msg: Int64) -> None:
        raise RuntimeError(f"cannot handle {msg.data}")


def _read_calibration() -> None:
    raise ValueError("no calibration file")


class FailsToStart(Node):
    """Its constructor raises (in a helper of its own), after naming itself."""

    def __init__(self) -> None:
        super().__init__("fails_to_start")
        _read_calibration()


class FailsOnRestart(Node):
    """The first instance crashes in a timer at 0.5 s; every later constructor raises."""

    instances = 0

    def __init__(self) -> None:
        super().__init__("fails_on_restart")
        type(self).instances += 1
        if type(self).instances > 1:
            raise RuntimeError("cannot reopen the device")
        self.create_timer(0.5, self.tick)

    def tick(self) -> None:
        raise OSError("device unplugged")


class InterruptedAtStart(Node):
    """Sends its own process SIGINT while the graph is being spawned: Ctrl-C before the graph runs."""

    def __init__(self) -> None:
        super().__init__("interrupted_at_start")
        os.kill(os.getpid(), signal.SIGINT)
