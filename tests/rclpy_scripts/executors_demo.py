"""Executors and callback groups, picked by argv[1]:

- `multi`: a MultiThreadedExecutor(4) spins a node with a 1 s and a 0.5 s timer in one mutually
  exclusive group (both publish) and a second node that logs what arrives;
- `composed`: the same two nodes on one SingleThreadedExecutor;
- `throttled`: a 0.1 s timer in a callback group of our own that hands out tokens (3 to start
  with, one more every 0.5 s);
- `priority`: an Executor subclass of our own that runs the `alarm` node's callbacks on one pool
  and the others on another, from wait_for_ready_callbacks; exits 1 on ExternalShutdownException.
"""

import sys
import threading
from concurrent.futures import ThreadPoolExecutor

import rclpy
from rclpy.callback_groups import CallbackGroup, MutuallyExclusiveCallbackGroup
from rclpy.executors import Executor, ExternalShutdownException, MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String


class TwoTimers(Node):
    def __init__(self):
        super().__init__("two_timers")
        self.n = 0
        self.out = self.create_publisher(String, "ticks", 10)
        group = MutuallyExclusiveCallbackGroup()
        self.create_timer(1.0, self.tick, callback_group=group)
        self.create_timer(0.5, self.tick, callback_group=group)

    def tick(self):
        self.out.publish(String(data=f"tick {self.n}"))
        self.n += 1


class Hearer(Node):
    def __init__(self, topic="ticks"):
        super().__init__("hearer")
        self.create_subscription(String, topic, lambda m: self.get_logger().info(f"heard {m.data}"), 10)


class Alarm(Node):
    def __init__(self):
        super().__init__("alarm")
        self.create_subscription(String, "alarm", lambda m: self.get_logger().info(f"ALARM {m.data}"), 10)


class Tokens(CallbackGroup):
    def __init__(self, node):
        super().__init__()
        self.left = 3
        self.lock = threading.Lock()
        node.create_timer(0.5, self.refill)

    def refill(self):
        with self.lock:
            self.left = min(self.left + 1, 3)

    def can_execute(self, entity):
        return self.left > 0

    def beginning_execution(self, entity):
        with self.lock:
            if self.left > 0:
                self.left -= 1
                return True
            return False

    def ending_execution(self, entity):
        pass


class Priority(Executor):
    def __init__(self):
        super().__init__()
        self.urgent = set()
        self.fast = ThreadPoolExecutor(max_workers=2)
        self.slow = ThreadPoolExecutor(max_workers=1)

    def spin_once(self, timeout_sec=None):
        try:
            handler, _, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
        except StopIteration:
            return
        (self.fast if node in self.urgent else self.slow).submit(handler)


def main():
    mode = sys.argv[1]
    try:
        with rclpy.init():
            if mode == "throttled":
                node = rclpy.create_node("throttled")
                count = [0]

                def tick():
                    node.get_logger().info(f"token {count[0]}")
                    count[0] += 1

                node.create_timer(0.1, tick, callback_group=Tokens(node))
                rclpy.spin(node)
                return
            nodes = [TwoTimers(), Hearer()]
            if mode == "priority":
                executor = Priority()
                alarm = Alarm()
                executor.urgent.add(alarm)
                nodes.append(alarm)
            else:
                executor = MultiThreadedExecutor(num_threads=4) if mode == "multi" else SingleThreadedExecutor()
            for node in nodes:
                executor.add_node(node)
            executor.spin()
    except KeyboardInterrupt:
        pass
    except ExternalShutdownException:
        sys.exit(1)


if __name__ == "__main__":
    main()
