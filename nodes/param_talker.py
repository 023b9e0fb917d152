"""The ROS 2 parameters tutorial's node: says hello to ``my_parameter``, then resets it to world."""

from actors import Node, Parameter


class MinimalParam(Node):
    """Node ``minimal_param_node``: every 1 s logs ``Hello <my_parameter>!`` and sets it back to ``world``."""

    def __init__(self) -> None:
        super().__init__("minimal_param_node")
        self.declare_parameter("my_parameter", "world")
        self.timer = self.create_timer(1, self.timer_callback)

    def timer_callback(self) -> None:
        my_param = self.get_parameter("my_parameter").get_parameter_value().string_value
        self.get_logger().info(f"Hello {my_param}!")
        my_new_param = Parameter("my_parameter", Parameter.Type.STRING, "world")
        self.set_parameters([my_new_param])
