"""Teleop from a pipe: one key per line (w/s/a/d/x), each held for half a second; prints /odom after each."""

import sys

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

KEYS = {"w": (0.2, 0.0), "s": (-0.2, 0.0), "a": (0.0, 0.5), "d": (0.0, -0.5), "x": (0.0, 0.0)}

rclpy.init()
node = rclpy.create_node("teleop")
pub = node.create_publisher(Twist, "/cmd_vel", 10)
last = []
node.create_subscription(Odometry, "/odom", lambda m: last.__setitem__(slice(None), [m]), 10)
for line in sys.stdin:
    twist = Twist()
    twist.linear.x, twist.angular.z = KEYS.get(line.strip(), (0.0, 0.0))
    pub.publish(twist)
    end = node.get_clock().now().nanoseconds + 500_000_000
    while node.get_clock().now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=0.1)
    if last:
        pose = last[0].pose.pose
        print(f"{line.strip()} {pose.position.x!r} {pose.position.y!r} {pose.orientation.z!r}", flush=True)
rclpy.shutdown()
