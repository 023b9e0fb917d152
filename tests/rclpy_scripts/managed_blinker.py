"""A managed node: /blinker blinks on /blinks only while active; /watcher logs what it sees."""

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.lifecycle import Node as ManagedNode
from rclpy.lifecycle import TransitionCallbackReturn
from rclpy.node import Node
from std_msgs.msg import UInt32


class Blinker(ManagedNode):
    def __init__(self):
        super().__init__("blinker")
        self.blinks = 0
        self.out = None

    def on_configure(self, state):
        self.out = self.create_lifecycle_publisher(UInt32, "blinks", 5)
        self.timer = self.create_timer(0.2, self.blink)
        self.get_logger().info(f"configured, coming from {state.label}")
        return TransitionCallbackReturn.SUCCESS

    def blink(self):
        self.blinks += 1
        self.out.publish(UInt32(data=self.blinks))

    def on_cleanup(self, state):
        self.destroy_timer(self.timer)
        self.destroy_lifecycle_publisher(self.out)
        self.get_logger().info("cleaned up")
        return TransitionCallbackReturn.SUCCESS


def main():
    rclpy.init()
    executor = SingleThreadedExecutor()
    blinker = Blinker()
    watcher = Node("watcher")
    watcher.create_subscription(UInt32, "blinks", lambda m: watcher.get_logger().info(f"saw blink {m.data}"), 5)
    executor.add_node(blinker)
    executor.add_node(watcher)
    watcher.get_logger().info("ready")
    executor.spin()


if __name__ == "__main__":
    main()
