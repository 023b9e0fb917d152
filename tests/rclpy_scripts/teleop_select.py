"""A teleop-style loop: select() on stdin with a timeout, a Twist per line, 'q' to quit; it never spins."""

import select
import sys

import rclpy
from geometry_msgs.msg import Twist

rclpy.init()
node = rclpy.create_node("teleop")
pub = node.create_publisher(Twist, "cmd_vel", 10)
print("ready", flush=True)
while True:
    ready, _, _ = select.select([sys.stdin], [], [], 0.1)
    if not ready:
        continue
    key = sys.stdin.readline().strip()
    if key in ("q", ""):
        break
    pub.publish(Twist())
rclpy.shutdown()
