"""Three ways a client waits for add_two_ints(41, 1), picked by argv[1]:

- `until`: spin_until_future_complete on a plain node;
- `poll`: spin_once in a loop until future.done();
- `coroutine`: an async timer callback that awaits call_async, in a reentrant group, on a
  SingleThreadedExecutor spun once at a time; the timer is cancelled after its first run.
"""

import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import SingleThreadedExecutor


def request():
    req = AddTwoInts.Request()
    req.a, req.b = 41, 1
    return req


def until(node, client):
    future = client.call_async(request())
    rclpy.spin_until_future_complete(node, future)
    return future.result().sum


def poll(node, client):
    future = client.call_async(request())
    while rclpy.ok():
        rclpy.spin_once(node)
        if future.done():
            return future.result().sum


def coroutine(node, client):
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    answers = []

    async def ask():
        timer.cancel()
        answers.append((await client.call_async(request())).sum)

    timer = node.create_timer(0.5, ask, callback_group=client.callback_group)
    while rclpy.ok() and not answers:
        executor.spin_once()
    return answers[0]


def main():
    style = sys.argv[1]
    rclpy.init()
    node = rclpy.create_node(f"client_{style}")
    client = node.create_client(AddTwoInts, "add_two_ints", callback_group=ReentrantCallbackGroup())
    while not client.wait_for_service(timeout_sec=1.0):
        node.get_logger().info("waiting for add_two_ints")
    total = {"until": until, "poll": poll, "coroutine": coroutine}[style](node, client)
    node.get_logger().info(f"41 + 1 = {total}")
    rclpy.shutdown()


if __name__ == "__main__":
    main()
