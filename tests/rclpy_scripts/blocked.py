"""Blocks in one way (argv[1]) after saying "ready" on stdout: the forms a signal must end."""

import sys
import threading
import time

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.exceptions import NotInitializedException
from rclpy.executors import ExternalShutdownException
from rclpy.task import Future

FORM = sys.argv[1]

rclpy.init()
node = rclpy.create_node("blocked")
client = node.create_client(AddTwoInts, "nobody_serves_this")
if FORM == "rate":
    started = threading.Event()

    def spin() -> None:
        started.set()
        try:
            rclpy.spin(node)
        except (ExternalShutdownException, NotInitializedException):  # the signal came first
            pass

    threading.Thread(target=spin, daemon=True).start()
    started.wait()
    rate = node.create_rate(0.01)
print("ready", flush=True)
if FORM == "spin":
    rclpy.spin(node)
elif FORM == "spin_once":
    while True:
        rclpy.spin_once(node, timeout_sec=1.0)
elif FORM == "future":
    rclpy.spin_until_future_complete(node, Future(), timeout_sec=100.0)
elif FORM == "call":
    client.call(AddTwoInts.Request(a=1, b=2))
elif FORM == "wait_for_service":
    while not client.wait_for_service(timeout_sec=1.0):
        pass
elif FORM == "rate":
    rate.sleep()
elif FORM == "sleep":
    time.sleep(100.0)
elif FORM == "input":
    input()
elif FORM == "busy":
    count = 0
    while True:
        count += 1
print("not stopped", flush=True)
