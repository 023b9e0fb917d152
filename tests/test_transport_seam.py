"""The transport seam: graph events from the tables, outlets, inlets, remote services, the merged view."""

from __future__ import annotations

import asyncio
from typing import Any

import anyio
import anyio.abc
import pytest

from actors import DurabilityPolicy, Node, QoSProfile, ReliabilityPolicy, Runtime, ServiceError, SupervisorPolicy
from actors.ros.qos import QoSSnapshot
from actors.transport import Hub, Inlet, Outlet, RemoteEndpoint, RemoteNode, RemoteService, is_proxy
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String
from interfaces.std_srvs.srv import Trigger

pytestmark = pytest.mark.virtual_time


class Recorder:
    """An attachment that writes down every graph event, and may show remote nodes."""

    def __init__(self, remote: list[RemoteNode] | None = None) -> None:
        self.events: list[tuple[str, str, str]] = []
        self.remote = remote or []

    async def __call__(self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any]) -> None:
        runtime.topics.listeners.append(self)
        runtime.services.listeners.append(self)
        task_status.started()
        await anyio.sleep_forever()

    def endpoint_added(self, topic: Any, endpoint: Any) -> None:
        self.events.append(("added", endpoint.node.fqn, topic.name))

    def endpoint_removed(self, topic: Any, endpoint: Any) -> None:
        self.events.append(("removed", endpoint.node.fqn, topic.name))

    def service_added(self, service: Any) -> None:
        self.events.append(("service added", service.node.fqn, service.service_name))

    def service_removed(self, service: Any) -> None:
        self.events.append(("service removed", service.node.fqn, service.service_name))

    def client_added(self, client: Any) -> None:
        self.events.append(("client added", client.node.fqn, client.service_name))

    def client_removed(self, client: Any) -> None:
        self.events.append(("client removed", client.node.fqn, client.service_name))

    def remote_nodes(self) -> list[RemoteNode]:
        return self.remote


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker", start_parameter_services=False)
        self.pub = self.create_publisher(String, "chatter", 10)


class Listener(Node):
    crash_on: str | None = None

    def __init__(self) -> None:
        super().__init__("listener", start_parameter_services=False)
        self.heard: list[str] = []
        self.sub = self.create_subscription(String, "chatter", self.on_msg, 10)

    def on_msg(self, msg: String) -> None:
        if msg.data == self.crash_on:
            raise RuntimeError("crash on purpose")
        self.heard.append(msg.data)


class Caller(Node):
    def __init__(self) -> None:
        super().__init__("caller", start_parameter_services=False)
        self.client = self.create_client(AddTwoInts, "add_two_ints")


class Adder(Node):
    def __init__(self) -> None:
        super().__init__("adder", start_parameter_services=False)
        self.create_service(AddTwoInts, "add_two_ints", self.add)

    def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        response.sum = request.a + request.b
        return response


async def test_listeners_hear_endpoints_come_and_go_but_not_publishes():
    recorder = Recorder()
    async with Runtime(attach=[recorder]) as rt:
        talker = rt.spawn(Talker)
        rt.spawn(Listener)
        talker.pub.publish(String(data="hi"))
        await anyio.sleep(0.1)
        await rt.stop("talker")
        await rt.stop("listener")
    assert [e for e in recorder.events if not e[2].startswith("/parameter")] == [
        ("added", "/talker", "/chatter"),
        ("added", "/listener", "/chatter"),
        ("removed", "/talker", "/chatter"),
        ("removed", "/listener", "/chatter"),
    ]


async def test_a_restarted_subscription_takes_its_place_without_an_event():
    recorder = Recorder()
    Listener.crash_on = "boom"
    try:
        async with Runtime(attach=[recorder], supervisor=SupervisorPolicy(backoff=0.01)) as rt:
            rt.spawn(Listener)
            talker = rt.spawn(Talker)
            talker.pub.publish(String(data="boom"))
            await anyio.sleep(1)
            talker.pub.publish(String(data="after"))
            await anyio.sleep(0.1)
            assert rt.node("listener").heard == ["after"]
            assert [e for e in recorder.events if e[1] == "/listener"] == [("added", "/listener", "/chatter")]
    finally:
        Listener.crash_on = None


async def test_listeners_hear_servers_and_clients_come_and_go():
    recorder = Recorder()
    async with Runtime(attach=[recorder]) as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        caller.destroy_client(caller.client)
        caller.destroy_client(caller.client)  # twice: heard once
        rt.spawn(Caller, name="caller2")
        await rt.stop("adder")
        await rt.stop("caller2")
    assert recorder.events == [
        ("service added", "/adder", "/add_two_ints"),
        ("client added", "/caller", "/add_two_ints"),
        ("client removed", "/caller", "/add_two_ints"),
        ("client added", "/caller2", "/add_two_ints"),
        ("service removed", "/adder", "/add_two_ints"),
        ("client removed", "/caller2", "/add_two_ints"),
    ]


async def test_an_outlet_sends_only_its_publishers_messages_in_order_inside_publish():
    sent: list[tuple[str, str]] = []
    async with Runtime() as rt:
        one = rt.spawn(Talker, name="one")
        two = rt.spawn(Talker, name="two")
        hub = Hub("/_transport", rt.loop, rt.logger)  # its actor never runs: the outlet does not need it
        outlet = Outlet(hub, one.pub, lambda pub, msg: sent.append((pub.node.fqn, msg.data)))
        outlet.attach()
        for i in range(3):
            one.pub.publish(String(data=f"one {i}"))
            assert sent[-1] == ("/one", f"one {i}")  # sent before publish() returned
            two.pub.publish(String(data=f"two {i}"))
        outlet.detach()
        one.pub.publish(String(data="after detach"))
        await anyio.sleep(0.1)
    assert sent == [("/one", "one 0"), ("/one", "one 1"), ("/one", "one 2")]
    assert rt.graph.topic("/chatter") is None  # nothing left behind
    assert hub.actor.pending == 0  # nothing waits for a round of the hub's actor, which nothing runs


async def test_an_outlet_sends_every_message_whatever_the_depth_beside_a_local_subscription():
    sent: list[str] = []
    async with Runtime() as rt:
        talker = rt.spawn(Talker)
        listener = rt.spawn(Listener)
        hub = Hub("/_transport", rt.loop, rt.logger)
        outlet = Outlet(hub, talker.pub, lambda pub, msg: sent.append(msg.data))
        outlet.attach()
        for i in range(15):  # depth 10, all in one turn: nothing waits in the outlet to be dropped
            talker.pub.publish(String(data=str(i)))
        assert sent == [str(i) for i in range(15)] and outlet.queued == 0 and outlet.dropped == 0
        await anyio.sleep(0.1)
        # The local subscription is fed as before: its depth keeps the newest ten.
        assert listener.heard == [str(i) for i in range(5, 15)]
        assert hub.actor.pending == 0


async def test_an_inlet_feeds_every_local_subscription_and_is_not_shown():
    class Latched(Node):
        def __init__(self) -> None:
            super().__init__("latched", start_parameter_services=False)
            self.heard: list[str] = []
            qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
            self.create_subscription(String, "chatter", lambda m: self.heard.append(m.data), qos)

    async with Runtime() as rt:
        listener = rt.spawn(Listener)
        latched = rt.spawn(Latched)
        hub = Hub("/_transport", rt.loop, rt.logger)
        inlet = Inlet(hub, "/chatter", String)
        rt.topics.add_publisher(inlet)
        msg = String(data="from elsewhere")
        inlet.publish(msg)
        await anyio.sleep(0.1)
        assert listener.heard == latched.heard == ["from elsewhere"]
        assert is_proxy(inlet)
        assert rt.graph.topic("/chatter").publishers == ()
        late = rt.spawn(Latched, name="late")
        await anyio.sleep(0.1)
        assert late.heard == []  # no local replay: history is the transport's business
        assert hub.actor.pending == 0


async def test_an_inlet_hands_its_subscribers_the_decoded_message_itself():
    # What a transport decoded belongs to nobody else: no copy, however often the topic's
    # subscriptions change (each change rebuilds the publisher's path).
    class Keeper(Node):
        def __init__(self) -> None:
            super().__init__("keeper", start_parameter_services=False)
            self.kept: list[String] = []
            self.create_subscription(String, "chatter", self.kept.append, 10)

    async with Runtime() as rt:
        first = rt.spawn(Keeper)
        inlet = Inlet(Hub("/_transport", rt.loop, rt.logger), "/chatter", String)
        rt.topics.add_publisher(inlet)
        before = String(data="before")
        inlet.publish(before)
        await anyio.sleep(0.1)
        second = rt.spawn(Keeper, name="second")
        await anyio.sleep(0.1)
        after = String(data="after")
        inlet.publish(after)
        await anyio.sleep(0.1)
        assert first.kept[0] is before
        assert first.kept[1] is after and second.kept[0] is after


async def test_a_remote_service_forwards_calls_and_gives_way_to_a_local_server():
    forwarded: list[tuple[int, int]] = []

    def forward(service: RemoteService, request: Any, future: asyncio.Future[Any]) -> None:
        forwarded.append((request.a, request.b))
        future.set_result(AddTwoInts.Response(sum=-1))

    async with Runtime() as rt:
        hub = Hub("/_transport", rt.loop, rt.logger)
        caller = rt.spawn(Caller)
        waiting = rt.loop.create_task(caller.client.wait_for_service(timeout=5))
        await anyio.sleep(0.1)
        proxy = RemoteService(hub, "/add_two_ints", AddTwoInts, "/far/adder", forward)
        rt.services.add(proxy)
        assert await waiting
        response = await caller.client.call(AddTwoInts.Request(a=2, b=3), timeout=1)
        assert (forwarded, response.sum) == ([(2, 3)], -1)
        assert [s.name for s in rt.graph.services()] == []  # the stand-in is not a server of this graph

        wrong = caller.create_client(Trigger, "add_two_ints")
        with pytest.raises(ServiceError, match="takes example_interfaces/srv/AddTwoInts_Request"):
            await wrong.call(Trigger.Request(), timeout=1)

        rt.spawn(Adder)  # a local server takes the name
        response = await caller.client.call(AddTwoInts.Request(a=2, b=3), timeout=1)
        assert (forwarded, response.sum) == ([(2, 3)], 5)
        rt.services.remove(proxy)  # the transport forgetting its stand-in leaves the local server alone
        assert rt.services.servers["/add_two_ints"].node.fqn == "/adder"
        assert hub.actor.pending == 0


async def test_the_graph_view_shows_remote_nodes_beside_local_ones():
    qos = QoSSnapshot(depth=7, reliability=ReliabilityPolicy.BEST_EFFORT)
    remote = [
        RemoteNode(
            name="/far/talker",
            process="abc123",
            endpoints=(
                RemoteEndpoint(
                    kind="publisher", name="/chatter", type="std_msgs/msg/String", type_hash="RIHS01_x", qos=qos
                ),
                RemoteEndpoint(
                    kind="publisher", name="/only_there", type="std_msgs/msg/Int64", type_hash="RIHS01_y", qos=qos
                ),
                RemoteEndpoint(
                    kind="server",
                    name="/far/add",
                    type="example_interfaces/srv/AddTwoInts",
                    type_hash="RIHS01_z",
                    qos=qos,
                ),
            ),
        )
    ]
    async with Runtime(attach=[Recorder(remote)]) as rt:
        rt.spawn(Listener)
        names = [n.name for n in rt.graph.nodes()]
        assert names == ["/listener", "/far/talker"]
        assert rt.graph.nodes()[1].process == "abc123"
        chatter = rt.graph.topic("/chatter")
        assert [(e.node, e.process, e.type_hash) for e in chatter.publishers] == [("/far/talker", "abc123", "RIHS01_x")]
        assert chatter.subscriptions[0].type_hash.startswith("RIHS01_")  # local hashes where remote ones compare
        assert [t.name for t in rt.graph.topics()] == ["/chatter", "/only_there", "/parameter_events", "/rosout"]
        assert [(s.name, s.node) for s in rt.graph.services()] == [("/far/add", "/far/talker")]
