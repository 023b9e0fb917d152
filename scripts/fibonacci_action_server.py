"""An rclpy action server: the Fibonacci sequence, one number a second, goals on a pool of threads.

    python -m actors run --clock virtual --with scripts/fibonacci_action_server.py scripts/fibonacci_action_client.py 5

An optional argument says how accepted goals start (`--with "scripts/fibonacci_action_server.py queue"`):
`parallel` (the default: each at once, side by side), `delayed` (each two seconds after it was
accepted), `queue` (one after the other) or `latest` (a new goal aborts the one running).
"""

import sys
import threading
import time

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node

LONGEST = 40  # longer sequences are refused


class FibonacciServer(Node):
    def __init__(self, policy):
        super().__init__("fibonacci_server")
        self.policy = policy
        self.guard = threading.Lock()
        self.current = None
        self.backlog = []
        self.server = ActionServer(
            self,
            Fibonacci,
            "fibonacci",
            execute_callback=self.compute,
            callback_group=ReentrantCallbackGroup(),  # goals run side by side on the pool's threads
            goal_callback=self.review,
            handle_accepted_callback=self.begin,
            cancel_callback=lambda goal: CancelResponse.ACCEPT,
        )

    def review(self, goal):
        if goal.order > LONGEST:
            self.get_logger().info(f"order {goal.order} is too long, refused")
            return GoalResponse.REJECT
        self.get_logger().info(f"order {goal.order} accepted")
        return GoalResponse.ACCEPT

    def begin(self, goal):
        if self.policy == "delayed":
            self.get_logger().info("starting in 2 s")
            pending = []
            pending.append(self.create_timer(2.0, lambda: (self.destroy_timer(pending[0]), goal.execute())))
            return
        with self.guard:
            if self.policy == "queue" and self.current is not None:
                self.backlog.append(goal)
                self.get_logger().info(f"{len(self.backlog)} goal(s) waiting")
                return
            if self.policy == "latest" and self.current is not None and self.current.is_active:
                self.get_logger().info("a newer goal came: aborting the running one")
                self.current.abort()
            self.current = goal
        goal.execute()

    def compute(self, goal):
        numbers = [0, 1]
        try:
            while len(numbers) <= goal.request.order:
                if not goal.is_active:
                    self.get_logger().info("superseded")
                    return Fibonacci.Result(sequence=numbers)
                if goal.is_cancel_requested:
                    goal.canceled()
                    self.get_logger().info(f"canceled at {numbers[-1]}")
                    return Fibonacci.Result(sequence=numbers)
                numbers.append(numbers[-1] + numbers[-2])
                self.get_logger().info(f"next: {numbers[-1]}")
                goal.publish_feedback(Fibonacci.Feedback(sequence=numbers))
                time.sleep(1.0)  # blocks this pool thread only
            with self.guard:
                if not goal.is_active:
                    self.get_logger().info("superseded")
                    return Fibonacci.Result(sequence=numbers)
                goal.succeed()
            self.get_logger().info(f"done: {numbers}")
            return Fibonacci.Result(sequence=numbers)
        finally:
            self.next_in_line()

    def next_in_line(self):
        if self.policy != "queue":
            return
        with self.guard:
            self.current = self.backlog.pop(0) if self.backlog else None
            if self.current is not None:
                self.get_logger().info("taking the next goal")
                self.current.execute()


def main():
    policy = sys.argv[1] if len(sys.argv) > 1 else "parallel"
    rclpy.init()
    try:
        rclpy.spin(FibonacciServer(policy), executor=MultiThreadedExecutor(num_threads=4))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
