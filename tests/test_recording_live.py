"""The live view: a WebSocket client speaking the Foxglove protocol sees topics, time and services of a graph."""

from __future__ import annotations

import base64
import contextlib
import json
import math
import shutil
import signal
import struct
import subprocess
import sys
from typing import Any

import anyio
import pytest
from conftest import ROOT, protobuf_class, python_env

from actors import Node, Runtime, codec
from actors.recording.live import FoxgloveView, SceneHost
from interfaces.nav_msgs.msg import Odometry
from interfaces.std_srvs.srv import SetBool
from interfaces.tf2_msgs.msg import TFMessage

pytest.importorskip("foxglove")
websockets = pytest.importorskip("websockets")

# The subprotocol names the WebSocket protocol's versions go by (the SDK accepts its own).
SUBPROTOCOLS = ["foxglove.sdk.v1", "foxglove.websocket.v1"]
MESSAGE_DATA, TIME, SERVICE_CALL_REQUEST, SERVICE_CALL_RESPONSE = 1, 2, 2, 3


class FoxgloveClient:
    """The client side of Foxglove's WebSocket protocol, as the app speaks it: JSON ops and binary frames."""

    def __init__(self, ws: Any) -> None:
        self.ws = ws
        self.channels: dict[str, dict[str, Any]] = {}  # topic -> advertised channel
        self.services: dict[str, dict[str, Any]] = {}  # name -> advertised service
        self.times: list[int] = []
        self._subscribing: dict[int, int] = {}  # channel id -> subscription id
        self._refused: list[int] = []  # channel ids the server did not know yet

    async def next_binary(self, opcode: int) -> bytes:
        """The next binary frame with ``opcode`` (JSON ops on the way are noted)."""
        while True:
            frame = await self.ws.recv()
            if isinstance(frame, str):
                self._note(json.loads(frame))
                await self._resubscribe()
            elif frame[0] == TIME:
                self.times.append(struct.unpack_from("<Q", frame, 1)[0])
                if opcode == TIME:
                    return frame
            elif frame[0] == opcode:
                return frame

    async def wait_for(self, kind: str, name: str) -> dict[str, Any]:
        """The channel (``kind`` "channels") or service ("services") advertised as ``name``."""
        while name not in getattr(self, kind):
            frame = await self.ws.recv()
            if isinstance(frame, str):
                self._note(json.loads(frame))
        return getattr(self, kind)[name]

    def _note(self, op: dict[str, Any]) -> None:
        if op["op"] == "advertise":
            self.channels.update({c["topic"]: c for c in op["channels"]})
        elif op["op"] == "advertiseServices":
            self.services.update({s["name"]: s for s in op["services"]})
        elif op["op"] == "status" and op["message"].startswith("Unknown channel ID: "):
            # foxglove-sdk sends an advertisement a moment before it knows the channel itself:
            # a client that subscribes at once may hear this, and subscribes again.
            self._refused.append(int(op["message"].rsplit(" ", 1)[1]))

    async def _resubscribe(self) -> None:
        while self._refused:
            channel = self._refused.pop()
            await self._send_subscribe(channel, self._subscribing[channel])

    async def subscribe(self, topic: str, subscription: int) -> None:
        channel = await self.wait_for("channels", topic)
        self._subscribing[channel["id"]] = subscription
        await self._send_subscribe(channel["id"], subscription)

    async def _send_subscribe(self, channel: int, subscription: int) -> None:
        await self.ws.send(
            json.dumps({"op": "subscribe", "subscriptions": [{"id": subscription, "channelId": channel}]})
        )

    async def message(self, subscription: int) -> tuple[int, bytes]:
        """The next message on ``subscription``: its log time and payload."""
        while True:
            frame = await self.next_binary(MESSAGE_DATA)
            sub, log_time = struct.unpack_from("<IQ", frame, 1)
            if sub == subscription:
                return log_time, frame[13:]


def _open(port: int, subprotocols: list[str] = SUBPROTOCOLS) -> Any:
    return websockets.connect(f"ws://127.0.0.1:{port}", subprotocols=subprotocols, max_size=None)


@contextlib.contextmanager
def serving_turtlebot(clock: str) -> Any:
    """The acceptance command (port 0: any free one) in a process; yields it and its port, stops it with Ctrl-C.

    Virtual time runs as fast as it can, until the end of a duration it will not reach here.
    """
    until = ["--duration", "1e6"] if clock == "virtual" else []
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graphs/turtlebot.toml", "--clock", clock, *until, "--foxglove", "0"],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert proc.stdout is not None
        for line in proc.stdout:  # the log, on stdout as the graph's console is
            if "foxglove: serving the graph on ws://127.0.0.1:" in line:
                yield proc, int(line.rsplit(":", 1)[1])
                break
        else:
            pytest.fail(f"the graph never said where it serves (exit {proc.wait()})")
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=30)  # the rest of the log: the graph never waits on a full pipe
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()


@pytest.mark.parametrize("clock", ["wall", "virtual"])
@pytest.mark.slow
def test_foxglove_client_receives_odom_from_the_running_turtlebot_graph(clock):
    with serving_turtlebot(clock) as (proc, port):

        async def watch() -> list[tuple[int, Odometry]]:
            with anyio.fail_after(60):
                return await _watch()

        async def _watch() -> list[tuple[int, Odometry]]:
            async with _open(port) as ws:
                client = FoxgloveClient(ws)
                odom = await client.wait_for("channels", "/odom")
                assert (odom["encoding"], odom["schemaName"], odom["schemaEncoding"]) == (
                    "cdr",
                    "nav_msgs/msg/Odometry",
                    "ros2msg",
                )
                assert odom["schema"] == codec.definition_text(Odometry)
                await client.subscribe("/odom", 7)
                received = []
                for _ in range(5):
                    log_time, payload = await client.message(7)
                    received.append((log_time, codec.decode_cdr(payload, Odometry)))
                return received

        received = anyio.run(watch)
    assert [m.header.frame_id for _, m in received] == ["odom"] * 5
    times = [t for t, _ in received]
    assert times == sorted(times) and len(set(times)) == 5
    # Log times are the runtime clock's when published: the robot stamps its odometry with it.
    stamps = [m.header.stamp.sec * 10**9 + m.header.stamp.nanosec for _, m in received]
    if clock == "virtual":
        assert times == stamps  # virtual time stands still while a callback runs
    else:
        assert all(0 <= t - s < 10**9 for t, s in zip(times, stamps))
    assert proc.returncode == 0


@pytest.mark.slow
def test_foxglove_client_sees_the_turtlebot_world_as_a_3d_scene_tied_to_tf():
    pytest.importorskip("google.protobuf", reason="the scene is decoded with its protobuf schema (test extra)")
    with serving_turtlebot("virtual") as (proc, port):

        async def watch() -> tuple[dict[str, Any], TFMessage, list[tuple[int, Any]]]:
            with anyio.fail_after(60):
                async with _open(port) as ws:
                    client = FoxgloveClient(ws)
                    scene = await client.wait_for("channels", "/scene")
                    await client.wait_for("channels", "/tf")
                    # Published once, long ago in virtual time: a new viewer gets it as a late ROS subscriber would.
                    await client.subscribe("/tf_static", 4)
                    static = codec.decode_cdr((await client.message(4))[1], TFMessage)
                    # A protobuf channel advertises its schema as a base64 FileDescriptorSet.
                    SceneUpdate = protobuf_class(scene["schemaName"], base64.b64decode(scene["schema"]))
                    await client.subscribe("/scene", 3)
                    updates = []
                    while len(updates) < 3 or not any(e.id == "/turtlebot/scan" for e in updates[-1][1].entities):
                        log_time, payload = await client.message(3)
                        updates.append((log_time, SceneUpdate.FromString(payload)))
                    return client.channels, static, updates

        channels, static, updates = anyio.run(watch)
    assert proc.returncode == 0
    scene = channels["/scene"]
    assert (scene["encoding"], scene["schemaName"], scene["schemaEncoding"]) == (
        "protobuf",
        "foxglove.SceneUpdate",
        "protobuf",
    )
    assert channels["/tf"]["schemaName"] == channels["/tf_static"]["schemaName"] == "tf2_msgs/msg/TFMessage"
    # The scene's frame is the root of the robot's tree: world -> odom -> base_footprint (on /tf).
    assert ("world", "odom") in {(t.header.frame_id, t.child_frame_id) for t in static.transforms}
    log_time, update = updates[-1]
    entities = {e.id: e for e in update.entities}
    assert set(entities) == {"walls", "obstacles", "/turtlebot", "/turtlebot/scan"}
    for e in update.entities:  # all in the root of the robot's tf tree, stamped with the graph's clock
        assert e.frame_id == "world"
        assert e.timestamp.seconds * 10**9 + e.timestamp.nanos == log_time
    # The "signs" world: four walls whose inner faces are 3 m from the origin, two boxes, one stop sign.
    walls = entities["walls"].cubes
    assert len(walls) == 4
    assert sorted(round(max(abs(c.pose.position.x), abs(c.pose.position.y)), 3) for c in walls) == [3.05] * 4
    assert all(sorted([c.size.x, c.size.y]) == pytest.approx([0.1, 6.2]) for c in walls)
    obstacles = entities["obstacles"]
    assert [(c.pose.position.x, c.pose.position.y) for c in obstacles.cubes] == [(1.61, 0.0), (-1.0, -0.5)]
    assert [(c.pose.position.x, c.pose.position.y) for c in obstacles.cylinders] == [(0.15, -2.0)]
    # The robot drives a circle of 1 m radius about (0, 1), heading along it.
    (body,) = entities["/turtlebot"].cylinders
    x, y = body.pose.position.x, body.pose.position.y
    assert math.hypot(x, y - 1.0) == pytest.approx(1.0, abs=0.05) and body.size.x == pytest.approx(0.21)
    # The scan: points where the beams ended, none beyond the walls, most of them on the walls' inner faces.
    points = [(s.pose.position.x, s.pose.position.y) for s in entities["/turtlebot/scan"].spheres]
    assert 100 <= len(points) <= 360
    assert all(max(abs(px), abs(py)) <= 3.0 + 1e-6 for px, py in points)
    on_walls = [p for p in points if max(abs(p[0]), abs(p[1])) >= 3.0 - 1e-6]
    assert len(on_walls) >= len(points) / 2
    assert all(math.dist((x, y), p) <= 3.5 + 0.3 for p in points)  # range_max, from where the scan was taken


@pytest.mark.parametrize("subprotocol", ["foxglove.websocket.v1", "foxglove.sdk.v1"])
@pytest.mark.slow
def test_clients_of_either_subprotocol_name_see_odom_and_the_scene(subprotocol):
    # foxglove.websocket.v1 is what clients built on the published ws-protocol libraries ask for
    # (and Lichtblick before it learnt the SDK's name); the SDK's server alone refuses it.
    pytest.importorskip("google.protobuf", reason="the scene is decoded with its protobuf schema (test extra)")
    with serving_turtlebot("virtual") as (proc, port):

        async def watch() -> tuple[str, Odometry, Any]:
            with anyio.fail_after(60):
                async with _open(port, [subprotocol]) as ws:
                    client = FoxgloveClient(ws)
                    scene = await client.wait_for("channels", "/scene")
                    SceneUpdate = protobuf_class(scene["schemaName"], base64.b64decode(scene["schema"]))
                    await client.subscribe("/odom", 1)
                    odom = codec.decode_cdr((await client.message(1))[1], Odometry)
                    await client.subscribe("/scene", 2)
                    update = SceneUpdate.FromString((await client.message(2))[1])
                    return ws.subprotocol, odom, update

        chosen, odom, update = anyio.run(watch)
    assert chosen == subprotocol  # answered under the name it asked for
    assert odom.header.frame_id == "odom" and odom.child_frame_id == "base_footprint"
    assert {"walls", "/turtlebot"} <= {e.id for e in update.entities}
    assert proc.returncode == 0


def _npm_client() -> list[str]:
    """The command that runs tests/ws_protocol_client.js under node; skips where node or its packages are missing."""
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is not installed")
    found = subprocess.run(
        [node, "-e", "require.resolve('@foxglove/ws-protocol'); require.resolve('ws')"],
        cwd=ROOT / "tests",
        capture_output=True,
    )
    if found.returncode != 0:
        pytest.skip("npm install @foxglove/ws-protocol ws (or set NODE_PATH) to run Foxglove's own client")
    return [node, str(ROOT / "tests" / "ws_protocol_client.js")]


@pytest.mark.slow
def test_foxglove_ws_protocol_npm_client_decodes_odom_and_the_scene():
    pytest.importorskip("google.protobuf", reason="the scene is decoded with its protobuf schema (test extra)")
    command = _npm_client()
    with serving_turtlebot("virtual") as (proc, port):
        done = subprocess.run(
            [*command, f"ws://127.0.0.1:{port}", "/odom", "/scene"], capture_output=True, text=True, timeout=60
        )
    assert done.returncode == 0, done.stderr
    seen = json.loads(done.stdout)
    assert seen["subprotocol"] == "foxglove.websocket.v1"  # what the published client asks for
    odom, scene = seen["topics"]["/odom"], seen["topics"]["/scene"]
    assert odom["channel"]["schemaName"] == "nav_msgs/msg/Odometry"
    assert codec.decode_cdr(base64.b64decode(odom["payload"]), Odometry).header.frame_id == "odom"
    SceneUpdate = protobuf_class(scene["channel"]["schemaName"], base64.b64decode(scene["channel"]["schema"]))
    update = SceneUpdate.FromString(base64.b64decode(scene["payload"]))
    assert {"walls", "/turtlebot"} <= {e.id for e in update.entities}
    assert proc.returncode == 0


@pytest.mark.slow
def test_a_client_of_neither_name_is_still_refused():
    with serving_turtlebot("virtual") as (_, port):

        async def knock() -> None:
            with anyio.fail_after(30):
                async with _open(port, ["foxglove.websocket.v2"]):
                    pass

        with pytest.raises(websockets.InvalidStatus, match="HTTP 400"):
            anyio.run(knock)


class Switch(Node):
    """Serves ``/switch`` (std_srvs/SetBool) and publishes odometry stamped with its clock."""

    def __init__(self) -> None:
        super().__init__("switch")
        self.on = False
        self.create_service(SetBool, "switch", self.set)
        self.pub = self.create_publisher(Odometry, "odom", 10)
        self.published = 0
        self.create_timer(0.01, self.tick)

    def set(self, request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
        self.on = request.data
        response.success = True
        response.message = f"switched {'on' if request.data else 'off'}"
        return response

    def tick(self) -> None:
        msg = Odometry()
        msg.header.stamp = self.get_clock().now().to_msg()
        self.pub.publish(msg)
        self.published += 1


async def test_services_are_callable_and_times_are_the_runtime_clock():
    view = FoxgloveView(0)
    async with Runtime(name="live_view", attach=[view]) as rt:
        switch = rt.spawn(Switch)
        async with _open(view.port) as ws:
            client = FoxgloveClient(ws)
            with anyio.fail_after(20):
                service = await client.wait_for("services", "/switch")
                assert service["type"] == "std_srvs/srv/SetBool"
                request = codec.encode_cdr(SetBool.Request(data=True))
                await ws.send(struct.pack("<BIII", SERVICE_CALL_REQUEST, service["id"], 42, 3) + b"cdr" + request)
                frame = await client.next_binary(SERVICE_CALL_RESPONSE)
                service_id, call_id, length = struct.unpack_from("<III", frame, 1)
                assert (service_id, call_id, frame[13 : 13 + length]) == (service["id"], 42, b"cdr")
                response = codec.decode_cdr(frame[13 + length :], SetBool.Response)
                assert (response.success, response.message, switch.on) == (True, "switched on", True)

                await client.subscribe("/odom", 1)
                log_time, payload = await client.message(1)
                stamp = codec.decode_cdr(payload, Odometry).header.stamp
                await client.next_binary(TIME)
            now = rt.clock.now_ns()
    # A message's log time is the runtime clock when it was published (its stamp here);
    # the time broadcast is the runtime clock too.
    assert stamp.sec * 10**9 + stamp.nanosec <= log_time <= now
    assert 0 < client.times[-1] <= now


async def test_nothing_is_encoded_while_no_client_subscribes(monkeypatch):
    encoded = []
    encode = codec.encode_cdr
    monkeypatch.setattr(codec, "encode_cdr", lambda msg: encoded.append(msg) or encode(msg))
    view = FoxgloveView(0)
    async with Runtime(name="live_unwatched", attach=[view]) as rt:
        switch = rt.spawn(Switch)
        async with _open(view.port) as ws:
            client = FoxgloveClient(ws)
            with anyio.fail_after(20):
                await client.wait_for("channels", "/odom")  # advertised, never subscribed
                await client.next_binary(TIME)
                published = switch.published
                await client.next_binary(TIME)  # a tenth of a second later
    assert switch.published > published > 0 and encoded == []


@pytest.mark.slow
def test_the_port_is_checked_and_a_port_in_use_is_one_line(run_module):
    bad = run_module("actors.run", "graphs/turtlebot.toml", "--foxglove", "http")
    assert bad.returncode == 2 and "not a port number" in bad.stderr
    view = FoxgloveView(0)
    view.start()
    try:
        taken = run_module("actors.run", "graphs/turtlebot.toml", "--duration", "1", "--foxglove", str(view.port))
    finally:
        view._server.stop()
    assert taken.returncode == 2
    assert taken.stderr.startswith(f"error: --foxglove: cannot serve on 127.0.0.1:{view.port}: ")
    assert "Traceback" not in taken.stderr


@pytest.mark.slow
async def test_a_scene_is_drawn_only_while_watched_and_a_failing_one_is_dropped(caplog):
    import foxglove.messages as fm

    drawn: list[int] = []

    def draw(now_ns: int) -> Any:
        drawn.append(now_ns)
        return fm.SceneUpdate(entities=[fm.SceneEntity(id="thing", frame_id="world")])

    def broken(now_ns: int) -> Any:
        raise ValueError("no paint")

    view = FoxgloveView(0)
    assert isinstance(view, SceneHost)
    async with Runtime(name="live_scene", attach=[view]) as rt:
        rt.spawn(Switch)
        view.add_scene("/picture", draw)
        view.add_scene("/broken", broken)
        async with _open(view.port) as ws:
            client = FoxgloveClient(ws)
            with anyio.fail_after(20):
                await client.wait_for("channels", "/picture")
                await client.next_binary(TIME)
                await client.next_binary(TIME)
                assert drawn == []  # advertised, never subscribed: never drawn
                await client.subscribe("/broken", 2)
                await client.subscribe("/picture", 1)
                log_time, payload = await client.message(1)
                while "/broken" in view._scenes:  # dropped at the first broadcast after its subscription lands
                    await client.next_binary(TIME)
        view.remove_scene("/picture")
        view.remove_scene("/picture")  # twice: nothing
    assert drawn[0] == log_time
    assert b"thing" in payload and b"world" in payload
    assert [r.getMessage() for r in caplog.records if "/broken" in r.getMessage()] == [
        "foxglove: scene /broken left out: drawing it raised ValueError('no paint')"
    ]
