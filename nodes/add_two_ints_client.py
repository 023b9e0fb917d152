"""The ROS 2 service tutorial's client: waits for ``add_two_ints``, sends a and b, logs the sum."""

from actors import Node
from interfaces.example_interfaces.srv import AddTwoInts


class MinimalClientAsync(Node):
    """Node ``minimal_client_async``: one request with parameters ``a`` (41) and ``b`` (1)."""

    def __init__(self) -> None:
        super().__init__("minimal_client_async")
        self.declare_parameter("a", 41)
        self.declare_parameter("b", 1)
        self.cli = self.create_client(AddTwoInts, "add_two_ints")
        self.req = AddTwoInts.Request()

    async def on_start(self) -> None:
        # What the rclpy tutorial's main() does: wait for the server, call, log the result.
        while not await self.cli.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("service not available, waiting again...")
        self.req.a = self.get_parameter("a").value
        self.req.b = self.get_parameter("b").value
        response = await self.cli.call(self.req)
        self.get_logger().info(f"Result of add_two_ints: for {self.req.a} + {self.req.b} = {response.sum}")
