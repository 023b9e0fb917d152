"""Waits for `add_two_ints` (a bool-returning wait, a second at a time), adds argv[1] + argv[2]."""

import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


class AskAdder(Node):
    def __init__(self):
        super().__init__("ask_adder")
        self.client = self.create_client(AddTwoInts, "add_two_ints")
        while not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("no adder yet")
        self.request = AddTwoInts.Request()

    def ask(self, a, b):
        self.request.a, self.request.b = a, b
        future = self.client.call_async(self.request)
        rclpy.spin_until_future_complete(self, future)
        return future.result()


def main():
    rclpy.init()
    node = AskAdder()
    a, b = int(sys.argv[1]), int(sys.argv[2])
    answer = node.ask(a, b)
    node.get_logger().info(f"{a} + {b} = {answer.sum}")
    node.destroy_node()
    rclpy.shutdown()
    return 0 if answer.sum == a + b else 3


if __name__ == "__main__":
    sys.exit(main())
