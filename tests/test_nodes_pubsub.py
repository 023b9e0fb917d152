"""The tutorial talker, listener and heartbeat nodes."""

from __future__ import annotations

import logging

import anyio
import pytest

from actors import Node, Runtime
from interfaces.std_msgs.msg import Bool, Int64
from nodes.heartbeat import Heartbeat
from nodes.listener import MinimalSubscriber
from nodes.talker import MinimalPublisher

pytestmark = pytest.mark.virtual_time


async def test_talker_and_listener(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        rt.spawn(MinimalSubscriber)
        rt.spawn(MinimalPublisher)
        await anyio.sleep(1.6)
    lines = [(r.ros_name, r.getMessage()) for r in caplog.records]
    assert ("minimal_publisher", 'Publishing: "Hello World: 2"') in lines
    heard = [text for name, text in lines if name == "minimal_subscriber"]
    assert heard == [f'I heard: "Hello World: {i}"' for i in range(3)]


class MotorHealth(Node):
    def __init__(self) -> None:
        super().__init__("motor")
        self.beats: list[int] = []
        self.pub = self.create_publisher(Bool, "/health/motor", 10)
        self.create_subscription(Int64, "/heartbeat", lambda m: self.beats.append(m.data), 10)


async def test_heartbeat_counts_until_the_motor_fails(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        heartbeat = rt.spawn(Heartbeat)
        motor = rt.spawn(MotorHealth)
        await anyio.sleep(3.5)
        motor.pub.publish(Bool(data=True))
        await anyio.sleep(1)
        motor.pub.publish(Bool(data=False))
        await anyio.sleep(5)
        assert motor.beats == [0, 1, 2, 3]
        assert heartbeat.hb_timer.is_canceled()
    fatal = [r for r in caplog.records if r.levelno == logging.CRITICAL]
    assert [(r.ros_name, r.getMessage()) for r in fatal] == [("heartbeat", "Heartbeat stopped")]
