"""The publish/deliver states, named: each arises where the design says, and the invariant check catches bad fields."""

from __future__ import annotations

import asyncio

import pytest

from actors import Node, Runtime
from actors.ros.topics import PublisherState, SubscriptionState
from interfaces.std_msgs.msg import Int64

pytestmark = pytest.mark.virtual_time


class Ear(Node):
    """Hears ``numbers``; notes its own subscription's state while its callback runs."""

    def __init__(self, name: str = "ear", depth: int = 5) -> None:
        super().__init__(name)
        self.heard: list[int] = []
        self.states_in_callback: list[SubscriptionState] = []
        self.sub = self.create_subscription(Int64, "numbers", self.on_number, depth)

    def on_number(self, msg: Int64) -> None:
        self.heard.append(msg.data)
        self.states_in_callback.append(self.sub.state)


class Mouth(Node):
    def __init__(self, name: str = "mouth") -> None:
        super().__init__(name)
        self.pub = self.create_publisher(Int64, "numbers", 10)

    def say(self, *numbers: int) -> None:
        for n in numbers:
            self.pub.publish(Int64(data=n))


async def turns(n: int = 5) -> None:
    for _ in range(n):
        await asyncio.sleep(0)


async def test_one_subscription_is_fed_directly_and_rounds_of_several_count_their_rest():
    async with Runtime() as rt:
        ear, mouth = rt.spawn(Ear), rt.spawn(Mouth)
        mouth.say(1)  # the first publish settles the path
        assert mouth.pub.state is PublisherState.DIRECT
        mouth.say(2, 3)
        assert ear.sub.state is SubscriptionState.IDLE
        await turns()
        assert ear.heard == [1, 2, 3]
        assert set(ear.states_in_callback) == {SubscriptionState.IN_ROUND}
        assert ear.sub.state is SubscriptionState.IDLE
        assert rt.topics.invariant_violations() == []


async def test_several_subscriptions_share_one_batch_that_a_round_closes():
    async with Runtime() as rt:
        ears = [rt.spawn(Ear, name=f"ear{i}", depth=3 + i) for i in range(3)]
        mouth = rt.spawn(Mouth)
        mouth.say(1)
        assert mouth.pub.state is PublisherState.BATCH_OPEN
        assert rt.topics.topics["/numbers"].dirty is mouth.pub
        assert {ear.sub.state for ear in ears} == {SubscriptionState.HOLDING_BATCH}
        assert rt.topics.invariant_violations() == []
        await turns()
        assert mouth.pub.state is PublisherState.BATCHING
        assert [ear.heard for ear in ears] == [[1]] * 3
        assert rt.topics.invariant_violations() == []


async def test_a_second_publisher_makes_the_first_check_for_a_batch_and_a_joiner_makes_paths_stale():
    async with Runtime() as rt:
        rt.spawn(Ear)
        first, second = rt.spawn(Mouth, name="first"), rt.spawn(Mouth, name="second")
        first.say(1)
        second.say(2)
        assert (first.pub.state, second.pub.state) == (PublisherState.DIRECT_SHARED,) * 2
        rt.spawn(Ear, name="late")
        assert (first.pub.state, second.pub.state) == (PublisherState.STALE,) * 2
        assert rt.topics.invariant_violations() == []
        first.say(3)
        assert first.pub.state is PublisherState.BATCH_OPEN
        assert rt.topics.invariant_violations() == []


async def test_a_publisher_left_alone_on_its_topic_stops_checking_for_another_batch():
    async with Runtime() as rt:
        rt.spawn(Ear)
        first, second = rt.spawn(Mouth, name="first"), rt.spawn(Mouth, name="second")
        first.say(1)
        assert first.pub.state is PublisherState.DIRECT_SHARED
        second.pub.destroy()
        assert first.pub.state is PublisherState.DIRECT
        assert rt.topics.invariant_violations() == []


async def test_the_check_names_fields_that_disagree():
    async with Runtime() as rt:
        ears = [rt.spawn(Ear, name=f"ear{i}") for i in range(2)]
        mouth = rt.spawn(Mouth)
        mouth.say(1)
        ears[0].sub._limit = ears[0].sub._depth  # a held batch would no longer be moved first
        ears[1].sub._batch = None  # the batch open is not held by every feed
        found = rt.topics.invariant_violations()
        assert any("ear0 on /numbers (holding a batch)" in line for line in found)
        assert any("a batch open that a feed does not hold" in line for line in found)
        rt.topics.topics["/numbers"].dirty = None
        assert any("not the topic's dirty publisher" in line for line in rt.topics.invariant_violations())
