"""The heartbeat exercise written for actors' own Node; Faltering raises on its third beat."""

from actors import Node
from interfaces.std_msgs.msg import Int64


class Heartbeat(Node):
    def __init__(self):
        super().__init__("heartbeat")
        self.count = 0
        self.out = self.create_publisher(Int64, "/heartbeat", 10)
        self.create_timer(1.0, self.beat)

    def beat(self):
        self.out.publish(Int64(data=self.count))
        self.count += 1


class Faltering(Heartbeat):
    def beat(self):
        if self.count == 2:
            raise RuntimeError("lost count")
        super().beat()
