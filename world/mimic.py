"""turtlesim's mimic: makes one turtle copy another's motion, as ROS 2's turtlesim mimic does.

Node ``turtle_mimic`` subscribes ``input/pose`` (turtlesim/Pose) and publishes
``output/cmd_vel`` (geometry_msgs/Twist, depth 1): each pose's linear and
angular velocity become the command.  Remap the two names onto the turtles,
as the "Launching nodes" tutorial does.
"""

from __future__ import annotations

from actors import Node
from interfaces.geometry_msgs.msg import Twist
from interfaces.turtlesim_msgs.msg import Pose

__all__ = ["Mimic"]


class Mimic(Node):
    """Node ``turtle_mimic``: copies the velocities of the poses it hears into commands."""

    def __init__(self) -> None:
        super().__init__("turtle_mimic")
        self.twist_pub = self.create_publisher(Twist, "output/cmd_vel", 1)
        self.create_subscription(Pose, "input/pose", self.on_pose, 1)

    def on_pose(self, pose: Pose) -> None:
        twist = Twist()
        twist.linear.x, twist.angular.z = pose.linear_velocity, pose.angular_velocity
        self.twist_pub.publish(twist)
