"""An rclpy action client: asks `fibonacci` for a sequence and follows it to the end.

    python -m actors run --clock virtual --with scripts/fibonacci_action_server.py scripts/fibonacci_action_client.py 5

Arguments: the order (default 6), then how to go about it: `callbacks` (the default: one callback
leads to the next), `cancel` (cancels the goal 2.5 s after it was accepted), `blocking` (spins until
each future is done, in main) or `asyncio` (two goals at once from asyncio tasks, then one more).
"""

import asyncio
import sys

import rclpy
from action_msgs.msg import GoalStatus
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

STATUS = {
    GoalStatus.STATUS_SUCCEEDED: "succeeded",
    GoalStatus.STATUS_CANCELED: "canceled",
    GoalStatus.STATUS_ABORTED: "aborted",
}


class FibonacciClient(Node):
    def __init__(self, order, style):
        super().__init__("fibonacci_client")
        self.order = order
        self.style = style
        self.action = ActionClient(self, Fibonacci, "fibonacci")
        self.get_logger().info("looking for the server")
        self.action.wait_for_server()

    def ask(self):
        return self.action.send_goal_async(Fibonacci.Goal(order=self.order), feedback_callback=self.progress)

    def progress(self, message):
        self.get_logger().info(f"so far: {list(message.feedback.sequence)}")

    def report(self, response):
        outcome = STATUS.get(response.status, f"status {response.status}")
        self.get_logger().info(f"{outcome}: {list(response.result.sequence)}")

    # -- callbacks: each step is a done callback of the previous step's future -----------------

    def start(self):
        self.ask().add_done_callback(self.answered)

    def answered(self, future):
        goal = future.result()
        if not goal.accepted:
            self.get_logger().info("the server said no")
            rclpy.shutdown()
            return
        self.get_logger().info("the server took it")
        self.goal = goal
        if self.style == "cancel":
            self.timer = self.create_timer(2.5, self.give_up)
        goal.get_result_async().add_done_callback(self.finished)

    def give_up(self):
        self.timer.cancel()
        self.get_logger().info("asking to cancel")
        self.goal.cancel_goal_async().add_done_callback(self.cancel_answered)

    def cancel_answered(self, future):
        canceling = future.result().goals_canceling
        self.get_logger().info("the server is canceling" if canceling else "the server would not cancel")

    def finished(self, future):
        self.report(future.result())
        rclpy.shutdown()

    # -- blocking: main spins until each future is done ---------------------------------------

    def run_blocking(self):
        sent = self.ask()
        rclpy.spin_until_future_complete(self, sent)
        goal = sent.result()
        self.get_logger().info("the server took it" if goal.accepted else "the server said no")
        if goal.accepted:
            result = goal.get_result_async()
            rclpy.spin_until_future_complete(self, result)
            self.report(result.result())

    # -- asyncio: rclpy futures awaited by asyncio tasks while a task spins --------------------

    async def one_goal(self, name):
        goal = await self.ask()
        self.get_logger().info(f"{name}: the server took it")
        response = await goal.get_result_async()
        self.get_logger().info(f"{name}: {STATUS[response.status]} with {len(response.result.sequence)} numbers")

    async def run_asyncio(self):
        async def spin():
            while rclpy.ok():
                rclpy.spin_once(self, timeout_sec=0.05)
                await asyncio.sleep(0)

        spinner = asyncio.ensure_future(spin())
        await asyncio.gather(self.one_goal("first"), self.one_goal("second"))
        await self.one_goal("third")
        spinner.cancel()


def main():
    order = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    style = sys.argv[2] if len(sys.argv) > 2 else "callbacks"
    rclpy.init()
    try:
        node = FibonacciClient(order, style)
        if style == "blocking":
            node.run_blocking()
        elif style == "asyncio":
            asyncio.run(node.run_asyncio())
        else:
            node.start()
            rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
