"""The ROS 2 tutorial's listener: logs every String heard on ``topic``."""

from actors import Node
from interfaces.std_msgs.msg import String


class MinimalSubscriber(Node):
    """Node ``minimal_subscriber``: logs ``I heard: "..."`` for each message on ``topic``."""

    def __init__(self) -> None:
        super().__init__("minimal_subscriber")
        self.subscription = self.create_subscription(String, "topic", self.listener_callback, 10)

    def listener_callback(self, msg: String) -> None:
        self.get_logger().info(f'I heard: "{msg.data}"')
