"""Prints its arguments without ROS's, then exits with the code its first argument names."""

import sys

import rclpy
from rclpy.utilities import remove_ros_args

rclpy.init()
print("args:", remove_ros_args(sys.argv)[1:])
print("namespace:", rclpy.create_node("probe").get_namespace())
rclpy.shutdown()
sys.exit(int(remove_ros_args(sys.argv)[1]))
