"""The Zenoh transport against what the network may do: bad samples, bad tokens, unknown hashes, a dying server.

These run a runtime with the transport in the test's own process, beside a
raw Zenoh session playing the other process (or a real second process where
one has to be killed).
"""

from __future__ import annotations

import logging

import anyio
import pytest
from zenoh_procs import free_port, matched, peer, section, spawned, until, zenoh_env

from actors import Node, Runtime, ServiceError
from actors.ops.doctor import diagnose
from actors.transport.zenoh import ZenohTransport
from actors.transport.zenoh.attachment import pack
from actors.transport.zenoh.keys import data_key
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

STRING_HASH = "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
TOPIC_KEY = data_key(0, "/chatter", "std_msgs/msg/String", STRING_HASH)


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.heard: list[str] = []
        self.got = anyio.Event()
        self.create_subscription(String, "chatter", self.on_msg, 10)

    def on_msg(self, msg: String) -> None:
        self.heard.append(msg.data)
        self.got.set()


class Caller(Node):
    def __init__(self) -> None:
        super().__init__("caller")
        self.client = self.create_client(AddTwoInts, "add_two_ints")


async def test_malformed_samples_are_dropped_and_logged_once_per_key_then_summed_up(caplog):
    port = free_port()
    caplog.set_level(logging.WARNING)
    async with Runtime(attach=[ZenohTransport(section(port))]) as rt, peer(port) as session:
        listener = rt.spawn(Listener)
        pub = await matched(session, TOPIC_KEY)
        good = b"\x00\x01\x00\x00" + (3).to_bytes(4, "little") + b"ok\x00"
        for i in range(3):  # a length past the end, each under another GID
            pub.put(b"\x00\x01\x00\x00\xff\xff\xff\x7fno", attachment=pack(i + 1, 0, bytes([i]) * 16))
        pub.put(good, attachment=b"\x01\x02")  # an attachment that is not one
        pub.put(good, attachment=pack(4, 0, bytes(16)))
        with anyio.fail_after(10):
            await listener.got.wait()
    assert listener.heard == ["ok"]
    warnings = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warnings) == 2, warnings  # the first, then what was left out when the transport closed
    assert "malformed sample" in warnings[0] and bytes(16).hex() in warnings[0] and TOPIC_KEY in warnings[0]
    assert warnings[1].startswith("left out 3 more warning(s) like these in ")
    assert f" s: 3 on {TOPIC_KEY}" in warnings[1]


@pytest.mark.slow
async def test_a_token_with_an_unknown_type_hash_is_ignored_and_doctor_says_why(caplog):
    port = free_port()
    other_hash = "RIHS01_" + "ab" * 32
    async with Runtime(attach=[ZenohTransport(section(port))]) as rt, peer(port) as session:
        liveliness = session.liveliness()
        zid = str(session.info.zid())
        tokens = [
            liveliness.declare_token(f"@ros2_lv/0/{zid}/0/0/NN/%/%/old_talker"),
            liveliness.declare_token(
                f"@ros2_lv/0/{zid}/0/1/MP/%/%/old_talker/%chatter/std_msgs::msg::dds_::String_/{other_hash}/::,10:,:,:,,"
            ),
            liveliness.declare_token(
                f"@ros2_lv/0/{zid}/0/2/MP/%/%/old_talker/%odd/foo_msgs::msg::dds_::Bar_/{other_hash}/::,10:,:,:,,"
            ),
            liveliness.declare_token(f"@ros2_lv/0/{zid}/0/3/XX/%/%/old_talker"),  # not rmw_zenoh's at all
        ]
        rt.spawn(Listener)
        await until(lambda: len(rt.graph.topic("/chatter").publishers) >= 1 and rt.graph.topic("/odd") is not None)
        chatter = rt.graph.topic("/chatter")
        (remote,) = chatter.publishers
        assert (remote.node, remote.process, remote.type_hash) == ("/old_talker", zid, other_hash)
        assert f"std_msgs/msg/String is {STRING_HASH} here, {other_hash} there" in remote.why
        report = diagnose(rt)
        check = next(c for c in report.checks if c.name == "type hashes")
        assert not check.passed
        assert any("/chatter: /old_talker" in r and "its data is ignored" in r for r in check.reasons)
        assert any("/odd: /old_talker" in r and "foo_msgs/msg/Bar is not known" in r for r in check.reasons)
        for token in tokens:
            token.undeclare()
    assert sum("not rmw_zenoh's" in r.getMessage() for r in caplog.records) == 1


@pytest.mark.slow
async def test_a_server_process_killed_during_a_call_fails_the_call_at_once(tmp_path):
    port = free_port()
    graph = tmp_path / "slow.toml"
    graph.write_text('[transport]\nkind = "zenoh"\n\n[[nodes]]\nuse = "zenoh_nodes:SlowAdder"\n')
    async with (
        spawned("-m", "actors.run", str(graph), env=zenoh_env(port)) as server,
        Runtime(attach=[ZenohTransport(section(port))]) as rt,
    ):
        caller = rt.spawn(Caller)
        with anyio.fail_after(30):
            assert await caller.client.wait_for_service(timeout=30)
            call = rt.loop.create_task(caller.client.call(AddTwoInts.Request(a=1, b=2), timeout=60))
            await server.wait_for("Incoming request")
        server.proc.kill()
        with anyio.fail_after(10), pytest.raises(ServiceError, match="add_two_ints"):
            await call
        await until(lambda: not caller.client.service_is_ready(), 5)  # its stand-in leaves with its token
