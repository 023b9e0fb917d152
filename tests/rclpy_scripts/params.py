"""Declares two parameters and prints what the command line made of them, then a debug line."""

import rclpy
from rclpy.node import Node

rclpy.init()
node = Node("tuned")
speed = node.declare_parameter("speed", 1.0).value
label = node.declare_parameter("label", "none").value
print(f"{node.get_fully_qualified_name()} speed={speed} label={label}")
node.get_logger().debug("debug is on")
rclpy.shutdown()
