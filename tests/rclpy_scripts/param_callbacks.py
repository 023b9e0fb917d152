"""Parameters with the three set callbacks: pre-set adds `gain` whenever `speed` is set, on-set accepts,
post-set keeps a copy in attributes the node logs every second."""

import rclpy
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter


class Tunable(Node):
    def __init__(self):
        super().__init__("tunable")
        self.speed = self.declare_parameter("speed", 1.0).value
        self.gain = self.declare_parameter("gain", 0.0).value
        self.add_pre_set_parameters_callback(self.pre)
        self.add_on_set_parameters_callback(self.check)
        self.add_post_set_parameters_callback(self.post)
        self.create_timer(1.0, lambda: self.get_logger().info(f"speed={self.speed} gain={self.gain}"))

    def pre(self, params):
        extra = [Parameter("gain", Parameter.Type.DOUBLE, 2.0) for p in params if p.name == "speed"]
        return params + extra

    def check(self, params):
        return SetParametersResult(successful=all(p.value >= 0 for p in params), reason="no negatives")

    def post(self, params):
        for p in params:
            setattr(self, p.name, p.value)


if __name__ == "__main__":
    rclpy.init()
    rclpy.spin(Tunable())
