"""The actor: callbacks one at a time per node, run by the scheduler without a task per node, fair rounds."""

from __future__ import annotations

import asyncio

import anyio
import anyio.lowlevel
import pytest

from actors import Node, Runtime
from interfaces.std_msgs.msg import Int64

pytestmark = pytest.mark.virtual_time


class Idle(Node):
    def __init__(self) -> None:
        super().__init__("idle")
        self.ticks = 0
        self.create_timer(1.0, self.tick)

    def tick(self) -> None:
        self.ticks += 1


async def test_nodes_with_plain_callbacks_own_no_task():
    async with Runtime() as rt:
        before = len(asyncio.all_tasks())
        nodes = [rt.spawn(Idle, name=f"idle{i}") for i in range(200)]
        await anyio.sleep(3.5)
        assert [n.ticks for n in nodes] == [3] * 200
        assert len(asyncio.all_tasks()) == before


async def test_an_async_callback_holds_back_its_node_but_not_the_others():
    events: list[str] = []

    class Slow(Node):
        def __init__(self) -> None:
            super().__init__("slow")
            self.create_subscription(Int64, "numbers", self.on_number, 10)

        async def on_number(self, msg: Int64) -> None:
            events.append(f"slow starts {msg.data}")
            await anyio.sleep(1)
            events.append(f"slow ends {msg.data}")

    class Fast(Node):
        def __init__(self) -> None:
            super().__init__("fast")
            self.create_subscription(Int64, "numbers", lambda msg: events.append(f"fast {msg.data}"), 10)

    async with Runtime() as rt:
        rt.spawn(Slow)
        rt.spawn(Fast)
        pub = rt.spawn(Idle).create_publisher(Int64, "numbers", 10)
        pub.publish(Int64(data=1))
        await anyio.sleep(0.5)
        pub.publish(Int64(data=2))
        assert rt.node("slow")._core.actor.awaiting
        await anyio.sleep(3)
    # The slow node's second message waits for its first callback; the fast node never waits.
    assert [e for e in events if e.startswith("slow")] == [
        "slow starts 1",
        "slow ends 1",
        "slow starts 2",
        "slow ends 2",
    ]
    assert events.index("fast 2") < events.index("slow ends 1")


async def test_a_node_that_keeps_itself_busy_does_not_starve_the_others():
    heard: list[str] = []

    class Echo(Node):
        """Republishes every number to itself at once, 100 times: it always has work."""

        def __init__(self) -> None:
            super().__init__("echo")
            self.pub = self.create_publisher(Int64, "loop", 10)
            self.create_subscription(Int64, "loop", self.again, 10)

        def again(self, msg: Int64) -> None:
            heard.append(f"echo {msg.data}")
            if msg.data < 100:
                self.pub.publish(Int64(data=msg.data + 1))

    class Other(Node):
        def __init__(self) -> None:
            super().__init__("other")
            self.create_subscription(Int64, "other", lambda msg: heard.append("other"), 10)

    async with Runtime() as rt:
        echo = rt.spawn(Echo)
        rt.spawn(Other)
        other = rt.spawn(Idle).create_publisher(Int64, "other", 10)
        echo.pub.publish(Int64(data=0))
        await anyio.lowlevel.checkpoint()
        other.publish(Int64(data=0))
        await anyio.sleep(1)
    # One message per round for the echo node: the other node's message waits a round or two, not 100.
    assert heard.index("other") < 5 and heard[-1] == "echo 100"


async def test_a_crash_in_a_plain_callback_ends_only_that_node():
    class Fragile(Node):
        def __init__(self) -> None:
            super().__init__("fragile")
            self.create_subscription(Int64, "numbers", self.on_number, 10)

        def on_number(self, msg: Int64) -> None:
            raise RuntimeError("no")

    async with Runtime() as rt:
        rt.spawn(Fragile, restart="temporary")
        idle = rt.spawn(Idle)
        rt.spawn(Idle, name="publisher").create_publisher(Int64, "numbers", 10).publish(Int64(data=1))
        await anyio.sleep(2.5)
        assert [n.name for n in rt.graph.nodes()] == ["/idle", "/publisher"]
        assert idle.ticks == 2


class Noting:
    """An entity that notes its name when it runs."""

    def __init__(self, name: str, notes: list[str]) -> None:
        self.name = name
        self.notes = notes

    def _run(self) -> None:
        self.notes.append(self.name)


class Awaiting:
    """An entity with an async callback: notes when it starts, and when it ends once ``release`` is done."""

    def __init__(self, notes: list[str], release: asyncio.Future[None]) -> None:
        self.notes = notes
        self.release = release

    def _run(self):
        self.notes.append("async starts")
        return self._rest()

    async def _rest(self) -> None:
        await self.release
        self.notes.append("async ends")


async def test_run_one_runs_an_idle_actors_round_at_once_and_otherwise_waits_its_turn():
    from actors.core._actor import Actor, Scheduler

    loop = asyncio.get_running_loop()
    scheduler = Scheduler(loop)
    first, second = Actor(loop, scheduler), Actor(loop, scheduler)
    in_context = scheduler.context.run  # as a loop callback calls run_one: in the rounds' context
    notes: list[str] = []
    # Nothing else waits: the round runs now, in the caller's loop callback, and the actor is idle after it.
    # Busy since the time the caller gives (the loop's now: the caller read it, and nothing ran since).
    in_context(first.run_one, Noting("alone", notes), scheduler, 1.5)
    assert notes == ["alone"] and not first._queued and first.busy_since == 1.5
    # Another actor's round is already due (a wake-up from a publish): it runs first, then this one.
    first.schedule(Noting("woken earlier", notes))
    in_context(second.run_one, Noting("timer", notes), scheduler, loop.time())
    assert notes == ["alone", "woken earlier", "timer"]
    # An actor with work queued (its round is due): the entity waits behind that work.
    first.schedule(Noting("queued", notes))
    in_context(first.run_one, Noting("behind it", notes), scheduler, loop.time())
    assert notes[3:] == ["queued", "behind it"]
    await asyncio.sleep(0)  # the loop callback those wake-ups asked for finds nothing left to run
    assert notes[5:] == []
    # An actor inside an async callback: the entity runs after it, never beside it.
    release = loop.create_future()
    first.schedule(Awaiting(notes, release))
    await asyncio.sleep(0)
    assert first.awaiting and notes[5:] == ["async starts"]
    in_context(first.run_one, Noting("during", notes), scheduler, loop.time())
    assert notes[5:] == ["async starts"]
    release.set_result(None)
    for _ in range(3):
        await asyncio.sleep(0)
    assert notes[5:] == ["async starts", "async ends", "during"]


async def test_run_one_on_an_idle_actor_hands_an_async_callback_to_a_task_and_a_failure_ends_the_actor():
    from actors.core._actor import Actor, CallbackFailed, Scheduler

    loop = asyncio.get_running_loop()
    scheduler = Scheduler(loop)
    actor = Actor(loop, scheduler)
    in_context = scheduler.context.run  # as a loop callback calls run_one: in the rounds' context
    notes: list[str] = []
    release = loop.create_future()
    in_context(actor.run_one, Awaiting(notes, release), scheduler, loop.time())
    assert actor.awaiting and actor._queued and notes == ["async starts"]
    in_context(
        actor.run_one, Noting("while it awaits", notes), scheduler, loop.time()
    )  # waits behind the async callback
    release.set_result(None)
    for _ in range(3):
        await asyncio.sleep(0)
    assert notes == ["async starts", "async ends", "while it awaits"] and not actor._queued

    exits: list[BaseException | None] = []
    actor.on_exit = exits.append

    class Failing:
        def _run(self):
            raise CallbackFailed(self, None, RuntimeError("no"))

    in_context(actor.run_one, Failing(), scheduler, loop.time())
    assert [type(e.error) for e in exits] == [RuntimeError] and actor.current is None  # type: ignore[union-attr]
    in_context(actor.run_one, Noting("after the end", notes), scheduler, loop.time())
    assert notes[-1] == "while it awaits"  # a stopped actor runs nothing more
