"""Two ways of publishing without a Node subclass, picked by argv[1]:

- `closure`: rclpy.create_node, one String reused and changed by a nested timer function;
- `sleep`: a `while rclpy.ok()` loop that publishes and then time.sleep()s half a second.
Run with `with rclpy.init(args=args):` and the examples' KeyboardInterrupt/ExternalShutdown guard.
"""

import sys
import time

import rclpy
from rclpy.executors import ExternalShutdownException
from std_msgs.msg import String


def closure(node):
    out = node.create_publisher(String, "words", 10)
    text = String()
    n = 0

    def tick():
        nonlocal n
        text.data = f"word {n}"
        n += 1
        node.get_logger().info(f"publishing {text.data}")
        out.publish(text)

    node.create_timer(0.5, tick)
    rclpy.spin(node)


def sleeping(node):
    out = node.create_publisher(String, "words", 10)
    n = 0
    while rclpy.ok():
        out.publish(String(data=f"word {n}"))
        node.get_logger().info(f"publishing word {n}")
        n += 1
        time.sleep(0.5)


def main(args=None):
    try:
        with rclpy.init(args=args):
            node = rclpy.create_node("words")
            {"closure": closure, "sleep": sleeping}[sys.argv[1]](node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
