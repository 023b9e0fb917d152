"""A heartbeat that also hands each beat to a helper thread of its own through a queue (as to a
logging QueueListener): the helper spends its life parked in ``Queue.get``, outside rclpy."""

import queue
import threading

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int64


class QueuedPulse(Node):
    def __init__(self):
        super().__init__("queued_pulse")
        self.count = 0
        self.handed = queue.Queue()
        self.out = self.create_publisher(Int64, "/heartbeat", 10)
        self.create_timer(1.0, self.on_beat)
        threading.Thread(target=self.helper, daemon=True).start()

    def on_beat(self):
        self.out.publish(Int64(data=self.count))
        self.handed.put(self.count)
        self.count += 1

    def helper(self):
        while True:
            try:
                self.handed.get(timeout=30.0)  # real seconds: only if virtual time never moved
            except queue.Empty:
                self.get_logger().error("the helper waited 30 s of real time for a beat")
                return


if __name__ == "__main__":
    rclpy.init()
    rclpy.spin(QueuedPulse())
    rclpy.shutdown()
