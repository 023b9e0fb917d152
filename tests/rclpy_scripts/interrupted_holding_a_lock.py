"""Ctrl-C lands while the main thread runs the runtime's code (it holds the session's turn)."""

import os
import signal
import threading

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor

from actors.compat.rclpy.context import current_session


def tick() -> None:
    session = current_session()
    assert session is not None
    with session.lock:  # what every call into the runtime holds
        os.kill(os.getpid(), signal.SIGINT)  # the handler runs at Python's next check: in here
        for _ in range(100):
            pass


def spin_beside(executor: SingleThreadedExecutor) -> None:
    try:
        executor.spin()  # waits on the context: the interrupt must wake it
    except ExternalShutdownException:
        pass


rclpy.init()
beside = SingleThreadedExecutor()
beside.add_node(rclpy.create_node("beside"))
threading.Thread(target=spin_beside, args=(beside,)).start()
node = rclpy.create_node("locked")
node.create_timer(0.1, tick)
try:
    rclpy.spin(node)
except (KeyboardInterrupt, ExternalShutdownException) as exc:
    print(type(exc).__name__, flush=True)
