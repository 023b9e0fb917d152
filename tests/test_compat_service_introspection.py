"""Service introspection on the overlay: the events a client and a service publish about each call."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors import codec
from actors.compat.rclpy.service_introspection import ServiceIntrospectionState
from actors.errors import MessageValidationError
from actors.ros.qos import qos_profile_system_default
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.service_msgs.msg import ServiceEventInfo

SENT, RECEIVED = ServiceEventInfo.REQUEST_SENT, ServiceEventInfo.REQUEST_RECEIVED
ANSWERED, GOT = ServiceEventInfo.RESPONSE_SENT, ServiceEventInfo.RESPONSE_RECEIVED


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _setup():
    node = rclpy.create_node("adder")
    service = node.create_service(AddTwoInts, "add", lambda req, resp: AddTwoInts.Response(sum=req.a + req.b))
    client = node.create_client(AddTwoInts, "add")
    events = []
    node.create_subscription(AddTwoInts.Event, "/add/_service_event", events.append, 10)
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(node)
    return node, service, client, events, executor


def _call(executor, client, a, b):
    future = client.call_async(AddTwoInts.Request(a=a, b=b))
    executor.spin_until_future_complete(future, timeout_sec=5)
    for _ in range(3):
        executor.spin_once(timeout_sec=0.01)  # the events of the call's last steps
    return future.result()


def test_contents_carry_the_request_and_response_of_each_step(session):
    node, service, client, events, executor = _setup()
    clock = node.get_clock()
    client.configure_introspection(clock, qos_profile_system_default, ServiceIntrospectionState.CONTENTS)
    service.configure_introspection(clock, qos_profile_system_default, ServiceIntrospectionState.CONTENTS)
    called_at = clock.now().to_msg()
    assert _call(executor, client, 2, 3).sum == 5
    by_step = {e.info.event_type: e for e in events}
    assert sorted(by_step) == [SENT, RECEIVED, ANSWERED, GOT] and len(events) == 4
    assert by_step[SENT].request == [AddTwoInts.Request(a=2, b=3)] and by_step[SENT].response == []
    assert by_step[RECEIVED].request == [AddTwoInts.Request(a=2, b=3)]
    assert by_step[ANSWERED].response == [AddTwoInts.Response(sum=5)] and by_step[ANSWERED].request == []
    assert by_step[GOT].response == [AddTwoInts.Response(sum=5)]
    assert by_step[SENT].info.client_gid == by_step[GOT].info.client_gid != [0] * 16
    assert by_step[SENT].info.sequence_number == by_step[GOT].info.sequence_number == 1
    assert by_step[SENT].info.stamp == called_at  # stamped by the clock given


def test_metadata_leaves_the_messages_out_and_off_stops_the_events(session):
    node, _service, client, events, executor = _setup()
    client.configure_introspection(node.get_clock(), qos_profile_system_default, ServiceIntrospectionState.METADATA)
    _call(executor, client, 1, 1)
    assert [(e.info.event_type, e.request, e.response) for e in events] == [(SENT, [], []), (GOT, [], [])]
    client.configure_introspection(node.get_clock(), qos_profile_system_default, ServiceIntrospectionState.OFF)
    assert node.count_publishers("/add/_service_event") == 0
    _call(executor, client, 4, 4)
    assert len(events) == 2
    client.configure_introspection(node.get_clock(), qos_profile_system_default, ServiceIntrospectionState.METADATA)
    _call(executor, client, 5, 5)
    assert events[-1].info.sequence_number == 3  # calls are counted while the events are off too


def test_every_service_type_has_its_event_type():
    event = AddTwoInts.Event()
    assert AddTwoInts.Event.__ros_type__ == "example_interfaces/srv/AddTwoInts_Event"
    assert (event.request, event.response) == ([], [])
    with pytest.raises(MessageValidationError, match="request"):
        codec.encode_cdr(AddTwoInts.Event(request=[AddTwoInts.Request()] * 2))
