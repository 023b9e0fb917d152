"""A bag recorded elsewhere, of types actors does not ship: typed from its own schemas, it plays and echoes."""

from __future__ import annotations

import sys
from pathlib import Path

import anyio
import pytest
import yaml

from actors import Runtime, codec
from actors.cli import main
from actors.errors import UnknownInterfaceError
from actors.messages import discovery
from actors.ops.control import ControlEndpoint
from actors.recording.player import plan, play, timeline
from actors.recording.reader import Bag

rosbag2 = pytest.importorskip("rosbags.rosbag2", reason="the foreign bag is written by rosbags (test extra)")
typesys = pytest.importorskip("rosbags.typesys")

CELL = "float32 volts\nuint8 health\n"
BATTERY = "std_msgs/Header header\nCell[] cells\nstring label\nuint8 FULL=100\n"


def foreign_bag(path: Path) -> str:
    """A rosbag2 MCAP bag of robot_msgs/msg/Battery written by rosbags; returns rosbags' RIHS01 of the type."""
    store = typesys.get_typestore(typesys.Stores.ROS2_KILTED)
    store.register(typesys.get_types_from_msg(CELL, "robot_msgs/msg/Cell"))
    store.register(typesys.get_types_from_msg(BATTERY, "robot_msgs/msg/Battery"))
    types = store.types
    with rosbag2.Writer(path, version=9, storage_plugin=rosbag2.StoragePlugin.MCAP) as writer:
        channel = writer.add_connection("/battery", "robot_msgs/msg/Battery", typestore=store)
        for i in range(3):
            header = types["std_msgs/msg/Header"](
                stamp=types["builtin_interfaces/msg/Time"](sec=i, nanosec=0), frame_id="base"
            )
            cells = [types["robot_msgs/msg/Cell"](volts=3.5 + i, health=90 - i)]
            msg = types["robot_msgs/msg/Battery"](header=header, cells=cells, label=f"b{i}")
            writer.write(channel, (i + 1) * 100_000_000, store.serialize_cdr(msg, "robot_msgs/msg/Battery"))
    return store.hash_rihs01("robot_msgs/msg/Battery")


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    monkeypatch.setattr(discovery, "_found", {})
    monkeypatch.setenv("ACTORS_INTERFACE_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    monkeypatch.chdir(tmp_path)
    yield tmp_path
    for name in [n for n in sys.modules if n.startswith("interfaces.robot_msgs")]:
        del sys.modules[name]
    codec._types.clear()


def test_a_type_we_do_not_ship_is_typed_from_the_bag_and_hashes_as_rosbags_does(fresh):
    theirs = foreign_bag(fresh / "foreign")
    with pytest.raises(UnknownInterfaceError):
        codec.get_type("robot_msgs/msg/Battery")
    playable, skipped = plan(Bag(fresh / "foreign"))
    assert skipped == []
    battery = playable["/battery"].msg_type
    assert battery.__ros_type__ == "robot_msgs/msg/Battery" and battery.FULL == 100
    assert codec.type_hash(battery) == theirs
    messages = [msg for _, _, msg in timeline(Bag(fresh / "foreign"), playable)]
    assert [(m.label, m.header.stamp.sec, m.cells[0].volts, m.cells[0].health) for m in messages] == [
        ("b0", 0, 3.5, 90),
        ("b1", 1, 4.5, 89),
        ("b2", 2, 5.5, 88),
    ]


async def test_a_foreign_bag_plays_into_a_graph_and_topic_echo_shows_its_messages(fresh, capsys):
    foreign_bag(fresh / "foreign")
    bag = Bag(fresh / "foreign")
    async with Runtime(name="foreign_bag", attach=[ControlEndpoint()]) as rt:
        plan(bag)  # types the bag's topics, as 'actors bag play' does before it starts
        async with anyio.create_task_group() as tg:
            echoed: list[int] = []

            async def echo() -> None:
                echoed.append(await anyio.to_thread.run_sync(main, ["topic", "echo", "/battery", "--once"]))

            tg.start_soon(echo)
            with anyio.fail_after(10):
                while not echoed:  # echo subscribes when its connection is served: play until it has heard one
                    await play(rt, bag)
    assert echoed == [0]
    first = next(yaml.safe_load_all(capsys.readouterr().out))
    assert first["label"].startswith("b") and first["cells"][0]["health"] in (88, 89, 90)
    assert first["header"]["frame_id"] == "base"
