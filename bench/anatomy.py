"""What one delivery and one service call cost, piece by piece: nanoseconds of CPU on the real objects.

Run: ``python -m bench.anatomy``.  Where scenarios a, b and c give a whole
rate against its baseline, this takes the path apart: each piece is timed on
its own (the runtime's own publisher, subscriptions, client and server, with
no event loop turning between pieces), in CPU time, the minimum of many
repeats, so that other processes on a shared machine count for little.  The
pieces of a path add up to about its total; what the total has beyond the
direct call is what delivery costs.  Not part of ``python -m bench``: it
explains the table, it does not extend it.
"""

from __future__ import annotations

import argparse
import asyncio
import time
import timeit
from collections import deque
from collections.abc import Callable
from typing import Any

from actors import Node, QoSProfile, Runtime
from actors.messages._copy import snapshotter
from bench.services import handle
from bench.throughput import Listener, Talker, call_rate
from interfaces.std_msgs.msg import String
from interfaces.std_srvs.srv import SetBool

__all__ = ["measure", "main"]

BATCH = 100  # operations per timed call: a batch, as the throughput scenarios publish


def _ns(fn: Callable[[], Any], per: int, repeats: int) -> float:
    """CPU nanoseconds per operation of ``fn`` (which does ``per`` of them): the best of ``repeats``."""
    best = min(timeit.repeat(fn, number=100, repeat=repeats, timer=time.process_time))
    return best / 100 / per * 1e9


class _Server(Node):
    def __init__(self) -> None:
        super().__init__("server")
        self.service = self.create_service(SetBool, "set_bool", handle)


class _Caller(Node):
    def __init__(self) -> None:
        super().__init__("caller")
        self.client = self.create_client(SetBool, "set_bool")


async def _path(rt: Runtime, subscribers: int, repeats: int) -> dict[str, float]:
    """One publisher feeding ``subscribers`` nodes: what a publish costs without and with the rounds (ns)."""
    listeners = [rt.spawn(Listener, name=f"listener{subscribers}_{i}") for i in range(subscribers)]
    subs = [n.create_subscription(String, f"anatomy{subscribers}", n.on_msg, QoSProfile(depth=1000)) for n in listeners]
    pub = rt.spawn(Talker, name=f"talker{subscribers}").create_publisher(
        String, f"anatomy{subscribers}", QoSProfile(depth=1000)
    )
    await asyncio.sleep(0)
    msg = String(data="Hello World")
    publish, flush, scheduler_ready = pub.publish, rt.scheduler._flush, rt.scheduler._ready

    def pushed() -> None:  # publish a batch, then empty the queues as if read, without a callback
        for _ in range(BATCH):
            publish(msg)
        pub._settle()  # a fan-out publisher's batch closed (the first round would do it)
        for sub in subs:
            sub._batch = None  # the batch each fan-out subscription holds, as read
            sub._limit = sub._depth
            sub._queue.clear()
            sub._scheduled = False
            sub._actor._ready.clear()
            sub._actor._queued = False
        scheduler_ready.clear()

    def delivered() -> None:
        for _ in range(BATCH):
            publish(msg)
        flush()

    on_msg = listeners[0].on_msg
    callbacks = [node.on_msg for node in listeners]
    return {
        "floor": min(1e9 / call_rate(callbacks, BATCH * 100, time.process_time) for _ in range(repeats)),
        "callback": _ns(lambda: [on_msg(msg) for _ in range(BATCH)], BATCH, repeats),
        "pushed": _ns(pushed, BATCH, repeats),
        "delivered": _ns(delivered, BATCH, repeats),
    }


async def _topics(rt: Runtime, repeats: int) -> dict[str, dict[str, float]]:
    # One subscriber: publish() appends to its queue.  Ten: publish() appends once to the
    # publisher's batch, a list the ten subscriptions read in turn.
    one, ten = await _path(rt, 1, repeats), await _path(rt, 10, repeats)
    snapshot, msg = snapshotter(String), String(data="Hello World")
    snap = _ns(lambda: [snapshot(msg) for _ in range(BATCH)], BATCH, repeats)
    sections = {}
    for name, path, n, into in (
        ("a. one-way (ns per delivery)", one, 1, "the append to the queue"),
        ("b. fan-out 1→10 (ns per delivery)", ten, 10, "one list that ten rounds read"),
    ):
        total = path["delivered"] / n
        sections[name] = {
            "the direct-call floor (bench.throughput.call_rate, the target's)": path["floor"],
            "a callback alone (a node's bound method)": path["callback"],
            f"publish() (share): call, type check, snapshot, {into}": path["pushed"] / n,
            "  of which the snapshot (share)": snap / n,
            "the rounds: each message's call and result check (callback included)": (path["delivered"] - path["pushed"])
            / n,
            "total per delivery": total,
            "floor ÷ total (× the floor's rate, as the target reads)": path["floor"] / total,
        }
    return sections


async def _service(rt: Runtime, repeats: int) -> dict[str, float]:
    server = rt.spawn(_Server).service
    client = rt.spawn(_Caller).client
    await asyncio.sleep(0)
    request = SetBool.Request(data=True)
    call_async, flush = client.call_async, rt.scheduler._flush
    timeouts, new_future = rt.services.timeouts(rt.loop), rt.loop.create_future
    waiting = deque(new_future() for _ in range(BATCH))  # 100 callers waiting, as in c's row
    for future in waiting:
        timeouts.add(future, client, 5.0)
    snap_request, snap_response = snapshotter(SetBool.Request), snapshotter(SetBool.Response)
    response = SetBool.Response()

    def sent() -> None:
        for _ in range(BATCH):
            call_async(request)
        server._queue.clear()
        server._scheduled = False
        server._actor._ready.clear()
        server._actor._queued = False
        rt.scheduler._ready.clear()

    def served() -> None:
        for _ in range(BATCH):
            call_async(request)
        flush()

    def answered(keep: bool) -> None:  # the oldest call is answered, a new one waits
        for _ in range(BATCH):
            waiting.popleft().set_result(None)
            future = new_future()
            waiting.append(future)
            if keep:  # what Client.call does for timeout=
                timeouts.add(future, client, 5.0)

    sending = _ns(sent, BATCH, repeats)
    return {
        "call_async(): type check, snapshot, future, queue": sending,
        "  of which the request's snapshot": _ns(lambda: [snap_request(request) for _ in range(BATCH)], BATCH, repeats),
        "serving a queued call: handler, response check and snapshot, set_result": _ns(served, BATCH, repeats)
        - sending,
        "  of which the response's snapshot": _ns(
            lambda: [snap_response(response) for _ in range(BATCH)], BATCH, repeats
        ),
        "a timeout's deadline, kept and dropped (timeout=)": (
            _ns(lambda: answered(True), BATCH, repeats) - _ns(lambda: answered(False), BATCH, repeats)
        ),
    }


def measure(repeats: int = 25) -> dict[str, dict[str, float]]:
    """Each path's pieces in CPU nanoseconds (the best of ``repeats``), by path."""

    async def main() -> dict[str, dict[str, float]]:
        async with Runtime() as rt:
            return {
                **await _topics(rt, repeats),
                "c. service call, without the loop's turns (ns per call)": await _service(rt, repeats),
            }

    return asyncio.run(main())


def main() -> None:
    """Print each path's pieces."""
    parser = argparse.ArgumentParser(prog="python -m bench.anatomy", description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=25, help="timings per piece, the best kept (default 25)")
    args = parser.parse_args()
    for path, pieces in measure(args.repeats).items():
        print(path)
        for piece, value in pieces.items():
            print(f"  {piece:<78} {value:8.2f}" if "×" in piece else f"  {piece:<78} {value:8.0f}")


if __name__ == "__main__":
    main()
