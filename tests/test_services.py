"""Services: calls, errors that reach the caller, timeouts, self-calls, restarts, concurrency."""

from __future__ import annotations

import asyncio
import logging
import re
from typing import ClassVar

import anyio
import anyio.lowlevel
import pytest
from conftest import live_loop_timers

from actors import Node, Runtime, ServiceError, SupervisorPolicy
from actors.errors import MessageValidationError
from actors.services import Service
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import Int64
from interfaces.std_srvs.srv import SetBool, Trigger

pytestmark = pytest.mark.virtual_time


class Adder(Node):
    """Serves add_two_ints; raises for negative numbers; crashes on a message to /adder_crash."""

    instances = 0
    latency = 0.0

    def __init__(self) -> None:
        super().__init__("adder")
        Adder.instances += 1
        self.create_service(AddTwoInts, "add_two_ints", self.add)
        self.create_subscription(Int64, "/adder_crash", self.crash, 10)

    async def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        if request.a < 0:
            raise ValueError(f"negative: {request.a}")
        if self.latency:
            await anyio.sleep(self.latency)
        response.sum = request.a + request.b
        return response

    def crash(self, msg: Int64) -> None:
        raise RuntimeError("crash on purpose")


class Caller(Node):
    def __init__(self) -> None:
        super().__init__("caller")
        self.cli = self.create_client(AddTwoInts, "add_two_ints")
        self.crash_pub = self.create_publisher(Int64, "/adder_crash", 10)


async def test_a_call_returns_the_sum():
    async with Runtime() as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        assert caller.cli.service_is_ready()
        response = await caller.cli.call(AddTwoInts.Request(a=41, b=1), timeout=1)
        assert response.sum == 42
        (info,) = [s for s in rt.graph.services() if s.name == "/add_two_ints"]
        assert (info.node, info.type, info.handled) == ("/adder", "example_interfaces/srv/AddTwoInts", 1)


async def test_an_error_in_the_handler_reaches_the_caller_and_the_server_keeps_serving(caplog):
    caplog.set_level(logging.ERROR, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        with pytest.raises(ServiceError, match=r"/add_two_ints on /adder raised ValueError\('negative: -1'\)"):
            await caller.cli.call(AddTwoInts.Request(a=-1, b=1), timeout=1)
        assert (await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=1)).sum == 2
        assert Adder.instances >= 1 and rt.graph.nodes()[0].crashes == 0
    assert any("negative" in r.getMessage() and r.exc_info for r in caplog.records)


async def test_a_missing_service_times_out():
    async with Runtime() as rt:
        caller = rt.spawn(Caller)
        assert not caller.cli.service_is_ready()
        assert await caller.cli.wait_for_service(timeout=2.0) is False
        start = rt.clock.monotonic()
        with pytest.raises(TimeoutError):
            await caller.cli.call(AddTwoInts.Request(a=1, b=2), timeout=0.5)
        assert rt.clock.monotonic() - start == pytest.approx(0.5)


async def test_a_call_that_times_out_discards_the_late_response_and_leaves_the_server_serving(caplog):
    class SlowAdder(Adder):
        latency = 1.0

    caplog.set_level(logging.ERROR, logger="actors")
    async with Runtime() as rt:
        rt.spawn(SlowAdder)
        caller = rt.spawn(Caller)
        start = rt.clock.monotonic()
        with pytest.raises(TimeoutError, match=r"no response from service /add_two_ints within 0.5 s"):
            await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=0.5)
        assert rt.clock.monotonic() - start == 0.5
        # The server finishes the abandoned request at 1.0 and drops its response; the next
        # call gets its own answer, not the late one.
        response = await caller.cli.call(AddTwoInts.Request(a=20, b=22), timeout=5)
        assert response.sum == 42
        assert rt.clock.monotonic() - start == 2.0
        (info,) = [s for s in rt.graph.services() if s.name == "/add_two_ints"]
        assert (info.handled, info.queued) == (2, 0)
        assert rt.graph.nodes()[0].crashes == 0
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR]


async def test_a_call_answered_in_time_cancels_its_timeout_timer():
    async with Runtime() as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        await anyio.lowlevel.checkpoint()
        assert (await caller.cli.call(AddTwoInts.Request(a=1, b=2), timeout=3600)).sum == 3
        assert live_loop_timers() == []
        assert rt.clock.monotonic() == 0.0


async def test_a_request_that_timed_out_before_the_server_took_it_is_skipped():
    class CountingAdder(Adder):
        seen: ClassVar[list[int]] = []

        async def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            CountingAdder.seen.append(request.a)
            return await super().add(request, response)

    async with Runtime() as rt:
        caller = rt.spawn(Caller)
        with pytest.raises(TimeoutError):
            await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=0.5)  # parked: no server yet
        rt.spawn(CountingAdder)
        assert (await caller.cli.call(AddTwoInts.Request(a=2, b=2), timeout=1)).sum == 4
        assert CountingAdder.seen == [2]


async def test_wait_for_service_times_out_on_one_timer_and_forgets_its_waiter():
    async with Runtime() as rt:
        caller = rt.spawn(Caller)
        assert await caller.cli.wait_for_service(timeout=2.5) is False
        assert rt.clock.monotonic() == 2.5
        with anyio.move_on_after(1):
            await caller.cli.wait_for_service()  # no timeout: cancelled from outside
        assert rt.clock.monotonic() == 3.5
        assert rt.services._watchers == {} and live_loop_timers() == []
        rt.spawn(Adder)
        assert await caller.cli.wait_for_service(timeout=0) is True


async def test_a_call_made_before_the_server_exists_is_answered_when_it_appears():
    async with Runtime() as rt:
        caller = rt.spawn(Caller)
        future = caller.cli.call_async(AddTwoInts.Request(a=2, b=3))
        await anyio.sleep(1)
        assert not future.done()
        rt.spawn(Adder)
        assert (await future).sum == 5


async def test_wait_for_service_returns_when_the_server_appears():
    async with Runtime() as rt:
        caller = rt.spawn(Caller)

        async def spawn_later() -> None:
            await anyio.sleep(3)
            rt.spawn(Adder)

        async with anyio.create_task_group() as tg:
            tg.start_soon(spawn_later)
            assert await caller.cli.wait_for_service(timeout_sec=10) is True
        assert rt.clock.monotonic() == pytest.approx(3)


async def test_a_thousand_concurrent_calls_all_complete():
    class SlowAdder(Adder):
        latency = 0.001

    async with Runtime() as rt:
        rt.spawn(SlowAdder)
        caller = rt.spawn(Caller)
        futures = [caller.cli.call_async(AddTwoInts.Request(a=i, b=2 * i)) for i in range(1000)]
        responses = await asyncio.gather(*futures)
        assert [r.sum for r in responses] == [3 * i for i in range(1000)]


async def test_calling_its_own_service_from_a_callback_is_a_clear_error():
    class SelfCaller(Node):
        def __init__(self) -> None:
            super().__init__("self_caller")
            self.create_service(Trigger, "ping", lambda req, res: res)
            self.cli = self.create_client(Trigger, "ping")
            self.outcome: BaseException | None = None
            self.create_timer(0.5, self.tick)

        async def tick(self) -> None:
            try:
                await self.cli.call(Trigger.Request(), timeout=5)
            except ServiceError as exc:
                self.outcome = exc

    async with Runtime() as rt:
        node = rt.spawn(SelfCaller)
        await anyio.sleep(0.5)
        assert rt.clock.monotonic() == 0.5
        await anyio.lowlevel.checkpoint()
        assert isinstance(node.outcome, ServiceError)
        assert "calls its own service /ping" in str(node.outcome)


async def test_a_call_inside_a_callback_does_not_deadlock():
    class Relay(Node):
        """A subscription callback that awaits a service before answering."""

        def __init__(self) -> None:
            super().__init__("relay")
            self.cli = self.create_client(AddTwoInts, "add_two_ints")
            self.sums: list[int] = []
            self.create_subscription(Int64, "numbers", self.on_number, 10)

        async def on_number(self, msg: Int64) -> None:
            self.sums.append((await self.cli.call(AddTwoInts.Request(a=msg.data, b=100), timeout=1)).sum)

    class Numbers(Node):
        def __init__(self) -> None:
            super().__init__("numbers")
            self.pub = self.create_publisher(Int64, "numbers", 10)

    async with Runtime() as rt:
        rt.spawn(Adder)
        relay = rt.spawn(Relay)
        numbers = rt.spawn(Numbers)
        for i in range(3):
            numbers.pub.publish(Int64(data=i))
        await anyio.sleep(1)
        assert relay.sums == [100, 101, 102]


async def test_a_cancelled_caller_does_not_disturb_the_server():
    class SlowAdder(Adder):
        latency = 1.0

    async with Runtime() as rt:
        rt.spawn(SlowAdder)
        caller = rt.spawn(Caller)
        with anyio.move_on_after(0.5):
            await caller.cli.call(AddTwoInts.Request(a=1, b=1))
        response = await caller.cli.call(AddTwoInts.Request(a=2, b=2), timeout=5)
        assert response.sum == 4
        assert rt.graph.nodes()[0].crashes == 0


async def test_requests_queued_while_the_server_restarts_are_answered_by_the_new_instance():
    Adder.instances = 0
    async with Runtime(supervisor=SupervisorPolicy(backoff=1.0)) as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        caller.crash_pub.publish(Int64(data=1))
        await anyio.sleep(0.1)  # the adder has crashed and waits 1 s before restarting
        assert Adder.instances == 1
        response = await caller.cli.call(AddTwoInts.Request(a=20, b=22), timeout=5)
        assert response.sum == 42
        assert Adder.instances == 2
        assert rt.clock.monotonic() == pytest.approx(1.0)  # crashed at 0, 1 s backoff


async def test_calls_after_a_restart_go_to_the_new_instance():
    # The client remembers the server it found; a restart's new instance takes its place.
    async with Runtime(supervisor=SupervisorPolicy(backoff=1.0)) as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        assert (await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=1)).sum == 2
        caller.crash_pub.publish(Int64(data=1))
        await anyio.sleep(2)  # restarted
        assert (await caller.cli.call(AddTwoInts.Request(a=2, b=2), timeout=1)).sum == 4
        assert (await caller.cli.call(AddTwoInts.Request(a=3, b=3), timeout=1)).sum == 6
        (info,) = [s for s in rt.graph.services() if s.name == "/add_two_ints"]
        assert info.handled == 3


async def test_a_call_after_its_server_was_destroyed_waits_for_the_next_server_of_the_name():
    class Named(Node):
        """Answers /who with its own name."""

        def __init__(self, name: str) -> None:
            super().__init__(name)
            self.srv = self.create_service(Trigger, "/who", self.who)

        def who(self, request: Trigger.Request, response: Trigger.Response) -> Trigger.Response:
            response.message = self.get_name()
            return response

    class Asker(Node):
        def __init__(self) -> None:
            super().__init__("asker")
            self.cli = self.create_client(Trigger, "/who")

    async with Runtime() as rt:
        first = rt.spawn(Named, "first")
        asker = rt.spawn(Asker)
        assert (await asker.cli.call(Trigger.Request(), timeout=1)).message == "first"
        first.destroy_service(first.srv)
        with pytest.raises(TimeoutError):
            await asker.cli.call(Trigger.Request(), timeout=1)
        parked = asker.cli.call_async(Trigger.Request())
        second = rt.spawn(Named, "second")
        assert (await parked).message == "second"
        assert (await asker.cli.call(Trigger.Request(), timeout=1)).message == "second"
        second.destroy_service(second.srv)
        first.srv = first.create_service(Trigger, "/who", first.who)
        assert (await asker.cli.call(Trigger.Request(), timeout=1)).message == "first"


async def test_a_second_server_on_the_same_name_is_refused():
    async with Runtime() as rt:
        rt.spawn(Adder)
        with pytest.raises(ServiceError, match="/adder already serves it"):
            rt.spawn(Adder, name="adder2")


async def test_request_and_response_types_are_checked():
    class WrongResponse(Node):
        def __init__(self) -> None:
            super().__init__("wrong")
            self.create_service(SetBool, "set", lambda req, res: Trigger.Response())

    async with Runtime() as rt:
        rt.spawn(WrongResponse)
        caller = rt.spawn(Caller)
        with pytest.raises(TypeError, match="takes example_interfaces/srv/AddTwoInts_Request"):
            caller.cli.call_async(SetBool.Request())
        with pytest.raises(TypeError, match="takes example_interfaces/srv/AddTwoInts_Request"):
            await caller.cli.call(SetBool.Request(), timeout=1)  # call makes call_async's checks itself
        cli = caller._core.create_client(SetBool, "/set")
        with pytest.raises(ServiceError, match="expected std_srvs/srv/SetBool_Response"):
            await cli.call(SetBool.Request(data=True), timeout=1)


async def test_the_server_sees_each_request_as_it_was_when_called():
    async with Runtime() as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        request = AddTwoInts.Request()
        futures = []
        for i in range(3):
            request.a, request.b = i, 10  # one object reused, as rclpy allows
            futures.append(caller.cli.call_async(request))
        request.a = 1000
        assert [r.sum for r in await asyncio.gather(*futures)] == [10, 11, 12]


async def test_a_server_of_a_service_subclass_takes_every_call_through_its_own_push():
    # Client.call queues straight into a plain Service's queue; a subclass (a transport's
    # stand-in) keeps its own _push, also once its queue exists.
    pushed = []

    class Recording(Service):
        def _push(self, call):
            pushed.append(call[0].a)
            super()._push(call)

    def add(request, response):
        response.sum = request.a + request.b
        return response

    class Server(Node):
        def __init__(self) -> None:
            super().__init__("adder")
            self._core.add_service(Recording(self._core, "/add_two_ints", AddTwoInts, add))

    async with Runtime() as rt:
        rt.spawn(Server)
        caller = rt.spawn(Caller)
        sums = [(await caller.cli.call(AddTwoInts.Request(a=a, b=1))).sum for a in range(3)]
        assert (sums, pushed) == ([1, 2, 3], [0, 1, 2])


@pytest.mark.parametrize("kind", ["plain", "async"])
async def test_each_caller_gets_the_response_as_the_handler_returned_it(kind):
    class Reuser(Node):
        """Answers every call with one response object it keeps and changes: each caller must get its own copy."""

        def __init__(self) -> None:
            super().__init__("reuser")
            self.reply = AddTwoInts.Response()
            self.create_service(AddTwoInts, "add_two_ints", self.add if kind == "plain" else self.add_async)

        def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            self.reply.sum = request.a + request.b
            return self.reply

        async def add_async(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            return self.add(request, response)

    async with Runtime() as rt:
        reuser = rt.spawn(Reuser)
        caller = rt.spawn(Caller)
        futures = [caller.cli.call_async(AddTwoInts.Request(a=i, b=10)) for i in range(3)]  # served in one round
        responses = await asyncio.gather(*futures)
        reuser.reply.sum = -1
        assert [r.sum for r in responses] == [10, 11, 12]
        assert not any(r is reuser.reply for r in responses)


async def test_a_response_the_handler_did_not_keep_reaches_the_caller_itself_and_what_it_kept_as_a_copy():
    from interfaces.rcl_interfaces.msg import ParameterValue
    from interfaces.rcl_interfaces.srv import GetParameters

    class Lister(Node):
        """Fills the response it is given with its own list of values, which it keeps and grows."""

        def __init__(self) -> None:
            super().__init__("lister")
            self.values: list[ParameterValue] = []
            self.answered: list[int] = []  # ids of the responses it returned (an id holds no reference)
            self.create_service(GetParameters, "values", self.get)

        def get(self, request: GetParameters.Request, response: GetParameters.Response) -> GetParameters.Response:
            self.values.append(ParameterValue(type=2, integer_value=len(self.values)))
            response.values = self.values
            self.answered.append(id(response))
            return response

    async with Runtime() as rt:
        lister = rt.spawn(Lister)
        cli = rt.spawn(Caller)._core.create_client(GetParameters, "/values")
        first = await cli.call(GetParameters.Request(), timeout=1)
        second = await cli.call(GetParameters.Request(), timeout=1)
        lister.values[0].integer_value = -1
        # Nobody else held the response objects: checked in place, not copied ...
        assert lister.answered == [id(first), id(second)]
        # ... but the list and the values the handler kept were copied when it returned.
        assert [v.integer_value for v in first.values] == [0]
        assert [v.integer_value for v in second.values] == [0, 1]
        assert first.values is not lister.values and second.values[0] is not lister.values[0]


async def test_a_handler_that_cancels_its_own_caller_leaves_the_server_serving():
    tasks: list[asyncio.Task] = []

    class Canceller(Node):
        def __init__(self) -> None:
            super().__init__("canceller")
            self.create_service(AddTwoInts, "add_two_ints", self.add)

        def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            if request.a < 0:
                tasks[0].cancel()  # the caller's future is cancelled before the answer is set
            response.sum = request.a + request.b
            return response

    async with Runtime() as rt:
        rt.spawn(Canceller)
        caller = rt.spawn(Caller)
        tasks.append(asyncio.ensure_future(caller.cli.call(AddTwoInts.Request(a=-1, b=0))))
        with pytest.raises(asyncio.CancelledError):
            await tasks[0]
        assert (await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=1)).sum == 2
        assert rt.graph.nodes()[0].crashes == 0


async def test_fields_that_do_not_fit_fail_the_call_naming_the_field(caplog):
    class Sloppy(Node):
        def __init__(self) -> None:
            super().__init__("sloppy")
            self.create_service(AddTwoInts, "add_two_ints", self.add)

        def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            response.sum = str(request.a + request.b)
            return response

    caplog.set_level(logging.CRITICAL, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Sloppy)
        caller = rt.spawn(Caller)
        with pytest.raises(MessageValidationError, match=r"^field 'a' of example_interfaces/srv/AddTwoInts_Request: "):
            caller.cli.call_async(AddTwoInts.Request(a=2**63))
        with pytest.raises(MessageValidationError, match=r"^field 'b' of example_interfaces/srv/AddTwoInts_Request: "):
            await caller.cli.call(AddTwoInts.Request(b=1.5))
        with pytest.raises(
            ServiceError,
            match=r"field 'sum' of example_interfaces/srv/AddTwoInts_Response: "
            r"expected an int, got the str '3'",
        ):
            await caller.cli.call(AddTwoInts.Request(a=1, b=2), timeout=1)


async def test_calls_with_different_timeouts_each_time_out_at_their_own_deadline():
    class SlowAdder(Adder):
        latency = 1.0  # one call at a time: the n-th answer comes at n seconds

    async with Runtime() as rt:
        rt.spawn(SlowAdder)
        caller = rt.spawn(Caller)
        await anyio.lowlevel.checkpoint()
        timeouts = [10, 0.5, 1.5, 10]  # answered at 1 s; given up at 0.5 s; given up at 1.5 s; answered at 3 s
        outcomes: dict[int, object] = {}

        async def one(i: int) -> None:
            try:
                outcomes[i] = (await caller.cli.call(AddTwoInts.Request(a=i, b=0), timeout=timeouts[i])).sum
            except TimeoutError:
                outcomes[i] = ("timed out", rt.clock.monotonic())

        async with anyio.create_task_group() as tg:
            for i in range(len(timeouts)):
                tg.start_soon(one, i)
        assert outcomes == {0: 0, 1: ("timed out", 0.5), 2: ("timed out", 1.5), 3: 3}
        assert live_loop_timers() == []  # no deadline left armed once nobody waits


async def _hundred_callers(rt: Runtime, caller: Caller) -> list[int]:
    """100 callers make 20 calls each (timeout=60); how many deadlines the runtime held after each call."""
    timeouts = rt.services.timeouts(rt.loop)
    sizes = []

    async def one(i: int) -> None:
        for _ in range(20):
            await caller.cli.call(AddTwoInts.Request(a=i, b=1), timeout=60)
            sizes.append(sum(map(len, timeouts._lanes.values())))

    async with anyio.create_task_group() as tg:
        for i in range(100):
            tg.start_soon(one, i)
    assert len(sizes) == 2000
    return sizes


async def test_answered_calls_leave_no_deadlines_behind():
    async with Runtime() as rt:
        rt.spawn(Adder)
        caller = rt.spawn(Caller)
        await anyio.lowlevel.checkpoint()
        # Answered entries are swept out, not kept for their 60 s.
        assert max(await _hundred_callers(rt, caller)) <= 2 * 100 + 64 + 1
        timeouts = rt.services.timeouts(rt.loop)
        assert timeouts._lanes == {} and timeouts._heads == [] and live_loop_timers() == []


def test_on_the_wall_clock_answered_calls_are_swept_without_being_counted_and_a_late_one_times_out():
    class Dawdler(Node):
        def __init__(self) -> None:
            super().__init__("dawdler")
            self.create_service(AddTwoInts, "dawdle", self.dawdle)

        async def dawdle(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            await asyncio.sleep(request.a)
            return response

    async def main() -> None:
        async with Runtime() as rt:
            rt.spawn(Adder)
            rt.spawn(Dawdler)
            caller = rt.spawn(Caller)
            dawdle = caller._core.create_client(AddTwoInts, "/dawdle")
            await asyncio.sleep(0)
            # A call that waits all along heads the lane of 60 s while 2,000 others come and go behind it.
            waiting = asyncio.ensure_future(dawdle.call(AddTwoInts.Request(a=3600), timeout=60))
            assert max(await _hundred_callers(rt, caller)) <= 2 * 101 + 64 + 1
            assert not waiting.done()
            waiting.cancel()
            with pytest.raises(TimeoutError, match=re.escape("no response from service /dawdle within 0.05 s")):
                await dawdle.call(AddTwoInts.Request(a=3600), timeout=0.05)
            assert (await caller.cli.call(AddTwoInts.Request(a=2, b=3), timeout=60)).sum == 5

    asyncio.run(main())


async def test_a_round_of_an_async_handler_serves_the_calls_queued_when_it_began_and_later_ones_next_round():
    # Calls that come while the handler awaits wait for the next round, behind a message that
    # came meanwhile: the round stops at the last call queued when it began.
    log: list[str] = []
    gate = asyncio.Event()

    class Slow(Node):
        def __init__(self) -> None:
            super().__init__("slow")
            self.create_service(AddTwoInts, "add_two_ints", self.add)
            self.create_subscription(Int64, "/slow_note", lambda msg: log.append(f"note {msg.data}"), 10)

        async def add(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> AddTwoInts.Response:
            log.append(f"call {request.a}")
            if request.a == 0:
                await gate.wait()
            response.sum = request.a + request.b
            return response

    async with Runtime() as rt:
        rt.spawn(Slow)
        caller = rt.spawn(Caller)
        note = caller.create_publisher(Int64, "/slow_note", 10)
        early = [caller.cli.call_async(AddTwoInts.Request(a=a, b=0)) for a in range(3)]
        while log != ["call 0"]:
            await asyncio.sleep(0)
        late = [caller.cli.call_async(AddTwoInts.Request(a=a, b=0)) for a in (3, 4)]
        note.publish(Int64(data=7))
        gate.set()
        assert [r.sum for r in await asyncio.gather(*early, *late)] == [0, 1, 2, 3, 4]
        assert log == ["call 0", "call 1", "call 2", "note 7", "call 3", "call 4"]


async def test_a_server_destroyed_with_calls_queued_before_its_round_fails_them_and_its_node_runs_on():
    # The round the server was scheduled for still comes, to an emptied queue.
    class Quitter(Node):
        def __init__(self) -> None:
            super().__init__("quitter")
            self.create_subscription(Int64, "/quitter_stop", self.stop, 10)  # runs first in the round
            self.srv = self.create_service(AddTwoInts, "add_two_ints", lambda request, response: response)

        def stop(self, msg: Int64) -> None:
            self.destroy_service(self.srv)

    async with Runtime() as rt:
        rt.spawn(Quitter)
        caller = rt.spawn(Caller)
        stop = caller.create_publisher(Int64, "/quitter_stop", 10)
        await caller.cli.call(AddTwoInts.Request(a=1, b=1), timeout=1)
        stop.publish(Int64(data=1))
        futures = [caller.cli.call_async(AddTwoInts.Request(a=a, b=0)) for a in range(2)]
        for future in futures:
            with pytest.raises(ServiceError, match="was destroyed"):
                await future
        await asyncio.sleep(0)
        assert rt.graph.nodes()[0].crashes == 0
