"""The World's 3D scene (world/scene.py): what a live view shows of the arena, the robots and their scans."""

from __future__ import annotations

import math

import anyio
import anyio.abc
import pytest
from conftest import protobuf_class

from actors import Node, Runtime
from interfaces.sensor_msgs.msg import LaserScan
from world.robot import TurtleBot
from world.scene import OBSTACLE_HEIGHT, scene_update
from world.sim import World

fm = pytest.importorskip("foxglove.messages")
pytest.importorskip("google.protobuf", reason="the scene is read back with its protobuf schema (test extra)")

pytestmark = pytest.mark.virtual_time

WORLD_FILE = """
[bounds]
min = [-2.0, -2.0]
max = [2.0, 2.0]

[[walls]]
start = [-2.0, 2.0]
end = [2.0, 2.0]
thickness = 0.2

[[polygons]]
name = "wedge"
vertices = [[1.0, -1.0], [1.5, -1.0], [1.0, -0.5]]
"""


class ScanReader(Node):
    """Subscribes to scan: without a reader the robot casts no lidar."""

    def __init__(self) -> None:
        super().__init__("scan_reader")
        self.create_subscription(LaserScan, "scan", lambda msg: None, 10)


def _read(update):
    schema = fm.SceneUpdate.get_schema()
    return protobuf_class(schema.name, schema.data).FromString(update.encode())


class Host:
    """A live view as the World sees it: an attachment that shows scenes (it draws none here)."""

    def __init__(self) -> None:
        self.scenes: dict[str, object] = {}

    async def __call__(self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[None]) -> None:
        task_status.started()
        await anyio.sleep_forever()

    def add_scene(self, topic: str, draw: object) -> None:
        self.scenes[topic] = draw

    def remove_scene(self, topic: str) -> None:
        self.scenes.pop(topic, None)


@pytest.mark.parametrize("reader", ["a /scan subscription", "a live view alone"])
async def test_the_scene_holds_the_arena_and_each_robot_and_its_scan_once_it_has_one(tmp_path, reader):
    path = tmp_path / "wedge.toml"
    path.write_text(WORLD_FILE)
    host = Host()
    async with Runtime(attach=[host] if reader == "a live view alone" else []) as rt:
        world = rt.spawn(World, params={"world": str(path)})
        rt.spawn(TurtleBot, name="turtlebot", namespace="robot1", params={"x": 0.5, "theta": math.pi / 2})
        if reader == "a /scan subscription":
            rt.spawn(ScanReader, namespace="robot1")
        else:
            assert list(host.scenes) == ["/scene"]
        before = _read(scene_update(world, rt.clock.now_ns()))
        await anyio.sleep(0.15)  # one scan
        now = rt.clock.now_ns()
        after = _read(scene_update(world, now))
    assert [e.id for e in before.entities] == ["walls", "obstacles", "/robot1/turtlebot"]
    assert [e.id for e in after.entities] == ["walls", "obstacles", "/robot1/turtlebot", "/robot1/turtlebot/scan"]
    walls, obstacles, robot, scan = after.entities
    assert {(e.frame_id, e.timestamp.seconds * 10**9 + e.timestamp.nanos) for e in after.entities} == {("world", now)}
    (wall,) = walls.cubes
    assert (wall.pose.position.x, wall.pose.position.y) == (0.0, 2.0)
    assert (wall.size.x, wall.size.y) == (pytest.approx(4.2), pytest.approx(0.2))  # square caps, as simulated
    (outline,) = obstacles.lines
    assert len(outline.points) == 3 * 6  # per corner: its floor edge, its top edge, its upright
    assert {(p.x, p.y) for p in outline.points} == {(1.0, -1.0), (1.5, -1.0), (1.0, -0.5)}
    assert {p.z for p in outline.points} == {0.0, OBSTACLE_HEIGHT}
    (body,) = robot.cylinders
    (heading,) = robot.arrows
    assert (body.pose.position.x, body.pose.position.y) == (pytest.approx(0.5), pytest.approx(0.0))
    assert 2 * math.atan2(heading.pose.orientation.z, heading.pose.orientation.w) == pytest.approx(math.pi / 2)
    # Facing +y from (0.5, 0): the beam straight ahead ends on the wall's face at y = 1.9.
    ahead = [s.pose.position for s in scan.spheres if abs(s.pose.position.x - 0.5) < 1e-9]
    assert [p.y for p in ahead] == [pytest.approx(1.9)]
    # Nothing beyond range_max (3.5 m) in a 4 m arena with one wall: the points are the wall's and the wedge's.
    assert all(p.pose.position.y == pytest.approx(1.9) or p.pose.position.x >= 1.0 - 1e-9 for p in scan.spheres)
