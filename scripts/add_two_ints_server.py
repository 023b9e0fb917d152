"""Serves `add_two_ints` (example_interfaces/AddTwoInts) and logs each request."""

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


class Adder(Node):
    def __init__(self):
        super().__init__("adder")
        self.create_service(AddTwoInts, "add_two_ints", self.add)

    def add(self, request, response):
        response.sum = request.a + request.b
        self.get_logger().info(f"adding {request.a} and {request.b}")
        return response


if __name__ == "__main__":
    rclpy.init()
    rclpy.spin(Adder())
