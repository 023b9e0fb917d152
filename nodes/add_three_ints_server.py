"""The custom-interfaces tutorial's server: ``add_three_ints`` returns a + b + c."""

from actors import Node
from interfaces.tutorial_interfaces.srv import AddThreeInts


class AddThreeIntsService(Node):
    """Node ``add_three_ints_server``: serves ``add_three_ints`` (tutorial_interfaces/srv/AddThreeInts)."""

    def __init__(self) -> None:
        super().__init__("add_three_ints_server")
        self.srv = self.create_service(AddThreeInts, "add_three_ints", self.add_three_ints_callback)

    def add_three_ints_callback(
        self, request: AddThreeInts.Request, response: AddThreeInts.Response
    ) -> AddThreeInts.Response:
        response.sum = request.a + request.b + request.c
        self.get_logger().info(f"Incoming request\na: {request.a} b: {request.b} c: {request.c}")
        return response
