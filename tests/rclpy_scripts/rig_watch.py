"""Prints every frame tf2 knows once a second, then two lookups across the rig's tree.

examples_tf2_py's frame dumper makes the first calls; this is our own program.
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener


class Watch(Node):
    def __init__(self):
        super().__init__("rig_watch")
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self, spin_thread=False)
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        print(self.buffer.all_frames_as_yaml())
        for target, source in (("lidar", "camera"), ("base", "pan_left")):
            seen = self.buffer.lookup_transform(target, source, Time())
            p, q = seen.transform.translation, seen.transform.rotation
            stamp = seen.header.stamp.sec + seen.header.stamp.nanosec / 1e9
            print(f"{target}->{source} at {stamp!r}: {p.x!r} {p.y!r} {p.z!r} {q.x!r} {q.y!r} {q.z!r} {q.w!r}")


def main():
    try:
        with rclpy.init():
            rclpy.spin(Watch())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
