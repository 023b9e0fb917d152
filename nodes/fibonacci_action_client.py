"""The ROS 2 action tutorial's client: sends one ``fibonacci`` goal, logs its feedback and result."""

from actors import Node
from interfaces.example_interfaces.action import Fibonacci


class FibonacciActionClient(Node):
    """Node ``fibonacci_action_client``: a goal of parameter ``order`` (10)."""

    def __init__(self) -> None:
        super().__init__("fibonacci_action_client")
        self.declare_parameter("order", 10)
        self.client = self.create_action_client(Fibonacci, "fibonacci")

    async def on_start(self) -> None:
        # What the rclpy tutorial does with chained callbacks, as one coroutine.
        while not await self.client.wait_for_server(timeout_sec=1.0):
            self.get_logger().info("action server not available, waiting again...")
        goal = Fibonacci.Goal(order=self.get_parameter("order").value)
        goal_handle = await self.client.send_goal(goal)
        if not goal_handle.accepted:
            self.get_logger().info("Goal rejected :(")
            return
        self.get_logger().info("Goal accepted :)")
        async for feedback in goal_handle.feedback():
            self.get_logger().info(f"Received feedback: {feedback.sequence}")
        response = await goal_handle.get_result()
        self.get_logger().info(f"Result: {response.result.sequence}")
