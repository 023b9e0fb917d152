"""The ROS 2 action tutorial's server: serves ``fibonacci``, one number per ``period`` seconds."""

import anyio

from actors import CancelResponse, Node, ServerGoalHandle
from interfaces.example_interfaces.action import Fibonacci


class FibonacciActionServer(Node):
    """Node ``fibonacci_action_server``: feedback after each number, canceled on request."""

    def __init__(self) -> None:
        super().__init__("fibonacci_action_server")
        self.period = self.declare_parameter("period", 1.0).value
        self.create_action_server(Fibonacci, "fibonacci", self.execute_callback, cancel=self.cancel_callback)

    def cancel_callback(self, goal_handle: ServerGoalHandle) -> CancelResponse:
        self.get_logger().info("Received cancel request")
        return CancelResponse.ACCEPT

    async def execute_callback(self, goal_handle: ServerGoalHandle) -> Fibonacci.Result:
        self.get_logger().info("Executing goal...")
        sequence = [0, 1]
        for i in range(1, goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                self.get_logger().info("Goal canceled")
                return Fibonacci.Result(sequence=sequence)
            sequence = [*sequence, sequence[i] + sequence[i - 1]]  # a new list: published ones stay as sent
            self.get_logger().info(f"Feedback: {sequence}")
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
            await anyio.sleep(self.period)
        goal_handle.succeed()
        return Fibonacci.Result(sequence=sequence)
