"""turtlesim on virtual time: the update rule against a model of ROS 2's, services, the action, the picture."""

from __future__ import annotations

import io
import logging
import math
import random
from itertools import pairwise

import anyio
import numpy as np
import pytest

from actors import Node, Runtime
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_srvs.srv import Empty
from interfaces.turtlesim_msgs.action import RotateAbsolute
from interfaces.turtlesim_msgs.msg import Color, Pose
from interfaces.turtlesim_msgs.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative
from world.canvas import METER, gif_bytes, png_bytes
from world.draw_square import DrawSquare
from world.mimic import Mimic
from world.teleop_key import TeleopTurtle
from world.turtlesim import BACKGROUND, WORLD_SIZE, Turtlesim

pytestmark = pytest.mark.virtual_time

FRAME_NS = 16_000_000
CENTRE = float(np.float32(WORLD_SIZE / 2))


def as_f32(value: float) -> float:
    return float(np.float32(value))


def model_poses(start: tuple[float, float, float], commands: list[tuple[int, float, float]], frames: int):
    """ROS 2 turtlesim's update rule, written from turtle.cpp for this test: poses after frames 2..frames.

    ``commands`` are (arrival in ns, linear.x, angular.z), each arriving
    between two frames.  Frame k happens at k·16 ms; the first only starts
    the frame count.  Positions are kept as the window has them (y down).
    """
    x, y, theta = start[0], WORLD_SIZE - start[1], start[2]
    lin = ang = 0.0
    last_ns = 0
    pending = sorted(commands)
    poses = []
    for k in range(2, frames + 1):
        now = k * FRAME_NS
        while pending and pending[0][0] < now:
            last_ns, lin, ang = pending.pop(0)
        if now - last_ns > 1_000_000_000:
            lin = ang = 0.0
        theta += ang * 0.016
        theta -= 2 * math.pi * math.floor((theta + math.pi) / (2 * math.pi))
        x += math.cos(theta) * lin * 0.016
        y -= math.sin(theta) * lin * 0.016
        x, y = min(max(x, 0.0), WORLD_SIZE), min(max(y, 0.0), WORLD_SIZE)
        poses.append((as_f32(x), as_f32(WORLD_SIZE - y), as_f32(theta), as_f32(abs(lin)), as_f32(ang)))
    return poses


class Watcher(Node):
    """Records each listed turtle's poses and colours, and drives it from a schedule of commands."""

    def __init__(self, names: list[str], schedule: dict[str, list[tuple[int, float, float]]] | None = None) -> None:
        super().__init__("watcher")
        self.poses: dict[str, list[tuple[float, ...]]] = {n: [] for n in names}
        self.colours: dict[str, list[Color]] = {n: [] for n in names}
        self.pubs = {n: self.create_publisher(Twist, f"/{n}/cmd_vel", 10) for n in names}
        for n in names:
            self.create_subscription(Pose, f"/{n}/pose", lambda m, n=n: self.poses[n].append(_fields(m)), 1000)
            self.create_subscription(Color, f"/{n}/color_sensor", self.colours[n].append, 1000)
        self.due = sorted((t, n, v, w) for n, cmds in (schedule or {}).items() for t, v, w in cmds)
        if self.due:
            self.create_timer(0.008, self.send)  # ticks at 8 ms + k·8 ms; commands fall between frames

    def send(self) -> None:
        now = self.get_clock().now().nanoseconds
        while self.due and self.due[0][0] <= now:
            _, name, v, w = self.due.pop(0)
            twist = Twist()
            twist.linear.x, twist.angular.z = v, w
            self.pubs[name].publish(twist)


def _fields(pose: Pose) -> tuple[float, ...]:
    return (pose.x, pose.y, pose.theta, pose.linear_velocity, pose.angular_velocity)


async def test_the_update_rule_matches_ros_over_a_thousand_random_command_sequences():
    rng = random.Random(32)
    frames = 80  # 1.28 s: long enough for the one-second command timeout to bite
    starts, schedule = {}, {}
    for i in range(1000):
        name = f"t{i:04d}"
        starts[name] = (rng.uniform(0, WORLD_SIZE), rng.uniform(0, WORLD_SIZE), rng.uniform(-math.pi, math.pi))
        # Commands at odd multiples of 8 ms, so each arrives strictly between two frames.
        times = sorted(rng.sample(range(1, 2 * frames - 1, 2), rng.randint(1, 6)))
        schedule[name] = [(t * 8_000_000, rng.uniform(-6, 6), rng.uniform(-6, 6)) for t in times]
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim)
        for name, (x, y, theta) in starts.items():
            sim.spawn(name, x, y, theta)
        watcher = rt.spawn(Watcher, list(starts), schedule)
        await anyio.sleep(frames * 0.016 + 0.004)
    for name, (x, y, theta) in starts.items():
        start = (as_f32(x), as_f32(y), as_f32(theta))
        assert watcher.poses[name] == model_poses(start, schedule[name], frames), name


async def test_start_parameters_and_the_centre():
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        await anyio.sleep(0.1)
    assert [sim.get_parameter(f"background_{c}").value for c in "rgb"] == [69, 86, 255]
    assert sim.get_parameter("holonomic").value is False
    assert not sim.has_parameter("image")  # declared only when given
    assert watcher.poses["turtle1"][0] == (CENTRE, CENTRE, 0.0, 0.0, 0.0)
    assert f"{CENTRE:f}" == "5.544445"  # as the start log prints it
    # Nothing drawn under a turtle that has not moved: transparent white, as ROS 2's path image.
    assert (watcher.colours["turtle1"][0].r, watcher.colours["turtle1"][0].g) == (255, 255)


async def test_a_command_lasts_one_second_and_the_wall_clamps_with_a_warning(caplog):
    caplog.set_level(logging.WARNING, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"], {"turtle1": [(8_000_000, 10.0, 0.0)]})
        await anyio.sleep(2)
    poses = watcher.poses["turtle1"]
    assert poses[-1][0] == as_f32(WORLD_SIZE)  # 10 m/s for 1 s would be far past the wall
    assert poses[-1][3] == 0.0  # stopped by the timeout
    moving = [p for p in poses if p[3] > 0]
    assert len(moving) == 62  # frames at 32 ms .. 1008 ms: 1.008 - 0.008 = 1.0 is not "more than one second"
    warnings = [r.getMessage() for r in caplog.records if "hit the wall" in r.getMessage()]
    assert warnings and warnings[0].startswith("Oh no! I hit the wall! (Clamping from [x=11.")


class Caller(Node):
    def __init__(self) -> None:
        super().__init__("caller")


async def call(node: Node, srv_type, service: str, **fields):
    client = node.create_client(srv_type, service)
    return await client.call(srv_type.Request(**fields), timeout=1.0)


async def test_spawn_kill_clear_and_reset(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim)
        caller = rt.spawn(Caller)
        assert (await call(caller, Spawn, "/spawn", x=2.0, y=2.0, theta=0.2, name="")).name == "turtle2"
        assert (await call(caller, Spawn, "/spawn", x=1.0, y=1.0, name="turtle2")).name == ""
        assert (await call(caller, Spawn, "/spawn", x=1.0, y=1.0, name="9lives")).name == ""
        assert (await call(caller, Spawn, "/spawn", x=3.0, y=4.0, name="leo")).name == "leo"
        topics = {name for name, _ in caller.get_topic_names_and_types()}
        assert {"/turtle2/pose", "/leo/cmd_vel", "/leo/color_sensor"} <= topics
        await call(caller, Kill, "/kill", name="leo")
        await call(caller, Kill, "/kill", name="nobody")
        topics = {name for name, _ in caller.get_topic_names_and_types()}
        assert "/leo/pose" not in topics and "/turtle2/pose" in topics
        await call(caller, Empty, "/reset")
        assert list(sim.turtles) == ["turtle1"]
        assert (await call(caller, Spawn, "/spawn", x=1.0, y=1.0, name="")).name == "turtle2"  # the count restarts
        await call(caller, Empty, "/clear")
    text = [r.getMessage() for r in caplog.records]
    assert "Spawning turtle [turtle2] at x=[2.000000], y=[2.000000], theta=[0.200000]" in text
    assert "A turtle named [turtle2] already exists" in text
    assert "Tried to kill turtle [nobody], which does not exist" in text
    assert "Resetting turtlesim." in text and "Clearing turtlesim." in text
    assert any(t.startswith("Cannot spawn a turtle named [9lives]") for t in text)


async def test_teleports_move_the_turtle_and_draw_with_the_pen():
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        caller = rt.spawn(Caller)
        await call(caller, TeleportAbsolute, "/turtle1/teleport_absolute", x=1.0, y=1.0, theta=0.0)
        await anyio.sleep(0.05)
        x, y, theta = watcher.poses["turtle1"][-1][:3]
        assert (x, y, theta) == (1.0, 1.0, 0.0)
        await call(caller, SetPen, "/turtle1/set_pen", r=255, g=0, b=0, width=5, off=0)
        await call(caller, TeleportRelative, "/turtle1/teleport_relative", linear=2.0, angular=math.pi / 2)
        await anyio.sleep(0.05)
        x, y, theta = watcher.poses["turtle1"][-1][:3]
        assert (x, y, theta) == pytest.approx((1.0, 3.0, math.pi / 2), abs=1e-6)
        await call(caller, SetPen, "/turtle1/set_pen", off=1)
        await call(caller, TeleportAbsolute, "/turtle1/teleport_absolute", x=9.0, y=3.0, theta=0.0)
        await anyio.sleep(0.05)
        picture = sim.picture()

    def at(x: float, y: float) -> tuple[int, ...]:
        return tuple(picture[round((WORLD_SIZE - y) * METER), round(x * METER)])

    assert at(1.0, 2.0) == (255, 0, 0)  # the red segment of the relative teleport
    assert at(1.0 + 2 / METER, 2.0) == (255, 0, 0)  # five pixels wide: two either side
    assert at(1.0 + 4 / METER, 2.0) == BACKGROUND
    assert at(5.0, 3.0) == BACKGROUND  # pen up on the way to (9, 3)
    assert at(3.0, 3.0) == (0xB3, 0xB8, 0xFF)  # the default pen from the centre to (1, 1)


async def test_rotate_absolute_feedback_success_cancel_and_preemption(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        caller = rt.spawn(Caller)
        action = caller.create_action_client(RotateAbsolute, "/turtle1/rotate_absolute")
        feedback: list[float] = []
        goal = await action.send_goal(RotateAbsolute.Goal(theta=1.0), feedback=lambda f: feedback.append(f.remaining))
        done = await goal.get_result()
        assert done.status == 4  # SUCCEEDED
        assert abs(watcher.poses["turtle1"][-1][2] - 1.0) < 0.02
        assert done.result.delta == pytest.approx(-1.0, abs=0.03)
        assert feedback[0] == pytest.approx(1.0) and all(a > b for a, b in pairwise(feedback))

        goal = await action.send_goal(RotateAbsolute.Goal(theta=-2.0))
        await anyio.sleep(0.5)
        await goal.cancel()
        canceled = await goal.get_result()
        assert canceled.status == 5  # CANCELED
        after_cancel = watcher.poses["turtle1"][-1]
        await anyio.sleep(0.2)
        assert watcher.poses["turtle1"][-1][2] == after_cancel[2]  # it stopped turning

        first = await action.send_goal(RotateAbsolute.Goal(theta=3.0))
        await anyio.sleep(0.1)
        second = await action.send_goal(RotateAbsolute.Goal(theta=0.0))
        assert (await first.get_result()).status == 6  # ABORTED: preempted
        await anyio.sleep(0.1)
        watcher.pubs["turtle1"].publish(Twist())
        assert (await second.get_result()).status == 6  # ABORTED by a velocity command
    text = [r.getMessage() for r in caplog.records]
    assert "Rotation goal completed successfully" in text and "Rotation goal canceled" in text
    assert "Rotation goal received before a previous goal finished. Aborting previous goal" in text
    assert "Velocity command received during rotation goal. Aborting goal" in text


async def test_the_colour_sensor_reads_the_trail_and_the_background_parameter_paints():
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim, params={"background_r": 10})
        watcher = rt.spawn(Watcher, ["turtle1"], {"turtle1": [(8_000_000, 1.0, 0.0)]})
        caller = rt.spawn(Caller)
        await call(caller, SetPen, "/turtle1/set_pen", r=1, g=2, b=3, width=9, off=0)
        await anyio.sleep(0.5)
        picture = sim.picture()
    assert (watcher.colours["turtle1"][-1].r, watcher.colours["turtle1"][-1].g) == (1, 2)
    assert tuple(picture[5, 5]) == (10, 86, 255)


async def test_the_picture_is_written_as_a_png_at_shutdown(tmp_path):
    from PIL import Image

    path = tmp_path / "turtlesim.png"
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim, params={"image": str(path)})
        assert sim.get_parameter("image").value == str(path)
        await anyio.sleep(0.1)
        expected = sim.picture()
    with Image.open(path) as image:
        assert image.size == (500, 500) and image.mode == "RGB"
        assert np.array_equal(np.asarray(image), expected)
    with Image.open(io.BytesIO(png_bytes(expected[:7, :3]))) as small:
        assert small.size == (3, 7)


async def test_the_picture_is_written_as_a_gif_when_the_name_says_so(tmp_path):
    from PIL import Image

    path = tmp_path / "turtlesim.gif"
    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim, params={"image": str(path)})
        watcher = rt.spawn(Watcher, ["turtle1"])
        twist = Twist()
        twist.linear.x, twist.angular.z = 2.0, 1.8
        watcher.pubs["turtle1"].publish(twist)
        await anyio.sleep(1.0)
        expected = sim.picture()
    with Image.open(path) as image:
        assert (image.format, image.size) == ("GIF", (500, 500))
        assert np.array_equal(np.asarray(image.convert("RGB")), expected)
    # more colours than a GIF holds: each pixel snaps to the nearest of a 6x7x6 cube's; noise this
    # size fills LZW's 4096-entry table twice over, so the restarts decode too
    many = np.random.default_rng(7).integers(0, 256, size=(120, 100, 3), dtype=np.uint8)
    with Image.open(io.BytesIO(gif_bytes(many))) as image:
        decoded = np.asarray(image.convert("RGB")).astype(int)
    assert decoded.shape == (120, 100, 3) and np.abs(decoded - many).max() <= 26


async def test_teleop_keys_move_rotate_and_cancel(capsys):
    async with Runtime() as rt:
        rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        teleop = rt.spawn(TeleopTurtle, io.BytesIO(b"\x1b[A"))  # the up arrow's escape sequence
        await anyio.sleep(1.5)
        x, y, theta, speed, _ = watcher.poses["turtle1"][-1]
        assert (y, theta, speed) == (CENTRE, 0.0, 0.0)  # it stopped a second after the key
        # scale_linear: 2 m/s, for the frames at 32 ms .. 1 s (the one at 16 ms only starts the count).
        assert x == pytest.approx(CENTRE + 61 * 0.016 * 2.0, abs=1e-5)
        teleop.on_key(b"r")  # rotate to π/2 ...
        await anyio.sleep(0.5)
        assert teleop.goal is not None and teleop.goal.accepted
        teleop.on_key(b"f")  # ... and cancel it half way
        await anyio.sleep(0.5)
        heading = watcher.poses["turtle1"][-1][2]
        assert 0.3 < heading < 1.2
        assert (await teleop.goal.get_result()).status == 5  # CANCELED
        assert teleop.on_key(b"q") is False
    assert "Use G|B|V|C|D|E|R|T keys to rotate to absolute orientations. 'F' to cancel a rotation." in (
        capsys.readouterr().out
    )


async def test_a_bag_of_cmd_vel_replays_the_same_path(tmp_path):
    pytest.importorskip("mcap")
    from actors.recording.player import play
    from actors.recording.reader import Bag
    from actors.recording.recorder import Recorder

    rng = random.Random(7)
    drive = [(t * 8_000_000, rng.uniform(-3, 3), rng.uniform(-3, 3)) for t in sorted(rng.sample(range(1, 400, 2), 12))]
    async with Runtime(attach=[Recorder(tmp_path / "drive", topics=["/turtle1/cmd_vel"])]) as rt:
        rt.spawn(Turtlesim)
        recorded = rt.spawn(Watcher, ["turtle1"], {"turtle1": drive})
        await anyio.sleep(4.0)
    bag = next((tmp_path / "drive").glob("*.mcap"))
    async with Runtime() as rt:
        rt.spawn(Turtlesim)
        replayed = rt.spawn(Watcher, ["turtle1"])
        await anyio.sleep(drive[0][0] / 1e9)  # the bag starts with the first command, when it was sent
        assert await play(rt, Bag(bag)) == len(drive)
        await anyio.sleep(4.0 - drive[-1][0] / 1e9)
    first, second = recorded.poses["turtle1"][-1], replayed.poses["turtle1"][-1]
    assert first[:3] != (CENTRE, CENTRE, 0.0)  # it went somewhere
    assert second == pytest.approx(first, abs=1e-6)


async def test_the_live_view_scene_shows_the_floor_the_trails_and_each_turtle():
    fm = pytest.importorskip("foxglove.messages")
    from world.turtlesim_scene import turtlesim_scene

    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim, params={"background_g": 0})
        rt.spawn(Watcher, ["turtle1"], {"turtle1": [(8_000_000, 1.0, 0.0)]})
        await anyio.sleep(0.5)
        update = turtlesim_scene(sim, rt.clock.now_ns())
    assert isinstance(update, fm.SceneUpdate)
    decoded = _read_scene(fm, update)
    assert [e.id for e in decoded.entities] == ["turtlesim/floor", "turtlesim/trails", "turtlesim/turtle1"]
    floor, trails, turtle = decoded.entities
    assert (floor.cubes[0].color.r, floor.cubes[0].color.g) == (pytest.approx(69 / 255), 0.0)
    (line,) = trails.lines
    assert len(line.points) == 2 * len(sim.canvas.segments) > 0
    assert line.points[-2].x == pytest.approx(sim.turtles["turtle1"].x)  # drawn from where it is now
    assert turtle.arrows[0].pose.position.x == pytest.approx(sim.turtles["turtle1"].x)


def _read_scene(fm, update):
    from conftest import protobuf_class

    schema = fm.SceneUpdate.get_schema()
    return protobuf_class(schema.name, schema.data).FromString(update.encode())


async def test_nothing_a_peer_sends_crashes_turtlesim(caplog):
    from actors.errors import ServiceError

    async with Runtime() as rt:
        sim = rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        caller = rt.spawn(Caller)
        wild = Twist()
        wild.linear.x, wild.angular.z = math.nan, math.inf
        watcher.pubs["turtle1"].publish(wild)  # refused: dropped and counted, the turtle keeps still
        with pytest.raises(ServiceError, match="not finite"):
            await call(caller, TeleportAbsolute, "/turtle1/teleport_absolute", x=math.inf, y=math.nan, theta=0.0)
        for _ in range(2):  # far beyond the window, twice in one frame: clamped by the walls, not drawn
            await call(caller, TeleportRelative, "/turtle1/teleport_relative", linear=3e38, angular=0.0)
        assert (await call(caller, Spawn, "/spawn", x=math.nan, y=1.0, name="")).name == ""
        await anyio.sleep(0.1)
        assert rt.node("turtlesim") is sim
        x, y = watcher.poses["turtle1"][-1][:2]
        assert (x, y) == (as_f32(WORLD_SIZE), CENTRE)


async def test_mimic_makes_the_second_turtlesim_copy_the_first():
    async with Runtime() as rt:
        rt.spawn(Turtlesim, namespace="turtlesim1", name="sim")
        rt.spawn(Turtlesim, namespace="turtlesim2", name="sim")
        rt.spawn(
            Mimic,
            remap={"input/pose": "/turtlesim1/turtle1/pose", "output/cmd_vel": "/turtlesim2/turtle1/cmd_vel"},
        )
        watcher = rt.spawn(Watcher, ["turtlesim1/turtle1", "turtlesim2/turtle1"])
        twist = Twist()
        twist.linear.x, twist.angular.z = 2.0, 1.8
        watcher.pubs["turtlesim1/turtle1"].publish(twist)
        await anyio.sleep(2.0)
    leader, follower = watcher.poses["turtlesim1/turtle1"][-1], watcher.poses["turtlesim2/turtle1"][-1]
    assert leader[:3] != (CENTRE, CENTRE, 0.0)
    assert math.dist(leader[:2], follower[:2]) < 0.1  # the same arc, a frame or two behind


async def test_draw_square_resets_then_drives_a_two_metre_square(caplog):
    caplog.set_level(logging.INFO)
    async with Runtime() as rt:
        rt.spawn(Turtlesim)
        watcher = rt.spawn(Watcher, ["turtle1"])
        off_centre = Twist()
        off_centre.angular.z = 1.0
        watcher.pubs["turtle1"].publish(off_centre)  # the reset puts it back before the square starts
        await anyio.sleep(0.5)
        rt.spawn(DrawSquare)
        await anyio.sleep(26.0)  # four sides of 2 s and four quarter turns of ~3.9 s, with stops between
    corners = [(CENTRE + 2, CENTRE), (CENTRE + 2, CENTRE + 2), (CENTRE, CENTRE + 2), (CENTRE, CENTRE)]
    path = [p[:2] for p in watcher.poses["turtle1"]]
    seen = 0
    for corner in corners:  # round the square anticlockwise, in order, back where it began
        seen = min(range(seen, len(path)), key=lambda i, c=corner: math.dist(path[i], c))
        assert math.dist(path[seen], corner) < 0.15, (corner, path[seen])
    goals = [r.getMessage() for r in caplog.records if r.getMessage().startswith("New goal")]
    assert goals[0] == f"New goal [{CENTRE + 2:f} {CENTRE:f}, 0.000000]"
    assert goals[1].endswith(", 1.570796]")  # a quarter turn by the program's PI, 3.141592
