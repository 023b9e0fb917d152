"""Nodes used by the Zenoh transport's two-process tests."""

from __future__ import annotations

import asyncio

import anyio

from actors import DurabilityPolicy, Node, QoSProfile
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

LATCHED = QoSProfile(depth=3, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Latcher(Node):
    """Publishes ``latched 0`` .. ``latched 4`` once, at start, on a transient-local topic (depth 3); names its loop."""

    def __init__(self) -> None:
        super().__init__("latcher")
        pub = self.create_publisher(String, "latched", LATCHED)
        for i in range(5):
            pub.publish(String(data=f"latched {i}"))
        self.get_logger().info(f"published (on {type(asyncio.get_running_loop()).__module__})")


class LateReader(Node):
    """Logs ``got: <data>`` for each message on the transient-local ``latched`` topic."""

    def __init__(self) -> None:
        super().__init__("late_reader")
        qos = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.create_subscription(String, "latched", lambda msg: self.get_logger().info(f"got: {msg.data}"), qos)


class SlowAdder(Node):
    """Serves ``add_two_ints`` but takes a minute to answer (for killing it mid-call)."""

    def __init__(self) -> None:
        super().__init__("slow_adder")
        self.create_service(AddTwoInts, "add_two_ints", self.add)

    async def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        self.get_logger().info("Incoming request")
        await anyio.sleep(60)
        response.sum = request.a + request.b
        return response
