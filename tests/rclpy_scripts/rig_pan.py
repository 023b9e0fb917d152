"""Two pan heads on the rig's mast, broadcast on /tf from joint states that a fake encoder publishes at 20 Hz.

Both nodes spin in one SingleThreadedExecutor, as examples_tf2_py's dynamic broadcaster's do; this
is our own program.
"""

import math

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile
from sensor_msgs.msg import JointState
from tf2_ros.transform_broadcaster import TransformBroadcaster

HEADS = {"pan_left": 0.2, "pan_right": -0.2}  # each head's offset along the mast's y


class PanBroadcaster(Node):
    def __init__(self):
        super().__init__("pan_broadcaster")
        self.broadcaster = TransformBroadcaster(self)
        self.create_subscription(JointState, "pan_joints", self.on_joints, QoSProfile(depth=10))

    def on_joints(self, msg):
        heads = []
        for name, angle in zip(msg.name, msg.position):
            if name not in HEADS:
                continue  # a joint that moves no frame of ours
            t = TransformStamped()
            t.header.stamp = msg.header.stamp
            t.header.frame_id = "mast"
            t.child_frame_id = name
            t.transform.translation.y = HEADS[name]
            t.transform.rotation.z = math.sin(angle / 2)
            t.transform.rotation.w = math.cos(angle / 2)
            heads.append(t)
        if heads:
            self.broadcaster.sendTransform(heads)


class Encoder(Node):
    def __init__(self):
        super().__init__("pan_encoder")
        self.pub = self.create_publisher(JointState, "pan_joints", QoSProfile(depth=1))
        self.create_timer(1 / 20.0, self.on_tick)

    def on_tick(self):
        now = self.get_clock().now()
        msg = JointState()
        msg.header.stamp = now.to_msg()
        msg.name = ["pan_left", "pan_right", "tilt"]
        seconds = now.nanoseconds / 1e9
        msg.position = [seconds, -seconds / 2, 1.0]
        self.pub.publish(msg)


def main():
    try:
        with rclpy.init():
            executor = SingleThreadedExecutor()
            for node in (PanBroadcaster(), Encoder()):
                executor.add_node(node)
            executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
