"""A timer triggers a guard condition; the guard's callback shuts rclpy down; the loop spins once at a time."""

import rclpy
from rclpy.executors import SingleThreadedExecutor

rclpy.init()
node = rclpy.create_node("guarded")
executor = SingleThreadedExecutor()
executor.add_node(node)


def on_guard():
    rclpy.shutdown()
    node.get_logger().info("guard: shut down")


def on_timer():
    guard.trigger()
    node.get_logger().info("timer: triggered")


node.create_timer(1.5, on_timer)
guard = node.create_guard_condition(on_guard)
while rclpy.ok():
    node.get_logger().info("spinning once")
    executor.spin_once()
node.get_logger().info("done")
