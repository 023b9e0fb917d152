"""The demo talker and listener of ``demo_nodes_cpp``/``demo_nodes_py``: "Hello World: N" on ``chatter``."""

from actors import Node
from interfaces.std_msgs.msg import String


class Talker(Node):
    """Node ``talker``: "Hello World: N" on ``chatter`` every second, N from 1, as ``demo_nodes_cpp``'s."""

    first = 1
    quote = "'"
    depth = 7

    def __init__(self) -> None:
        super().__init__("talker")
        self.count = self.first
        self.pub = self.create_publisher(String, "chatter", self.depth)
        self.timer = self.create_timer(1.0, self.tick)

    def tick(self) -> None:
        msg = String(data=f"Hello World: {self.count}")
        self.count += 1
        self.get_logger().info(f"Publishing: {self.quote}{msg.data}{self.quote}")
        self.pub.publish(msg)


class PyTalker(Talker):
    """``demo_nodes_py``'s talker: N from 0, the text in double quotes, a queue of 10."""

    first = 0
    quote = '"'
    depth = 10


class Listener(Node):
    """Node ``listener``: logs ``I heard: [...]`` for each String on ``chatter`` (both packages' listener)."""

    def __init__(self) -> None:
        super().__init__("listener")
        self.sub = self.create_subscription(String, "chatter", self.heard, 10)

    def heard(self, msg: String) -> None:
        self.get_logger().info(f"I heard: [{msg.data}]")
