"""The heartbeat exercise, whose timer publishes a string where an Int64 is due."""

import rclpy
from good import Heartbeat
from std_msgs.msg import Int64


class Wordy(Heartbeat):
    def beat(self):
        self.out.publish(Int64(data=str(self.count)))
        self.count += 1


rclpy.init()
rclpy.spin(Wordy())
