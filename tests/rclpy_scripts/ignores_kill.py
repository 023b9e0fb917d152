"""A constant controller that forgets to stop: it subscribes to /kill and does nothing with it."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Bool


class Stubborn(Node):
    def __init__(self):
        super().__init__("constant_control")
        self.cmd_pub = self.create_publisher(Twist, "/cmd_vel", 10)
        self.create_timer(0.2, self.drive)
        self.create_subscription(Bool, "/kill", lambda msg: None, 10)

    def drive(self):
        cmd = Twist()
        cmd.linear.x = 0.2
        self.cmd_pub.publish(cmd)


rclpy.init()
rclpy.spin(Stubborn())
