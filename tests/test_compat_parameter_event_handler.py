"""rclpy's ParameterEventHandler on the overlay: callbacks fed by a real node's /parameter_events."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.parameter import parameter_value_to_python
from actors.compat.rclpy.parameter_event_handler import ParameterEventHandler
from actors.ros.parameter import Parameter
from interfaces.rcl_interfaces.msg import ParameterEvent


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _spin(*nodes, times=3):
    executor = rclpy.executors.SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    for _ in range(times):
        executor.spin_once(timeout_sec=0.1)
    executor.shutdown()


def test_callbacks_see_declarations_and_changes_of_one_node(session):
    watcher = rclpy.create_node("watcher", namespace="/plant")
    target = rclpy.create_node("boiler", namespace="/plant")
    handler = ParameterEventHandler(watcher)
    seen = []
    events = []
    handler.add_parameter_callback(
        "pressure", "boiler", lambda p: seen.append((p.name, parameter_value_to_python(p.value)))
    )
    handler.add_parameter_callback("pressure", "/elsewhere/boiler", lambda p: seen.append("wrong node"))
    handler.add_parameter_event_callback(lambda event: events.append(event.node))

    target.declare_parameter("pressure", 2)
    target.set_parameters([Parameter("pressure", Parameter.Type.INTEGER, 5)])
    target.declare_parameter("colour", "red")
    _spin(watcher, target)

    assert seen == [("pressure", 2), ("pressure", 5)]
    assert events.count("/plant/boiler") == 3


def test_the_newest_callback_runs_first_and_removed_ones_not_at_all(session):
    handler = ParameterEventHandler(rclpy.create_node("orderly"))
    order = []
    first = handler.add_parameter_event_callback(lambda _: order.append("first"))
    handler.add_parameter_event_callback(lambda _: order.append("second"))
    handler._callbacks.event_callback(ParameterEvent(node="/x"))
    assert order == ["second", "first"]

    handler.remove_parameter_event_callback(first)
    with pytest.raises(RuntimeError, match="doesn't exist"):
        handler.remove_parameter_event_callback(first)
    own = handler.add_parameter_callback("p", "", lambda _: order.append("own"))
    assert own.node_name == "/orderly"  # no name: the handler's own node
    handler.remove_parameter_callback(own)
    with pytest.raises(RuntimeError, match="doesn't exist"):
        handler.remove_parameter_callback(own)
    assert handler._callbacks.parameter_callbacks == {}


def test_an_event_lists_new_parameters_before_changed_ones():
    new = Parameter("a", Parameter.Type.INTEGER, 1).to_parameter_msg()
    changed = Parameter("b", Parameter.Type.INTEGER, 2).to_parameter_msg()
    event = ParameterEvent(node="/n", new_parameters=[new], changed_parameters=[changed])
    assert list(ParameterEventHandler.get_parameters_from_event(event)) == [new, changed]
    assert ParameterEventHandler.get_parameter_from_event(event, "b", "/n") is changed
    assert ParameterEventHandler.get_parameter_from_event(event, "b", "/m") is None
