"""A script whose timer callback raises: the error leaves spin() and ends the script."""

import rclpy

rclpy.init()
node = rclpy.create_node("broken")
node.create_timer(0.5, lambda: 1 / 0)
rclpy.spin(node)
