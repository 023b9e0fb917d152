"""The custom-interfaces tutorial's subscriber: logs every tutorial_interfaces/msg/Num heard."""

from actors import Node
from interfaces.tutorial_interfaces.msg import Num


class NumSubscriber(Node):
    """Node ``num_subscriber``: logs ``I heard: "N"`` for each Num on ``topic``."""

    def __init__(self) -> None:
        super().__init__("num_subscriber")
        self.subscription = self.create_subscription(Num, "topic", self.listener_callback, 10)

    def listener_callback(self, msg: Num) -> None:
        self.get_logger().info(f'I heard: "{msg.num}"')
