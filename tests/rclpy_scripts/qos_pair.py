"""A talker or listener (argv) with a best-effort (sensor data) or --reliable QoS, for -n cycles of spin_once.

Its own options are parsed with argparse from the arguments remove_ros_args leaves.
"""

import argparse
import sys

import rclpy
from rclpy.qos import QoSProfile, QoSReliabilityPolicy, qos_profile_sensor_data
from std_msgs.msg import String


def main(argv=sys.argv[1:]):
    parser = argparse.ArgumentParser()
    parser.add_argument("role", choices=["talker", "listener"])
    parser.add_argument("--reliable", action="store_true")
    parser.add_argument("-n", "--cycles", type=int, default=5)
    args = parser.parse_args(rclpy.utilities.remove_ros_args(args=argv))
    rclpy.init(args=argv)
    qos = QoSProfile(depth=10, reliability=QoSReliabilityPolicy.RELIABLE) if args.reliable else qos_profile_sensor_data
    node = rclpy.create_node(f"qos_{args.role}")
    node.get_logger().info(
        f"{'reliable' if qos.reliability is QoSReliabilityPolicy.RELIABLE else 'best effort'} {args.role}"
    )
    if args.role == "talker":
        out = node.create_publisher(String, "chatter", qos)
        count = [0]

        def tick():
            out.publish(String(data=f"msg {count[0]}"))
            node.get_logger().info(f"sent msg {count[0]}")
            count[0] += 1

        node.create_timer(1.0, tick)
    else:
        node.create_subscription(String, "chatter", lambda m: node.get_logger().info(f"got {m.data}"), qos)
    for _ in range(args.cycles):
        rclpy.spin_once(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
