"""The Zenoh path's hops: queries answered as they settle, an answered call's end unheard, thread states kept."""

from __future__ import annotations

import asyncio
import threading
from types import SimpleNamespace
from typing import Any

import pytest
from zenoh_procs import free_port, raw_config

from actors import codec
from actors.transport.zenoh.attachment import unpack
from actors.transport.zenoh.handoff import keep_thread_state
from actors.transport.zenoh.services import ServiceBridge, _Answer
from interfaces.example_interfaces.srv import AddTwoInts

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
