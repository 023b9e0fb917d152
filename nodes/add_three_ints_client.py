"""The custom-interfaces tutorial's client: sends a, b and c to ``add_three_ints``, logs the sum."""

from actors import Node
from interfaces.tutorial_interfaces.srv import AddThreeInts


class AddThreeIntsClient(Node):
    """Node ``add_three_ints_client``: one request with parameters ``a``, ``b``, ``c`` (2, 3, 1)."""

    def __init__(self) -> None:
        super().__init__("add_three_ints_client")
        for name, default in (("a", 2), ("b", 3), ("c", 1)):
            self.declare_parameter(name, default)
        self.cli = self.create_client(AddThreeInts, "add_three_ints")

    async def on_start(self) -> None:
        while not await self.cli.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("service not available, waiting again...")
        req = AddThreeInts.Request(**{n: self.get_parameter(n).value for n in ("a", "b", "c")})
        response = await self.cli.call(req)
        self.get_logger().info(f"Result of add_three_ints: for {req.a} + {req.b} + {req.c} = {response.sum}")
