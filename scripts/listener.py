"""Logs what arrives on `chatter`; a plain node with a lambda callback, spun one callback at a time."""

import rclpy
from rclpy.executors import ExternalShutdownException
from std_msgs.msg import String


def main(args=None):
    try:
        with rclpy.init(args=args):
            node = rclpy.create_node("listener")
            node.create_subscription(String, "chatter", lambda m: node.get_logger().info(f"got {m.data}"), 10)
            while rclpy.ok():
                rclpy.spin_once(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
