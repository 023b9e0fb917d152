"""Drives turtle1 around a circle (1 m/s, 0.5 rad/s) and, after SECONDS, prints where both turtles are.

With ``--still`` it only reports (something else drives turtle1).
"""

import math
import sys

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim_msgs.msg import Pose


class Leader(Node):
    def __init__(self, seconds: float, drive: bool) -> None:
        super().__init__("leader")
        self.poses: dict[str, Pose] = {}
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        for name in ("turtle1", "turtle2"):
            self.create_subscription(Pose, f"/{name}/pose", lambda p, name=name: self.poses.__setitem__(name, p), 10)
        if drive:
            self.create_timer(0.1, self.drive)
        self.report_timer = self.create_timer(seconds, self.report)

    def drive(self) -> None:
        twist = Twist()
        twist.linear.x, twist.angular.z = 1.0, 0.5
        self.cmd.publish(twist)

    def report(self) -> None:
        self.report_timer.cancel()
        a, b = self.poses["turtle1"], self.poses.get("turtle2")
        where = f"turtle2 {b.x:.3f} {b.y:.3f} " if b is not None else ""
        print(f"turtle1 {a.x:.3f} {a.y:.3f} {where}distance {math.hypot(a.x - b.x, a.y - b.y) if b else -1:.3f}")


def main() -> None:
    rclpy.init()
    node = Leader(float(sys.argv[1]), "--still" not in sys.argv[2:])
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
