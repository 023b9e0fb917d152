"""The Zenoh path's hops: puts inside publish(), rounds run in the drain, queries answered as they settle, ..."""

from __future__ import annotations

import asyncio
import threading
from types import SimpleNamespace
from typing import Any

import pytest
from zenoh_procs import free_port, raw_config

from actors import Node, Runtime, codec
from actors.transport import Hub, Inlet, Outlet
from actors.transport.zenoh.attachment import unpack
from actors.transport.zenoh.handoff import Handoff, keep_thread_state
from actors.transport.zenoh.link import Endpoint, Link
from actors.transport.zenoh.services import ServiceBridge, _Answer
from actors.transport.zenoh.topics import TopicBridge, _Out
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import Int64

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

GID = bytes(range(16))


class Query:
    """What a queryable hands over, as far as an answer goes: what was answered, and when it ended."""

    def __init__(self) -> None:
        self.answers: list[tuple[str, Any, Any]] = []
        self.dropped = False

    def reply(self, key: str, payload: bytes, *, attachment: bytes) -> None:
        self.answers.append(("reply", key, (payload, attachment)))

    def reply_err(self, payload: bytes) -> None:
        self.answers.append(("error", "", payload.decode()))

    def drop(self) -> None:
        self.dropped = True


class Logger:
    def __init__(self) -> None:
        self.errors: list[str] = []

    def error(self, text: str) -> None:
        self.errors.append(text)


def answer(loop: asyncio.AbstractEventLoop) -> tuple[_Answer, Query, Logger]:
    query, logger = Query(), Logger()
    link = SimpleNamespace(loop=loop, logger=logger, now_ns=lambda: 42)
    return _Answer(link, "0/add_two_ints", query, 7, GID), query, logger  # type: ignore[arg-type]


async def test_a_settled_answer_replies_there_and_then_with_the_callers_sequence_and_gid():
    future, query, _ = answer(asyncio.get_running_loop())
    future.set_result(AddTwoInts.Response(sum=5))
    # No loop round has passed: the reply is out as the handler's result is set.
    [(kind, key, (payload, attachment))] = query.answers
    assert (kind, key, query.dropped) == ("reply", "0/add_two_ints", True)
    assert codec.decode_cdr(payload, AddTwoInts.Response).sum == 5
    assert unpack(attachment) == (7, 42, GID)
    assert future.result().sum == 5


async def test_a_failed_or_cancelled_answer_is_an_error_reply():
    loop = asyncio.get_running_loop()
    future, query, _ = answer(loop)
    future.set_exception(ValueError("no sum today"))
    assert query.answers == [("error", "", "no sum today")] and query.dropped
    future, query, _ = answer(loop)
    assert future.cancel()
    assert query.answers == [("error", "", "the call was cancelled")]
    assert not future.cancel() and len(query.answers) == 1  # cancelled once, answered once


async def test_a_response_cdr_cannot_carry_is_an_error_reply_and_logged():
    future, query, logger = answer(asyncio.get_running_loop())
    future.set_result(AddTwoInts.Response(sum=2**70))  # beyond int64
    [(kind, _, text)] = query.answers
    assert kind == "error" and "cannot encode the response" in text
    assert len(logger.errors) == 1 and "0/add_two_ints" in logger.errors[0]


class Publisher:
    """A zenoh publisher, as far as a put goes: what was put, in order."""

    def __init__(self) -> None:
        self.puts: list[tuple[bytes, bytes]] = []

    def put(self, payload: bytes, *, attachment: bytes) -> None:
        self.puts.append((payload, attachment))


class Heard(Node):
    def __init__(self) -> None:
        super().__init__("heard", start_parameter_services=False)
        self.heard: list[int] = []
        self.create_subscription(Int64, "ping", lambda msg: self.heard.append(msg.data), 10)


async def test_a_publish_puts_on_the_wire_before_it_returns_in_order_with_sequence_numbers():
    async with Runtime() as rt:
        node = rt.spawn(Node, "talker", start_parameter_services=False)
        pub = node.create_publisher(Int64, "pong", 10)
        link = SimpleNamespace(now_ns=lambda: 42)
        bridge = TopicBridge(link, rt.topics)  # type: ignore[arg-type]
        zpub = Publisher()
        outlet = Outlet(Hub("/_zenoh", rt.loop, rt.logger), pub, bridge._send)
        bridge._outs[pub] = _Out(Endpoint("/talker", 1, None, GID, "0/pong"), zpub, outlet)
        outlet.attach()
        for i in range(3):
            pub.publish(Int64(data=i))
            assert len(zpub.puts) == i + 1  # no loop round between publish() and the wire
        sent = [(codec.decode_cdr(payload, Int64).data, unpack(attachment)) for payload, attachment in zpub.puts]
        assert sent == [(0, (1, 42, GID)), (1, (2, 42, GID)), (2, (3, 42, GID))]


async def test_a_drain_runs_the_rounds_its_items_woke_before_the_loops_next_callback():
    loop = asyncio.get_running_loop()
    async with Runtime() as rt:
        node = rt.spawn(Heard)
        inlet = Inlet(Hub("/_zenoh", rt.loop, rt.logger), "/ping", Int64)
        rt.topics.add_publisher(inlet)
        handoff = Handoff(loop, rt.scheduler, lambda exc: None)
        for i in range(2):
            handoff.put(inlet.publish, Int64(data=i))  # as zenoh's thread hands samples over
        seen = loop.create_future()
        # Queued right behind the drain: what it sees, the drain did itself, rounds included.
        loop.call_soon(lambda: seen.set_result(list(node.heard)))
        assert await seen == [0, 1]


class Session:
    """Records the handler a get is given, as zenoh would call it."""

    def __init__(self) -> None:
        self.handlers: list[Any] = []

    def get(self, key: str, handler: Any, **options: Any) -> None:
        self.handlers.append(handler)


class Standin:
    service_name, provider, srv_type = "/add_two_ints", "/server", AddTwoInts


async def test_the_end_of_a_call_that_was_answered_is_not_handed_to_the_loop():
    loop = asyncio.get_running_loop()
    handed: list[tuple[Any, Any]] = []
    session = Session()
    fake_zenoh = SimpleNamespace(
        handlers=SimpleNamespace(Callback=lambda callback, drop, indirect: (callback, drop)),
        QueryTarget=SimpleNamespace(ALL_COMPLETE=None),
        ConsolidationMode=SimpleNamespace(NONE=None),
        Locality=SimpleNamespace(REMOTE=None),
    )
    link = SimpleNamespace(
        zid="z",
        zenoh=fake_zenoh,
        session=session,
        handoff=SimpleNamespace(put=lambda function, argument: handed.append((function, argument))),
        now_ns=lambda: 1,
    )
    bridge = ServiceBridge(link, table=None, discovery=None)  # type: ignore[arg-type]
    standin = Standin()
    bridge._keys[standin] = "0/add_two_ints"  # type: ignore[index]
    for answered in (True, False):
        handed.clear()
        future = loop.create_future()
        bridge._forward(standin, AddTwoInts.Request(a=1, b=2), future)  # type: ignore[arg-type]
        replied, ended = session.handlers[-1]
        if answered:
            replied("a reply")
        ended()
        assert [function.__name__ for function, _ in handed] == (["_settle"] if answered else ["_ended"])


def test_a_zenoh_thread_keeps_its_python_thread_state_from_one_callback_to_the_next():
    # Two sessions of this process on loopback: samples arrive on zenoh's own receive thread.
    port = free_port()
    listening = raw_config(port)
    listening.insert_json5("listen/endpoints", f'["tcp/127.0.0.1:{port}"]')
    receiver, sender = zenoh.open(listening), zenoh.open(raw_config(port))
    kept = threading.local()  # per thread state: it starts empty in a fresh one
    counts: list[int] = []
    threads: set[int] = set()
    arrived = threading.Event()

    def callback(sample: Any) -> None:
        keep_thread_state()
        threads.add(threading.get_ident())
        kept.count = getattr(kept, "count", 0) + 1
        counts.append(kept.count)
        if len(counts) == 20:
            arrived.set()

    try:
        sub = receiver.declare_subscriber("hops", zenoh.handlers.Callback(callback, indirect=False))
        pub = sender.declare_publisher("hops")
        found = threading.Event()  # the two sessions found each other
        pub.declare_matching_listener(lambda status: status.matching and found.set())  # before the look
        assert pub.matching_status.matching or found.wait(10)
        for _ in range(20):
            pub.put(b"x")
        assert arrived.wait(10)
        assert threading.get_ident() not in threads  # the samples came on zenoh's threads
        # Each receive thread counts on from its first callback: its thread state was kept.
        assert max(counts) > 1 and counts.count(1) <= 4
        sub.undeclare()
    finally:
        sender.close()
        receiver.close()


def test_a_server_answers_before_its_token_tells_peers_it_is_there():
    # A client may call as soon as it sees the server's token (wait_for_service returns then): the
    # queryable must already be declared, as rmw_zenoh declares it first.
    order: list[str] = []

    class Liveliness:
        def declare_token(self, key: str) -> str:
            order.append("token" if "/SS/" in key else "node token")
            return key

    session = SimpleNamespace(
        info=SimpleNamespace(zid=lambda: "0123456789abcdef"),
        liveliness=Liveliness,
        declare_queryable=lambda key, handler, **options: order.append("queryable"),
    )
    fake_zenoh = SimpleNamespace(
        handlers=SimpleNamespace(Callback=lambda callback, indirect: callback),
        Locality=SimpleNamespace(REMOTE=None),
    )
    hub = SimpleNamespace(loop=asyncio.new_event_loop())
    logger = SimpleNamespace(warning=lambda *args: None)
    link = Link(fake_zenoh, session, 0, hub, SimpleNamespace(put=None), lambda: 1, logger)  # type: ignore[arg-type]
    bridge = ServiceBridge(link, table=None, discovery=None)  # type: ignore[arg-type]
    server = SimpleNamespace(service_name="/add_two_ints", node=SimpleNamespace(fqn="/adder"), srv_type=AddTwoInts)
    try:
        bridge.add_service(server)  # type: ignore[arg-type]
    finally:
        hub.loop.close()
    assert order == ["node token", "queryable", "token"]
