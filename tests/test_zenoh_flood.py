"""A Zenoh peer flooding a graph with malformed samples, queries and tokens costs it a few log lines.

The peer is a plain Zenoh session in a process of its own (as
``tests/test_zenoh_interop.py``'s raw sessions, but apart, so that the RSS
measured is the graph's alone): 20,000 malformed samples each with a fresh
publisher GID, 2,000 malformed queries, then 5,000 liveliness tokens that are
not rmw_zenoh's.

Zenoh itself keeps about 3 KB per liveliness token it hears of, in any
session subscribed to them: that is upstream, not ours to bound.  So beside
the graph runs a bare Zenoh peer with the same liveliness subscriber, and
what the graph grows beyond it is what the graph keeps.
"""

from __future__ import annotations

import gc
import logging
import sys
from pathlib import Path

import anyio
import pytest
from zenoh_procs import free_port, peer, section, until, zenoh_env

from actors import Node, Runtime
from actors.ops.doctor import diagnose
from actors.transport.zenoh import ZenohTransport
from actors.transport.zenoh.discovery import MAX_FOREIGN_TOKENS
from actors.transport.zenoh.keys import data_key
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

pytestmark = pytest.mark.slow

STRING_HASH = "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
ADD_HASH = "RIHS01_e118de6bf5eeb66a2491b5bda11202e7b68f198d6f67922cf30364858239c81a"
SAMPLES, QUERIES, TOKENS = 20_000, 2_000, 5_000
MB = 2**20

# Phase one: the samples and the queries; phase two (a line on stdin): the tokens, held until stdin ends.
FLOOD = """
import json, sys
import zenoh
from actors.transport.zenoh.attachment import pack

port, topic, service, samples, queries, tokens = sys.argv[1], sys.argv[2], sys.argv[3], *map(int, sys.argv[4:7])
config = zenoh.Config()
config.insert_json5("connect/endpoints", json.dumps([f"tcp/127.0.0.1:{port}"]))
config.insert_json5("scouting/multicast/enabled", "false")
session = zenoh.open(config)
pub = session.declare_publisher(topic, congestion_control=zenoh.CongestionControl.BLOCK)  # every one arrives
matching = pub.declare_matching_listener()  # before the look: a change after it is heard
if not pub.matching_status.matching:
    while not matching.recv().matching:
        pass
for i in range(samples):
    pub.put(b"\\x00\\x01\\x00\\x00\\xff\\xff\\xff\\x7fno", attachment=pack(i, 0, i.to_bytes(16, "little")))
end = b"\\x00\\x01\\x00\\x00\\x04\\x00\\x00\\x00end\\x00"  # the last one is well-formed
pub.put(end, attachment=pack(samples, 0, bytes(16)))
replies = [session.get(service, payload=b"\\x01\\x02", attachment=b"\\x03") for _ in range(queries)]
for handler in replies:
    for _ in handler:
        pass
print("sent", flush=True)
sys.stdin.readline()
zid = str(session.info.zid())
declared = [session.liveliness().declare_token(f"@ros2_lv/0/{zid}/0/{i}/XX/%/%/n{i}") for i in range(tokens)]
print("declared", flush=True)
sys.stdin.read()
"""

# A bare Zenoh peer that hears every liveliness token of the domain, as the transport does, and nothing else.
BARE = """
import gc, json, sys, threading
import zenoh

def rss():
    gc.collect()
    status = open("/proc/self/status").read()
    return int(next(line for line in status.splitlines() if line.startswith("VmRSS:")).split()[1]) * 1024

port, tokens = sys.argv[1], int(sys.argv[2])
config = zenoh.Config()
config.insert_json5("connect/endpoints", json.dumps([f"tcp/127.0.0.1:{port}"]))
config.insert_json5("scouting/multicast/enabled", "false")
session = zenoh.open(config)
heard, all_heard = set(), threading.Event()
def hear(sample):
    if "/XX/" in str(sample.key_expr):
        heard.add(str(sample.key_expr))
        if len(heard) >= tokens:
            all_heard.set()
watch = session.liveliness().declare_subscriber("@ros2_lv/0/**", zenoh.handlers.Callback(hear), history=True)
print("ready", rss(), flush=True)
all_heard.wait()
heard.clear()  # what a callback keeps is not zenoh's
print("heard", rss(), flush=True)
sys.stdin.read()
"""


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.heard: list[str] = []
        self.create_subscription(String, "chatter", lambda msg: self.heard.append(msg.data), 10)


class Adder(Node):
    def __init__(self) -> None:
        super().__init__("adder")
        self.create_service(AddTwoInts, "add_two_ints", lambda request, response: response)


def rss() -> int:
    gc.collect()
    status = Path("/proc/self/status").read_text()
    return int(next(line for line in status.splitlines() if line.startswith("VmRSS:")).split()[1]) * 1024


async def line(stream) -> list[str]:
    """One line of a child's output, split into words."""
    data = b""
    while not data.endswith(b"\n"):
        data += await stream.receive(1)
    return data.decode().split()


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads RSS from /proc")
async def test_a_flood_of_malformed_samples_queries_and_tokens_costs_a_few_lines(caplog):
    port = free_port()
    caplog.set_level(logging.WARNING)
    transport = ZenohTransport(section(port))
    topic = data_key(0, "/chatter", "std_msgs/msg/String", STRING_HASH)
    service = data_key(0, "/add_two_ints", "example_interfaces/srv/AddTwoInts", ADD_HASH)
    flood_argv = [sys.executable, "-c", FLOOD, str(port), topic, service, str(SAMPLES), str(QUERIES), str(TOKENS)]
    bare_argv = [sys.executable, "-c", BARE, str(port), str(TOKENS)]
    async with Runtime(attach=[transport]) as rt:
        listener = rt.spawn(Listener)
        rt.spawn(Adder)
        warnings = transport.warnings
        assert warnings is not None
        async with (
            await anyio.open_process(bare_argv, env=zenoh_env(port)) as bare,
            await anyio.open_process(flood_argv, env=zenoh_env(port)) as flood,
        ):
            assert bare.stdout and bare.stdin and flood.stdout and flood.stdin
            try:
                with anyio.fail_after(60):
                    bare_before = int((await line(bare.stdout))[1])
                    before = rss()
                    assert await line(flood.stdout) == ["sent"]
                    await until(lambda: listener.heard == ["end"], 60)  # every query was answered before
                    middle, seen = rss(), warnings.seen
                    await flood.stdin.send(b"tokens\n")
                    assert await line(flood.stdout) == ["declared"]
                    bare_after = int((await line(bare.stdout))[1])
                    await until(lambda: warnings.seen >= seen + TOKENS, 60)
                    after = rss()
                report = diagnose(rt)
            finally:
                for child in (flood, bare):
                    child.kill()
    lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(lines) <= 40, lines[:50]
    assert seen >= QUERIES + 1  # samples the listener's depth would not keep are not even decoded
    # One line per key: the topic, the service, the tokens; and one for samples the listener's
    # backlog pushed out, if the loop fell behind the flood.
    pushed_out = sum("came faster than the graph could take them" in text for text in lines)
    assert pushed_out <= 1
    left_out = warnings.seen - 3 - pushed_out
    assert lines[-1].startswith(f"left out {left_out} more warning(s) like these")
    flood, ours, upstream = (middle - before) / MB, (after - middle) / MB, (bare_after - bare_before) / MB
    measured = f"samples and queries {flood:+.1f} MB; tokens {ours:+.1f} MB, to a bare zenoh peer's {upstream:+.1f} MB"
    assert flood < 10, measured
    assert ours - upstream < 10, measured
    check = next(c for c in report.checks if c.name == "transport limits")
    assert check.passed  # malformed tokens take no room
    assert check.warnings == (
        f"{left_out} of {warnings.seen} warning(s) about what other processes "
        "sent left out of the log (rate-limited; the log has a summary)",
    )


async def test_foreign_tokens_beyond_the_limit_are_ignored_and_doctor_says_so(monkeypatch, caplog):
    import actors.transport.zenoh.discovery as discovery

    monkeypatch.setattr(discovery, "MAX_FOREIGN_TOKENS", 50)
    port = free_port()
    transport = ZenohTransport(section(port))
    async with Runtime(attach=[transport]) as rt, peer(port) as session:
        zid = str(session.info.zid())
        tokens = [session.liveliness().declare_token(f"@ros2_lv/0/{zid}/0/{i}/NN/%/%/node{i}") for i in range(80)]
        await until(lambda: len(rt.graph.remote_nodes()) + transport.ignored_tokens >= 80)
        assert len(rt.graph.remote_nodes()) == 50
        check = next(c for c in diagnose(rt).checks if c.name == "transport limits")
        assert not check.passed
        assert check.reasons[0].startswith("30 liveliness token(s) of other processes ignored: more than 50 at once")
        for token in tokens[:40]:
            token.undeclare()
        await until(lambda: len(rt.graph.remote_nodes()) == 10)
        more = session.liveliness().declare_token(f"@ros2_lv/0/{zid}/0/99/NN/%/%/late")  # room again: kept
        await until(lambda: any(n.name == "/late" for n in rt.graph.remote_nodes()))
        for token in [*tokens[40:], more]:
            token.undeclare()
    ignored = [r.getMessage() for r in caplog.records if "at most 50 tokens of other processes" in r.getMessage()]
    assert len(ignored) == 1  # one line for 30 tokens ignored
    assert MAX_FOREIGN_TOKENS == 10_000
