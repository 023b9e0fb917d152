"""A node's parameter services: what the command line and parameter clients talk to."""

from __future__ import annotations

from typing import Any

import anyio
import pytest
from test_params import Bare, Tuned

from actors import Node, Runtime
from actors.errors import ServiceError
from actors.ros.parameter_store import ParameterType, value_from_msg, value_to_msg
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg
from interfaces.rcl_interfaces.srv import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    SetParameters,
    SetParametersAtomically,
)
from interfaces.std_msgs.msg import Int64

pytestmark = pytest.mark.virtual_time


async def test_the_parameter_services():
    class Asker(Node):
        def __init__(self) -> None:
            super().__init__("asker")

    async with Runtime() as rt:
        rt.spawn(Tuned)
        asker = rt.spawn(Asker)
        core = asker._core
        listed = await core.create_client(ListParameters, "/tuned/list_parameters").call(
            ListParameters.Request(), timeout=1
        )
        # Declaration order, as rclpy answers: use_sim_time first (the node's own), then the class's.
        assert listed.result.names == ["use_sim_time", "speed", "count", "model", "names", "flag"]
        got = await core.create_client(GetParameters, "/tuned/get_parameters").call(
            GetParameters.Request(names=["speed", "names", "ghost"]), timeout=1
        )
        assert [value_from_msg(v) for v in got.values] == [0.5, ["a", "b"], None]
        types = await core.create_client(GetParameterTypes, "/tuned/get_parameter_types").call(
            GetParameterTypes.Request(names=["speed", "ghost"]), timeout=1
        )
        assert list(types.types) == [ParameterType.DOUBLE, ParameterType.NOT_SET]  # uint8[]: bytes
        setter = core.create_client(SetParameters, "/tuned/set_parameters")
        response = await setter.call(
            SetParameters.Request(
                parameters=[
                    ParameterMsg(name="speed", value=value_to_msg(0.25)),
                    ParameterMsg(name="model", value=value_to_msg("x")),
                    ParameterMsg(name="ghost", value=value_to_msg(1)),
                ]
            ),
            timeout=1,
        )
        assert [r.successful for r in response.results] == [True, False, False]
        assert "not declared" in response.results[2].reason  # an answer, not an exception
        atomic = await core.create_client(SetParametersAtomically, "/tuned/set_parameters_atomically").call(
            SetParametersAtomically.Request(
                parameters=[
                    ParameterMsg(name="count", value=value_to_msg(5)),
                    ParameterMsg(name="count", value=value_to_msg(70)),
                ]
            ),
            timeout=1,
        )
        assert not atomic.result.successful and rt.node("tuned").get_parameter("count").value == 3
        described = await core.create_client(DescribeParameters, "/tuned/describe_parameters").call(
            DescribeParameters.Request(names=["count"]), timeout=1
        )
        assert described.descriptors[0].integer_range[0].to_value == 10
        assert rt.node("tuned").get_parameter("speed").value == 0.25


KINDS = [
    "describe_parameters",
    "get_parameters",
    "get_parameter_types",
    "list_parameters",
    "set_parameters",
    "set_parameters_atomically",
]


def listed(rt: Runtime, node: str) -> list[tuple[str, str, str]]:
    """``(name, type, server)`` of the services under ``node`` that ``service list`` shows."""
    return [(s.name, s.type, s.node) for s in rt.graph.services() if s.name.startswith(node + "/")]


class Asker(Node):
    def __init__(self) -> None:
        super().__init__("asker")


async def test_a_node_can_do_without_parameter_services():
    async with Runtime() as rt:
        asker = rt.spawn(Asker)
        rt.spawn(Bare, start_parameter_services=False)
        assert listed(rt, "/bare") == []
        assert asker.get_service_names_and_types_by_node("bare", "/") == []
        assert not asker._core.create_client(GetParameters, "/bare/get_parameters").service_is_ready()


async def test_parameter_services_are_listed_before_anything_builds_them():
    async with Runtime() as rt:
        rt.spawn(Tuned)
        asker = rt.spawn(Asker)
        assert not [n for n in rt.services.servers if n.startswith("/tuned/")]  # none built yet
        types = {
            "describe_parameters": "DescribeParameters",
            "get_parameters": "GetParameters",
            "get_parameter_types": "GetParameterTypes",
            "list_parameters": "ListParameters",
            "set_parameters": "SetParameters",
            "set_parameters_atomically": "SetParametersAtomically",
        }
        expected = [(f"/tuned/{k}", f"rcl_interfaces/srv/{types[k]}", "/tuned") for k in sorted(KINDS)]
        assert listed(rt, "/tuned") == expected
        (info,) = [n for n in rt.graph.nodes() if n.name == "/tuned"]
        assert list(info.serves) == [name for name, _, _ in expected]
        assert asker.get_service_names_and_types_by_node("tuned", "/") == [(n, [t]) for n, t, _ in expected]
        graph_wide = dict(asker.get_service_names_and_types())
        assert all(graph_wide[n] == [t] for n, t, _ in expected)
        assert asker.count_services("/tuned/get_parameters") == 1
        assert not [n for n in rt.services.servers if n.startswith("/tuned/")]  # listing built nothing
        # Building them changes nothing a user sees.
        assert rt.services.get("/tuned/list_parameters") is not None
        assert len([n for n in rt.services.servers if n.startswith("/tuned/")]) == 6
        assert listed(rt, "/tuned") == expected
        assert asker.get_service_names_and_types_by_node("tuned", "/") == [(n, [t]) for n, t, _ in expected]


async def test_unbuilt_parameter_services_go_with_their_node():
    async with Runtime() as rt:
        rt.spawn(Tuned)
        asker = rt.spawn(Asker)
        await rt.stop("tuned")
        assert listed(rt, "/tuned") == []
        assert list(rt.services.deferred("/tuned")) == []
        assert asker.count_services("/tuned/get_parameters") == 0
        client = asker._core.create_client(GetParameters, "/tuned/get_parameters")
        assert not client.service_is_ready()
        assert not await client.wait_for_service(timeout=0.5)


async def test_a_client_made_before_the_node_is_answered_once_it_runs():
    async with Runtime() as rt:
        asker = rt.spawn(Asker)
        client = asker._core.create_client(GetParameters, "/tuned/get_parameters")
        early = client.call_async(GetParameters.Request(names=["speed"]))
        watcher = asker._core.create_client(ListParameters, "/tuned/list_parameters")
        assert not watcher.service_is_ready()
        rt.spawn(Tuned)
        assert client.service_is_ready() and watcher.service_is_ready()
        with anyio.fail_after(1):
            assert value_from_msg((await early).values[0]) == 0.5
            later = await watcher.call(ListParameters.Request(), timeout=1)
        assert "speed" in later.result.names


async def test_a_parameter_service_name_served_by_another_node_is_refused_either_way():
    class Squatter(Node):
        def __init__(self) -> None:
            super().__init__("squatter")
            self.create_service(GetParameters, "/tuned/get_parameters", lambda req, res: res)

    async with Runtime() as rt:
        rt.spawn(Squatter)
        with pytest.raises(ServiceError, match="/squatter already serves it"):
            rt.spawn(Tuned)
    async with Runtime() as rt:
        rt.spawn(Tuned)
        with pytest.raises(ServiceError, match="/tuned already serves it"):
            rt.spawn(Squatter)
    async with Runtime() as rt:
        rt.spawn(Squatter)
        await rt.stop("squatter")
        rt.spawn(Tuned)  # the name is free again, and the services wait to be needed as usual
        assert list(rt.services.deferred("/tuned")) and "/tuned/get_parameters" not in rt.services.servers


async def test_a_listener_joining_a_running_graph_sees_every_parameter_service():
    heard: list[str] = []

    class Late:
        def service_added(self, service: Any) -> None:
            heard.append(service.service_name)

        def service_removed(self, service: Any) -> None:
            heard.remove(service.service_name)

        def client_added(self, client: Any) -> None:
            pass

        def client_removed(self, client: Any) -> None:
            pass

    async with Runtime() as rt:
        rt.spawn(Tuned)
        late = Late()
        rt.services.add_listener(late)
        heard.extend(s.service_name for s in rt.services.servers.values())  # the catch-up, as a transport does
        assert sorted(heard) == [f"/tuned/{k}" for k in sorted(KINDS)]
        rt.spawn(Bare)  # with a listener, a node's services are built and heard of at once
        assert sorted(n for n in heard if n.startswith("/bare/")) == [f"/bare/{k}" for k in sorted(KINDS)]
        await rt.stop("bare")
        assert not [n for n in heard if n.startswith("/bare/")]


class Fragile(Node):
    """Declares a parameter and crashes on a message to /break."""

    instances = 0

    def __init__(self) -> None:
        super().__init__("fragile")
        Fragile.instances += 1
        self.declare_parameter("instance", Fragile.instances)
        self.create_subscription(Int64, "/break", self.on_break, 10)

    def on_break(self, msg: Int64) -> None:
        raise RuntimeError("broken")


async def test_a_call_made_while_the_node_restarts_is_answered_by_the_new_instance():
    Fragile.instances = 0
    async with Runtime() as rt:
        rt.spawn(Fragile)
        asker = rt.spawn(Asker)
        breaker = asker.create_publisher(Int64, "/break", 10)
        breaker.publish(Int64(data=1))
        (child,) = [c for c in rt.supervisor.children if c.cls is Fragile]
        while child.state != "restarting":
            await anyio.sleep(0.01)
        client = asker._core.create_client(GetParameters, "/fragile/get_parameters")
        assert client.service_is_ready()  # the crashed instance's, queuing for the next
        got = await client.call(GetParameters.Request(names=["instance"]), timeout=5)
        assert value_from_msg(got.values[0]) == 2
        assert Fragile.instances == 2
