"""A module-level node serving add_two_ints from a plain function, spun one callback at a time."""

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.executors import ExternalShutdownException

server = None


def add(request, response):
    response.sum = request.a + request.b
    server.get_logger().info(f"sum of {request.a} and {request.b}")
    return response


def main():
    global server
    try:
        with rclpy.init():
            server = rclpy.create_node("loop_server")
            server.create_service(AddTwoInts, "add_two_ints", add)
            while rclpy.ok():
                rclpy.spin_once(server)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
