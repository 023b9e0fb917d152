"""AsyncParameterClient: another node's parameters through its services, as rclpy's client does."""

from __future__ import annotations

import anyio
import pytest

from actors import Node, Parameter, Runtime
from actors.ros.param_client import AsyncParameterClient
from actors.ros.parameter_store import ParameterType, value_from_msg
from interfaces.rcl_interfaces.msg import ParameterDescriptor, ParameterEvent

pytestmark = pytest.mark.virtual_time


class Blackboard(Node):
    """Like demo_nodes_cpp's parameter_blackboard: takes any parameter."""

    def __init__(self) -> None:
        super().__init__(
            "parameter_blackboard",
            allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=True,
        )
        self.declare_parameter("fixed", 1, ParameterDescriptor(read_only=True))


class Asker(Node):
    def __init__(self) -> None:
        super().__init__("asker")
        self.client = AsyncParameterClient(self, "parameter_blackboard")
        self.events: list[ParameterEvent] = []
        self.answers: list[object] = []
        self.in_my_task: list[bool] = []


async def test_set_list_get_describe_and_delete():
    async with Runtime() as rt:
        asker = rt.spawn(Asker)
        client = asker.client
        assert not client.services_are_ready()
        assert not await client.wait_for_services(timeout_sec=1.0)
        rt.spawn(Blackboard, params={"seeded": "yes"})
        assert await client.wait_for_services(timeout_sec=1.0)
        client.on_parameter_event(asker.events.append)

        set_response = await client.set_parameters(
            [
                Parameter("int_parameter", Parameter.Type.INTEGER, 10),
                Parameter("string_parameter", Parameter.Type.STRING, "Fee Fi Fo Fum").to_parameter_msg(),
                Parameter("fixed", value=2),
            ]
        )
        assert [r.successful for r in set_response.results] == [True, True, False]
        listed = await client.list_parameters(["int_parameter", "string_parameter"], 10)
        assert listed.result.names == ["int_parameter", "string_parameter"]
        got = await client.get_parameters(["int_parameter", "seeded", "ghost"])
        assert [value_from_msg(v) for v in got.values] == [10, "yes", None]
        types = await client.get_parameter_types(["string_parameter"])
        assert list(types.types) == [ParameterType.STRING]  # uint8[]: bytes
        described = await client.describe_parameters(["fixed"])
        assert described.descriptors[0].read_only
        atomic = await client.set_parameters_atomically(
            [Parameter("int_parameter", value=11), Parameter("fixed", value=3)]
        )
        assert not atomic.result.successful
        deleted = await client.delete_parameters(["string_parameter", "fixed"])
        assert [r.successful for r in deleted.results] == [True, False]
        assert not rt.node("parameter_blackboard").has_parameter("string_parameter")
        await anyio.sleep(0.1)
        assert [p.name for e in asker.events for p in e.changed_parameters + e.new_parameters] == [
            "int_parameter",
            "string_parameter",
        ]


async def test_a_callback_runs_in_the_clients_node_with_the_done_future():
    async with Runtime() as rt:
        rt.spawn(Blackboard)
        asker = rt.spawn(Asker)
        await asker.client.wait_for_services()

        def on_done(future) -> None:
            asker.answers.append(value_from_msg(future.result().values[0]))
            asker.in_my_task.append(asker._core.actor.current is not None)

        asker.client.get_parameters(["fixed"], callback=on_done)
        await anyio.sleep(0.1)
        assert asker.answers == [1] and asker.in_my_task == [True]


async def test_an_absolute_remote_name_and_a_namespaced_client():
    async with Runtime() as rt:
        rt.spawn(Blackboard, namespace="robot")
        asker = rt.spawn(Asker, namespace="robot")  # relative: /robot/parameter_blackboard
        assert await asker.client.wait_for_services(timeout_sec=1.0)
        other = AsyncParameterClient(asker, "/robot/parameter_blackboard")
        assert other.services_are_ready()
