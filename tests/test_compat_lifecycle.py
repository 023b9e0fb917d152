"""rclpy's LifecycleNode on the overlay: the managed-node state machine, its services, events and publishers."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.lifecycle import LifecycleNode, ManagedEntity, TransitionCallbackReturn
from actors.ros.lifecycle import TRANSITIONS, LifecycleError, LifecycleMachine
from interfaces.lifecycle_msgs.msg import Transition, TransitionEvent
from interfaces.lifecycle_msgs.srv import ChangeState, GetAvailableTransitions, GetState
from interfaces.std_msgs.msg import UInt32

SUCCESS, FAILURE, ERROR = (
    TransitionCallbackReturn.SUCCESS,
    TransitionCallbackReturn.FAILURE,
    TransitionCallbackReturn.ERROR,
)


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


class Scripted(LifecycleNode):
    """Answers each callback from a script of results, and notes which callback ran from which state."""

    def __init__(self, name, results, **kwargs):
        self.results = dict(results)
        self.calls = []
        super().__init__(name, **kwargs)

    def _answer(self, name, state):
        self.calls.append((name, state.label))
        answer = self.results.get(name, SUCCESS)
        if isinstance(answer, Exception):
            raise answer
        return answer

    def on_configure(self, state):
        return self._answer("on_configure", state)

    def on_activate(self, state):
        return self._answer("on_activate", state)

    def on_error(self, state):
        return self._answer("on_error", state)


def _label(node):
    return node._state_machine.current_state[1]


def test_the_graph_has_rcl_lifecycles_edges():
    machine = LifecycleMachine()
    assert [(t.label, t.id) for t in machine.available()] == [("configure", 1), ("shutdown", 5)]
    assert len(TRANSITIONS) == 25 and {t.id for t in TRANSITIONS} == set(range(1, 8)) | {
        10 * p + r for p in range(1, 7) for r in range(3)
    }
    with pytest.raises(LifecycleError, match="no transition with label 'activate' from state unconfigured"):
        machine.find(label="activate")


def test_results_lead_forward_back_or_through_error_processing(session):
    node = Scripted("moody", {"on_configure": FAILURE}, enable_communication_interface=False)
    assert node.trigger_configure() == FAILURE and _label(node) == "unconfigured"
    node.results["on_configure"] = RuntimeError("disk full")  # an exception is an error
    assert node.trigger_configure() == ERROR and _label(node) == "unconfigured"  # on_error succeeded
    assert node.calls[-1] == ("on_error", "unconfigured")
    node.results.update(on_configure=SUCCESS, on_activate=ERROR, on_error=FAILURE)
    assert node.trigger_configure() == SUCCESS and _label(node) == "inactive"
    assert node.trigger_activate() == ERROR and _label(node) == "finalized"
    assert node.trigger_deactivate() == ERROR  # nothing leaves finalized: logged, refused
    with pytest.raises(LifecycleError, match="Shutdown"):
        node.trigger_shutdown()


def test_managed_entities_follow_the_node_and_publishers_deliver_only_while_active(session):
    node = LifecycleNode("lamp", enable_communication_interface=False)
    seen = []
    listener = rclpy.create_node("eye")
    listener.create_subscription(UInt32, "glow", lambda m: seen.append(m.data), 10)
    out = node.create_lifecycle_publisher(UInt32, "glow", 10)

    class Stubborn(ManagedEntity):
        def on_deactivate(self, state):
            return FAILURE

    node.add_managed_entity(Stubborn())
    out.publish(UInt32(data=1))
    node.trigger_configure()
    node.trigger_activate()
    assert out.is_activated
    out.publish(UInt32(data=2))
    assert node.trigger_deactivate() == FAILURE and _label(node) == "active"  # one entity refused
    rclpy.spin_once(listener, timeout_sec=0.1)
    assert seen == [2]
    with pytest.raises(TypeError, match="ManagedEntity"):
        node.add_managed_entity(object())


def test_the_services_and_events_of_a_managed_node(session):
    node = Scripted("served", {})
    caller = rclpy.create_node("caller")
    events = []
    caller.create_subscription(TransitionEvent, "/served/transition_event", events.append, 10)
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(caller)

    def call(srv_type, name, request):
        future = caller.create_client(srv_type, f"/served/{name}").call_async(request)
        executor.spin_until_future_complete(future, timeout_sec=5)
        return future.result()

    by_label = ChangeState.Request(transition=Transition(label="configure"))
    assert call(ChangeState, "change_state", by_label).success
    assert call(GetState, "get_state", GetState.Request()).current_state.label == "inactive"
    available = call(GetAvailableTransitions, "get_available_transitions", GetAvailableTransitions.Request())
    assert [(d.transition.label, d.goal_state.label) for d in available.available_transitions] == [
        ("cleanup", "cleaningup"), ("activate", "activating"), ("shutdown", "shuttingdown"),
    ]  # fmt: skip
    not_now = ChangeState.Request(transition=Transition(label="deactivate"))
    assert not call(ChangeState, "change_state", not_now).success
    executor.spin_once(timeout_sec=0.1)
    assert [(e.start_state.label, e.goal_state.label) for e in events] == [
        ("unconfigured", "configuring"),
        ("configuring", "inactive"),
    ]
    executor.shutdown()


def test_the_communication_interface_is_optional_and_its_flag_a_bool(session):
    quiet = LifecycleNode("quiet", enable_communication_interface=False)
    assert not quiet._state_machine.service_get_state and not hasattr(quiet, "_service_get_state")
    served = [name for name, _ in quiet.get_service_names_and_types_by_node("quiet", "/")]
    assert "/quiet/get_parameters" in served and not any("state" in name or "transition" in name for name in served)
    with pytest.raises(TypeError, match="bool"):
        LifecycleNode("loud", enable_communication_interface="yes")
