"""A script node calls its own service, as rclpy lets it: its executor answers while the caller waits."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from actors.compat.rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from actors.errors import ServiceError
from actors.ros.node import Node as NativeNode
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import Int64


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _adder(node, group=None):
    def add(request, response):
        response.sum = request.a + request.b
        return response

    return node.create_service(AddTwoInts, "add", add, callback_group=group)


def test_a_request_to_its_own_service_is_answered_once_the_node_is_spun(session):
    node = rclpy.create_node("self_caller")
    _adder(node)
    client = node.create_client(AddTwoInts, "add")
    future = client.call_async(AddTwoInts.Request(a=2, b=3))
    rclpy.spin_until_future_complete(node, future, timeout_sec=5)
    assert future.result().sum == 5


def test_a_blocking_call_from_a_reentrant_callback_on_a_multithreaded_executor(session):
    node = rclpy.create_node("reentrant_self_caller")
    group = ReentrantCallbackGroup()
    _adder(node, group)
    client = node.create_client(AddTwoInts, "add", callback_group=group)
    sums: list[int] = []

    def on_number(msg: Int64) -> None:
        sums.append(client.call(AddTwoInts.Request(a=msg.data, b=10)).sum)

    node.create_subscription(Int64, "numbers", on_number, 10, callback_group=group)
    pub = node.create_publisher(Int64, "numbers", 10)
    # Each waiting callback holds a worker; the service's callback needs one more, as in rclpy.
    executor = MultiThreadedExecutor(num_threads=3)
    executor.add_node(node)
    pub.publish(Int64(data=1))
    pub.publish(Int64(data=2))
    while len(sums) < 2:
        executor.spin_once(timeout_sec=1)
    assert sorted(sums) == [11, 12]
    executor.shutdown()


def test_an_async_callback_awaits_its_own_service_on_one_thread(session):
    # The awaiting callback holds its group until it ends, as in rclpy: the service and the
    # client's response must not wait for that group, or the await never ends.
    node = rclpy.create_node("async_self_caller")
    _adder(node, MutuallyExclusiveCallbackGroup())
    client = node.create_client(AddTwoInts, "add", callback_group=ReentrantCallbackGroup())
    sums: list[int] = []

    async def tick() -> None:
        timer.cancel()
        response = await client.call_async(AddTwoInts.Request(a=20, b=22))
        sums.append(response.sum)

    timer = node.create_timer(0.1, tick)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    while not sums:
        executor.spin_once(timeout_sec=1)
    assert sums == [42]
    executor.shutdown()


class Native(NativeNode):
    def __init__(self) -> None:
        super().__init__("native_self_caller")
        self.create_service(AddTwoInts, "native_add", lambda req, res: res)
        self.client = self.create_client(AddTwoInts, "native_add")


def test_a_native_node_is_still_refused_because_its_callbacks_run_one_at_a_time(session):
    native = session.call(session.runtime.spawn, Native)
    with pytest.raises(ServiceError, match="calls its own service"):
        session.call(native.client.call_async, AddTwoInts.Request())
