"""The course's constant-control exercise: a constant Twist on cmd_vel, stopped by /kill."""

from actors import Node
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_msgs.msg import Bool


class ConstantControl(Node):
    """Node ``constant_control``: publishes Twist(v, omega) on ``cmd_vel`` every 0.2 s.

    Parameters ``v`` (m/s, default 0.2) and ``omega`` (rad/s, default 0.0).  A
    std_msgs/Bool true on ``kill`` cancels the timer and publishes one zero
    Twist.  It says "sending constant control..." when it starts and every
    ten seconds after, and one line when the kill arrives.
    """

    def __init__(self) -> None:
        super().__init__("constant_control")
        self.declare_parameter("v", 0.2)
        self.declare_parameter("omega", 0.0)
        self.cmd_pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.2, self.control_callback)
        self.kill_sub = self.create_subscription(Bool, "kill", self.kill_callback, 10)

    def control_callback(self) -> None:
        msg = Twist()  # zero-initialises everything
        msg.linear.x = self.get_parameter("v").value
        msg.angular.z = self.get_parameter("omega").value
        self.cmd_pub.publish(msg)
        self.get_logger().info("sending constant control...", throttle_duration_sec=10.0)

    def kill_callback(self, msg: Bool) -> None:
        if msg.data and not self.timer.is_canceled():
            self.timer.cancel()
            self.cmd_pub.publish(Twist())
            self.get_logger().info("kill received: timer cancelled, zero command sent")
