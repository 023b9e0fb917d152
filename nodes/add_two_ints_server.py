"""The ROS 2 service tutorial's server: ``add_two_ints`` returns a + b."""

from actors import Node
from interfaces.example_interfaces.srv import AddTwoInts


class MinimalService(Node):
    """Node ``minimal_service``: serves ``add_two_ints`` (example_interfaces/srv/AddTwoInts)."""

    def __init__(self) -> None:
        super().__init__("minimal_service")
        self.srv = self.create_service(AddTwoInts, "add_two_ints", self.add_two_ints_callback)

    def add_two_ints_callback(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        response.sum = request.a + request.b
        self.get_logger().info(f"Incoming request\na: {request.a} b: {request.b}")
        return response
