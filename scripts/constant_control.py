"""The course's constant-control exercise as a student writes it in rclpy.

Drives forward at 0.2 m/s (a Twist on /cmd_vel every 0.2 s) until a std_msgs/Bool true arrives on
/kill; then it cancels its timer and sends one zero Twist.
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Bool


class ConstantControl(Node):
    def __init__(self):
        super().__init__("constant_control")
        self.cmd_pub = self.create_publisher(Twist, "/cmd_vel", 10)
        self.timer = self.create_timer(0.2, self.send_command)
        self.kill_sub = self.create_subscription(Bool, "/kill", self.on_kill, 10)

    def send_command(self):
        cmd = Twist()
        cmd.linear.x = 0.2
        self.cmd_pub.publish(cmd)

    def on_kill(self, msg):
        if msg.data:
            self.timer.cancel()
            self.cmd_pub.publish(Twist())
            self.get_logger().info("killed: stopping")


if __name__ == "__main__":
    rclpy.init()
    node = ConstantControl()
    rclpy.spin(node)
    rclpy.shutdown()
