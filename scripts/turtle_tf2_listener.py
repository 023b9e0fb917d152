"""turtle2 chases a frame, as the tf2 tutorials' listener: spawns turtle2, then steers it once a second.

Parameter target_frame (default turtle1); argument MODE picks the lookup of the page it follows:
latest (Writing a listener: the latest transform), now (Using time: at the current time, waiting up
to one second), now-nowait (the same without waiting, which fails into the future) or travel
(Traveling in time: turtle1 five seconds ago, through 'world').  A wait inside a callback needs the
listener's callbacks to run meanwhile: "now" spins on a MultiThreadedExecutor (the listener's
subscriptions are in a reentrant group), as examples_tf2_py's blocking waiter does.
"""

import math
import sys

import rclpy
import rclpy.duration
import rclpy.time
from geometry_msgs.msg import Twist
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from tf2_ros import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener
from turtlesim_msgs.srv import Spawn


class Follower(Node):
    def __init__(self, mode: str) -> None:
        super().__init__("turtle_tf2_frame_listener")
        self.mode = mode
        self.target = self.declare_parameter("target_frame", "turtle1").get_parameter_value().string_value
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self)
        self.spawner = self.create_client(Spawn, "spawn")
        self.spawn_future = None
        self.spawned = False
        self.cmd = self.create_publisher(Twist, "turtle2/cmd_vel", 1)
        self.create_timer(1.0, self.on_timer)

    def lookup(self):
        if self.mode == "latest":
            return self.buffer.lookup_transform("turtle2", self.target, rclpy.time.Time())
        now = self.get_clock().now()
        if self.mode == "now":
            return self.buffer.lookup_transform(
                "turtle2", self.target, now, timeout=rclpy.duration.Duration(seconds=1.0)
            )
        if self.mode == "now-nowait":
            return self.buffer.lookup_transform("turtle2", self.target, now)
        # Virtual time starts at 0, and a Time cannot be before it: travel only once 5 s have passed.
        if now.nanoseconds < 5_000_000_000:
            raise TransformException("not yet five seconds into the run")
        when = now - rclpy.duration.Duration(seconds=5.0)
        return self.buffer.lookup_transform_full(
            target_frame="turtle2",
            target_time=rclpy.time.Time(),
            source_frame=self.target,
            source_time=when,
            fixed_frame="world",
            timeout=rclpy.duration.Duration(seconds=0.05),
        )

    def on_timer(self) -> None:
        if not self.spawned:
            if self.spawn_future is None and self.spawner.service_is_ready():
                self.spawn_future = self.spawner.call_async(Spawn.Request(x=4.0, y=2.0, theta=0.0, name=""))
            elif self.spawn_future is not None and self.spawn_future.done():
                self.get_logger().info(f"Successfully spawned {self.spawn_future.result().name}")
                self.spawned = True
            return
        try:
            t = self.lookup()
        except TransformException as ex:
            self.get_logger().info(f"Could not transform turtle2 to {self.target}: {ex}")
            return
        x, y = t.transform.translation.x, t.transform.translation.y
        msg = Twist()
        msg.angular.z = 1.0 * math.atan2(y, x)
        msg.linear.x = 0.5 * math.sqrt(x**2 + y**2)
        self.cmd.publish(msg)


def main() -> None:
    args = rclpy.utilities.remove_ros_args(sys.argv)[1:]
    rclpy.init()
    mode = args[0] if args else "latest"
    node = Follower(mode)
    executor = MultiThreadedExecutor() if mode == "now" else SingleThreadedExecutor()
    executor.add_node(node)
    try:
        executor.spin()
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
