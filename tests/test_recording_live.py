"""The live view: a WebSocket client speaking the Foxglove protocol sees topics, time and services of a graph."""

from __future__ import annotations

import json
import signal
import struct
import subprocess
import sys
from typing import Any

import anyio
import pytest

from actors import Node, Runtime, codec
from actors.recording.live import FoxgloveView
from conftest import ROOT, python_env
from interfaces.nav_msgs.msg import Odometry
from interfaces.std_srvs.srv import SetBool

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
        await self.ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": subscription, "channelId": channel}]}))

    async def message(self, subscription: int) -> tuple[int, bytes]:
        """The next message on ``subscription``: its log time and payload."""
        while True:
            frame = await self.next_binary(MESSAGE_DATA)
            sub, log_time = struct.unpack_from("<IQ", frame, 1)
            if sub == subscription:
                return log_time, frame[13:]


def _open(port: int) -> Any:
    return websockets.connect(f"ws://127.0.0.1:{port}", subprotocols=SUBPROTOCOLS, max_size=None)


@pytest.mark.parametrize("clock", ["wall", "virtual"])
def test_foxglove_client_receives_odom_from_the_running_turtlebot_graph(clock):
    # The acceptance command (port 0: any free one), on either clock; virtual time runs
    # as fast as it can, until the end of a duration it will not reach here.
    until = ["--duration", "1e6"] if clock == "virtual" else []
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", "graphs/turtlebot.toml", "--clock", clock, *until, "--foxglove", "0"],
        cwd=ROOT, env=python_env(), stdout=subprocess.PIPE, text=True,
    )
    try:
        assert proc.stdout is not None
        for line in proc.stdout:  # the log, on stdout as the graph's console is
            if "foxglove: serving the graph on ws://127.0.0.1:" in line:
                port = int(line.rsplit(":", 1)[1])
                break
        else:
            pytest.fail(f"the graph never said where it serves (exit {proc.wait()})")

        async def watch() -> list[tuple[int, Odometry]]:
            with anyio.fail_after(60):
                return await _watch()

        async def _watch() -> list[tuple[int, Odometry]]:
            async with _open(port) as ws:
                client = FoxgloveClient(ws)
                odom = await client.wait_for("channels", "/odom")
                assert (odom["encoding"], odom["schemaName"], odom["schemaEncoding"]) == (
                    "cdr", "nav_msgs/msg/Odometry", "ros2msg"
                )
                assert odom["schema"] == codec.definition_text(Odometry)
                await client.subscribe("/odom", 7)
                received = []
                for _ in range(5):
                    log_time, payload = await client.message(7)
                    received.append((log_time, codec.decode_cdr(payload, Odometry)))
                return received

        received = anyio.run(watch)
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=30)  # the rest of the log: the graph never waits on a full pipe
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
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
