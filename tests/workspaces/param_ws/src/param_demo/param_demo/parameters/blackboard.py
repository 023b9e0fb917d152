"""A node that takes any parameter it is given: what demo_nodes_cpp's parameter_blackboard is."""

import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node(
        "parameter_blackboard",
        allow_undeclared_parameters=True,
        automatically_declare_parameters_from_overrides=True,
    )
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
