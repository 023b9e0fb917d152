"""ros2's forms on the command line: counts, verbose lists, parameter filters, aliases and usage errors.

Each expected output is what ros2cli prints for the same graph (its verbs' sources are the
specification; docs/ros2cli.md lists every verb and flag and where it is tested).
"""

from __future__ import annotations

import contextlib
from collections.abc import AsyncIterator

import anyio
import pytest

from actors import Node, Runtime
from actors.cli import main
from actors.ops.control import ControlEndpoint
from interfaces.rcl_interfaces.srv import GetParameters
from interfaces.std_msgs.msg import String


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker")
        self.pub = self.create_publisher(String, "/chatter", 10)
        self.declare_parameter("speed", 0.5)
        self.declare_parameter("pid.kp", 1.0)
        self.declare_parameter("pid.ki", 2)
        self.declare_parameter("mode", "idle")


class Listener(Node):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.create_subscription(String, "/chatter", lambda msg: None, 10)
        self.create_client(GetParameters, "/talker/get_parameters")


@pytest.fixture(autouse=True)
def endpoints(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))


@contextlib.asynccontextmanager
async def chatter() -> AsyncIterator[Runtime]:
    async with Runtime(name="cli_forms", attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)
        rt.spawn(Listener, "one")
        rt.spawn(Listener, "two")
        yield rt


async def actors(capsys, *argv: str) -> tuple[int, str, str]:
    """``actors ARGS`` in a thread (the command line blocks), beside the graph on this loop."""
    code = await anyio.to_thread.run_sync(main, list(argv))
    out, err = capsys.readouterr()
    return code, out, err


async def test_counts_print_one_number(capsys):
    async with chatter():
        for group, flag in (("topic", "-c"), ("node", "--count-nodes"), ("service", "--count-services")):
            _, listed, _ = await actors(capsys, group, "list")
            assert await actors(capsys, group, "list", flag) == (0, f"{len(listed.splitlines())}\n", "")
    assert listed.count("\n") > 3  # the nodes' parameter services: a count worth checking


async def test_topic_list_verbose_counts_publishers_and_subscribers(capsys):
    async with chatter():
        code, out, _ = await actors(capsys, "topic", "list", "-v")
    assert code == 0
    assert out == (
        "Published topics:\n"
        " * /chatter [std_msgs/msg/String] 1 publisher\n"
        " * /parameter_events [rcl_interfaces/msg/ParameterEvent] 1 publisher\n"
        " * /rosout [rcl_interfaces/msg/Log] 1 publisher\n"
        "\n"
        "Subscribed topics:\n"
        " * /chatter [std_msgs/msg/String] 2 subscribers\n"
        "\n"
    )


async def test_param_list_of_one_node_has_no_header(capsys):
    async with chatter():
        _, one, _ = await actors(capsys, "param", "list", "/talker")
        _, every, _ = await actors(capsys, "param", "list")
    assert one == "  mode\n  pid.ki\n  pid.kp\n  speed\n  use_sim_time\n"
    assert "/talker:\n" + one in every and every.startswith("/one:\n  use_sim_time\n")


async def test_param_list_filters_prefixes_and_types(capsys):
    async with chatter():
        _, prefixed, _ = await actors(capsys, "param", "list", "/talker", "--param-prefixes", "pid")
        _, filtered, _ = await actors(capsys, "param", "list", "/talker", "--filter", "s")
        _, typed, _ = await actors(capsys, "param", "list", "/talker", "--param-type", "--filter", "pid|mode")
        bad = await actors(capsys, "param", "list", "/talker", "--filter", "(")
    assert prefixed == "  pid.ki\n  pid.kp\n"
    assert filtered == "  speed\n"  # matched from the name's start, as re.match
    assert typed == "  mode (type: string)\n  pid.ki (type: integer)\n  pid.kp (type: double)\n"
    assert bad[0] == 2 and bad[2].startswith("actors: --filter '(' is not a regular expression")


async def test_param_get_hide_type_prints_the_value_alone(capsys):
    async with chatter():
        shown = await actors(capsys, "param", "get", "/talker", "speed")
        hidden = await actors(capsys, "param", "get", "/talker", "speed", "--hide-type")
    assert shown == (0, "Double value is: 0.5\n", "")
    assert hidden == (0, "0.5\n", "")


async def test_service_info_counts_clients_and_servers(capsys):
    async with chatter():
        asked = await actors(capsys, "service", "info", "/talker/get_parameters")
        unasked = await actors(capsys, "service", "info", "talker/set_parameters")
        unknown = await actors(capsys, "service", "info", "/talker/get_parameter")
    assert asked == (0, "Type: rcl_interfaces/srv/GetParameters\nClients count: 2\nServices count: 1\n", "")
    assert unasked == (0, "Type: rcl_interfaces/srv/SetParameters\nClients count: 0\nServices count: 1\n", "")
    assert unknown[0] == 2 and "did you mean '/talker/get_parameters'?" in unknown[2]


async def test_wtf_is_doctor(capsys):
    async with chatter():
        doctor = await actors(capsys, "doctor")
        wtf = await actors(capsys, "wtf")
    assert wtf == doctor and doctor[0] == 0


def test_daemon_verbs_say_there_is_none_and_succeed(capsys):
    for verb in ("status", "stop"):
        assert main(["daemon", verb]) == 0
        assert capsys.readouterr().out == "The daemon is not running\n"
    assert main(["daemon", "start"]) == 0
    assert capsys.readouterr().out == "actors needs no daemon: each command asks the running graph directly\n"


@pytest.mark.parametrize(
    "argv", [["topic", "list", "--bogus"], ["param", "get", "/talker", "speed", "--bogus"], ["doctor", "--bogus"]]
)
def test_an_unknown_flag_prints_the_verbs_usage(capsys, argv):
    with pytest.raises(SystemExit) as exited:
        main(argv)
    err = capsys.readouterr().err
    verb = " ".join(a for a in argv[:2] if not a.startswith(("-", "/")))
    assert exited.value.code == 2
    assert err.startswith(f"usage: actors {verb} ")
    assert err.endswith(f"actors {verb}: error: unrecognized arguments: --bogus\n")


@pytest.mark.parametrize(
    ("argv", "error"),
    [
        (("topic", "info", "/chater"), "unknown topic /chater (did you mean '/chatter'?)"),
        (("topic", "echo", "/chater", "--once"), "unknown topic /chater (did you mean '/chatter'?)"),
        (("node", "info", "/talkr"), "unknown node /talkr (did you mean '/talker'?)"),
        (("param", "get", "/talkr", "speed"), "unknown node /talkr (did you mean '/talker'?)"),
        (
            ("service", "call", "/talker/list_parameter", "rcl_interfaces/srv/ListParameters"),
            "unknown service /talker/list_parameter (did you mean '/talker/list_parameters'?)",
        ),
        (
            ("topic", "pub", "/chatter", "std_msgs/msg/Strin", "data: hi"),
            "unknown interface type 'std_msgs/msg/Strin' (did you mean 'std_msgs/msg/String'?)",
        ),
        (
            ("topic", "pub", "/chatter", "std_msgs/Strng", "data: hi"),
            "unknown interface type 'std_msgs/Strng' (did you mean 'std_msgs/String'?)",
        ),
        (
            ("topic", "pub", "/chatter", "std_msg/msg/String", "data: hi"),
            "unknown interface type 'std_msg/msg/String' (did you mean 'std_msgs/msg/String'?)",
        ),
        (("topic", "pub", "/chatter", "nope_msgs/msg/Nope", "data: hi"), "unknown interface type 'nope_msgs/msg/Nope'"),
    ],
)
async def test_typos_in_names_and_types_get_a_did_you_mean(capsys, argv, error):
    async with chatter():
        code, _, err = await actors(capsys, *argv)
    assert (code, err) == (2, f"actors: {error}\n")
