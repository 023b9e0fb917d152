"""rclpy's Waitable on the overlay: a user's own work polled and run by a node's executor."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from actors.compat.rclpy.waitable import NumberOfEntities, Waitable


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


class Mailbox(Waitable):
    """Ready while letters wait; each execution handles the letter taken for it."""

    def __init__(self) -> None:
        super().__init__(MutuallyExclusiveCallbackGroup())
        self.letters: list[str] = []
        self.handled: list[str] = []
        self.polls = 0

    def add_to_wait_set(self, wait_set):
        self.polls += 1

    def is_ready(self, wait_set):
        return bool(self.letters)

    def take_data(self):
        return self.letters.pop(0)

    async def execute(self, taken_data):
        self.handled.append(taken_data.upper())

    def get_num_entities(self):
        return NumberOfEntities(num_guard_conditions=1)


def test_a_ready_waitable_has_its_data_taken_and_executed_in_order(session):
    node = rclpy.create_node("post_office")
    box = Mailbox()
    node.add_waitable(box)
    assert box in node.waitables and box.callback_group.has_entity(box)
    rclpy.spin_once(node, timeout_sec=0.1)
    assert box.polls >= 1 and box.handled == []  # polled, nothing to do
    box.letters += ["a", "b"]
    rclpy.spin_once(node, timeout_sec=0.1)
    rclpy.spin_once(node, timeout_sec=0.1)
    assert box.handled == ["A", "B"] and box.letters == []
    node.remove_waitable(box)
    box.letters.append("c")
    rclpy.spin_once(node, timeout_sec=0.1)
    assert box.handled == ["A", "B"]


def test_counts_add_up_and_the_base_is_abstract():
    total = NumberOfEntities(1, 2, 3, 4, 5, 6) + NumberOfEntities(num_events=4)
    assert (total.num_subscriptions, total.num_events) == (1, 10)
    total += NumberOfEntities(num_timers=1)
    assert total == NumberOfEntities(1, 2, 4, 4, 5, 10) and repr(total) == "<NumberOfEntities(1, 2, 4, 4, 5, 10)>"
    with pytest.raises(TypeError, match="abstract"):
        Waitable(MutuallyExclusiveCallbackGroup())  # type: ignore[abstract]
