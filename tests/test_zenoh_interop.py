"""Interoperation with zenoh-ros2-sdk, both ways, replayed from its recording (tests/goldens/zenoh_ros2_sdk.json).

A raw Zenoh session plays the SDK's processes: it declares the SDK's own
liveliness tokens and puts, asks or answers exactly the bytes the SDK put on
the wire.  Our runtime with the transport is the other side, unchanged.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import anyio
import pytest
from zenoh_procs import free_port, matched, peer, section, until

from actors import Node, Runtime, codec
from actors.ros.endpoint_info import wire_gids
from actors.transport.zenoh import ZenohTransport
from actors.transport.zenoh.attachment import gid_of, pack, unpack
from actors.transport.zenoh.keys import parse_token
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

SDK = json.loads((Path(__file__).parent / "goldens" / "zenoh_ros2_sdk.json").read_text())
TOPIC_KEY = SDK["samples"][0]["key"]
SERVICE_KEY = SDK["queries"][0]["key"]


def sdk_tokens(node: str) -> list[str]:
    """The SDK's tokens of ``node``: its node token and its endpoint's."""
    return [t for t in SDK["tokens"] if parse_token(t).node == f"/{node}"]


def hub_idle(transport: ZenohTransport) -> bool:
    """Whether nothing waits for a round of the transport's hub actor, which nothing runs (each test checks)."""
    return transport.hub is not None and transport.hub.actor.pending == 0


class Hearer(Node):
    def __init__(self) -> None:
        super().__init__("hearer")
        self.heard: list[str] = []
        self.two = anyio.Event()
        self.create_subscription(String, "topic", self.on_msg, 10)

    def on_msg(self, msg: String) -> None:
        self.heard.append(msg.data)
        if len(self.heard) == 2:
            self.two.set()


class Sayer(Node):
    def __init__(self) -> None:
        super().__init__("sayer")
        self.pub = self.create_publisher(String, "topic", 10)


class Adder(Node):
    def __init__(self) -> None:
        super().__init__("adder")
        self.create_service(AddTwoInts, "add_two_ints", self.add)

    def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        response.sum = request.a + request.b
        return response


class Asker(Node):
    def __init__(self) -> None:
        super().__init__("asker")
        self.client = self.create_client(AddTwoInts, "add_two_ints")


async def test_the_sdks_talker_is_seen_and_heard():
    port = free_port()
    async with Runtime(attach=[transport := ZenohTransport(section(port))]) as rt, peer(port) as sdk:
        tokens = [sdk.liveliness().declare_token(t) for t in sdk_tokens("sdk_talker")]
        hearer = rt.spawn(Hearer)
        pub = await matched(sdk, TOPIC_KEY)
        for sample in SDK["samples"]:
            pub.put(bytes.fromhex(sample["payload"]), attachment=bytes.fromhex(sample["attachment"]))
        with anyio.fail_after(10):
            await hearer.two.wait()
        assert hearer.heard == ["SDK says 0", "SDK says 1"]
        # Our subscription shows the GID the SDK gives it: the xxh3 of its token.
        (ours,) = [str(r.ok.key_expr) for r in sdk.liveliness().get("@ros2_lv/0/**/MS/**/hearer/**")]
        assert [s.gid for s in rt.graph.topic("/topic").subscriptions] == [[*gid_of(ours)]]
        (info,) = hearer.get_subscriptions_info_by_topic("/topic")
        assert info.endpoint_gid == [*gid_of(ours)]
        await until(lambda: any(n.name == "/sdk_talker" for n in rt.graph.nodes()))
        (remote,) = [p for p in rt.graph.topic("/topic").publishers if p.process]
        assert (remote.node, remote.type, remote.why) == ("/sdk_talker", "std_msgs/msg/String", "")
        assert hub_idle(transport)
        for token in tokens:
            token.undeclare()


async def test_the_sdks_listener_gets_our_samples_as_it_would_its_own():
    port = free_port()
    async with Runtime(attach=[transport := ZenohTransport(section(port))]) as rt, peer(port) as sdk:
        got: list[Any] = []
        subscriber = sdk.declare_subscriber(TOPIC_KEY, got.append)
        tokens = [sdk.liveliness().declare_token(t) for t in sdk_tokens("sdk_listener")]
        sayer = rt.spawn(Sayer)
        await until(lambda: sayer.pub.get_subscription_count() == 1)  # the SDK's MS token, nothing else
        sayer.pub.publish(String(data="SDK says 0"))
        await until(lambda: got)
        (sample,) = got
        assert str(sample.key_expr) == TOPIC_KEY
        assert sample.payload.to_bytes().hex() == SDK["samples"][0]["payload"]
        sequence, _, gid = unpack(sample.attachment.to_bytes())
        assert sequence == 1  # rmw_zenoh counts a publisher's samples from 1 (the SDK from 0)
        publisher_token = next(str(r.ok.key_expr) for r in sdk.liveliness().get("@ros2_lv/0/**/MP/**/sayer/**"))
        assert gid == gid_of(publisher_token)
        assert hub_idle(transport)
        # Here it shows the GID it has there, while the transport announces it.
        (info,) = sayer.get_publishers_info_by_topic("/topic")
        (shown,) = rt.graph.topic("/topic").publishers
        assert info.endpoint_gid == shown.gid == [*gid]
        pub = sayer.pub
        sayer.destroy_publisher(pub)
        assert pub not in wire_gids
        for token in tokens:
            token.undeclare()
        subscriber.undeclare()


async def test_the_sdks_client_is_answered_as_its_own_server_answers():
    port = free_port()
    query = SDK["queries"][0]
    async with Runtime(attach=[transport := ZenohTransport(section(port))]) as rt, peer(port) as sdk:
        tokens = [sdk.liveliness().declare_token(t) for t in sdk_tokens("sdk_caller")]
        rt.spawn(Adder)
        with anyio.fail_after(10):
            while True:  # until our queryable is known over there
                replies = await anyio.to_thread.run_sync(
                    lambda: list(
                        sdk.get(
                            query["key"],
                            payload=bytes.fromhex(query["payload"]),
                            attachment=bytes.fromhex(query["attachment"]),
                            timeout=1,
                        )
                    )
                )
                if replies:
                    break
        (reply,) = replies
        sdk_reply = SDK["replies"][0]
        assert str(reply.ok.key_expr) == sdk_reply["key"] == SERVICE_KEY
        assert reply.ok.payload.to_bytes().hex() == sdk_reply["payload"]  # sum 42
        sequence, _, gid = unpack(reply.ok.attachment.to_bytes())
        sdk_sequence, _, sdk_gid = unpack(bytes.fromhex(sdk_reply["attachment"]))
        assert (sequence, gid) == (sdk_sequence, sdk_gid) == unpack(bytes.fromhex(query["attachment"]))[::2]
        assert hub_idle(transport)
        for token in tokens:
            token.undeclare()


async def test_our_client_is_answered_by_the_sdks_server():
    port = free_port()
    sdk_reply = SDK["replies"][0]
    asked: list[tuple[str, bytes, bytes]] = []

    def answer(q: Any) -> None:
        asked.append((str(q.key_expr), q.payload.to_bytes(), q.attachment.to_bytes()))
        sequence, _, gid = unpack(q.attachment.to_bytes())
        q.reply(sdk_reply["key"], bytes.fromhex(sdk_reply["payload"]), attachment=pack(sequence, 0, gid))
        q.drop()

    async with Runtime(attach=[transport := ZenohTransport(section(port))]) as rt, peer(port) as sdk:
        queryable = sdk.declare_queryable(SERVICE_KEY, answer, complete=True)
        tokens = [sdk.liveliness().declare_token(t) for t in sdk_tokens("sdk_adder")]
        asker = rt.spawn(Asker)
        with anyio.fail_after(10):
            assert await asker.client.wait_for_service(timeout=10)
            response = await asker.client.call(AddTwoInts.Request(a=20, b=22), timeout=10)
        assert response.sum == 42
        ((key, payload, attachment),) = asked
        assert key == SERVICE_KEY
        assert payload.hex() == SDK["queries"][0]["payload"]  # the same request, the same bytes
        assert unpack(attachment)[0] == 1  # a client counts its requests from 1, as the SDK's does
        assert codec.decode_cdr(payload, AddTwoInts.Request) == AddTwoInts.Request(a=20, b=22)
        assert hub_idle(transport)
        for token in tokens:
            token.undeclare()
        queryable.undeclare()
