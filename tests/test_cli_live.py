"""``python -m actors`` against ``python -m actors.run graph.toml`` (wall clock), as subprocesses.

One graph serves the whole module; it is named uniquely (the graph name is the
file's stem) and every command passes ``--graph``, so other graphs running on
the machine do not interfere.  Every subprocess is bounded in time.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml
from conftest import ROOT, python_env

from actors.cli import main


class GraphProcess:
    """``python -m actors.run FILE`` in the background, its output collected line by line.

    ``runner``: the command before FILE (an rclpy script's ``actors run``); the
    graph is named after FILE's stem either way.
    """

    def __init__(self, path: Path, runner: tuple[str, ...] = ("-m", "actors.run")) -> None:
        self.name = path.stem
        self.lines: list[str] = []
        self._changed = threading.Condition()
        self.proc = subprocess.Popen(
            [sys.executable, *runner, str(path)],
            cwd=ROOT,
            env=python_env(),
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with self._changed:
                self.lines.append(line)
                self._changed.notify_all()
        with self._changed:
            self.lines.append("<exited>")
            self._changed.notify_all()

    def wait_for(self, text: str, *, after: int = 0, timeout: float = 10) -> str:
        """The first line from index ``after`` on containing ``text``; fails after ``timeout`` s."""

        def found() -> str | None:
            return next((line for line in self.lines[after:] if text in line or line == "<exited>"), None)

        with self._changed:
            line = self._changed.wait_for(found, timeout)
        assert line and line != "<exited>", f"{text!r} never printed:\n{''.join(self.lines[-20:])}"
        return line

    def stop(self) -> None:
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        finally:
            self.proc.kill()


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> Iterator[GraphProcess]:
    path = tmp_path_factory.mktemp("graph") / f"cli_live_{os.getpid()}.toml"
    shutil.copy(ROOT / "graph.toml", path)
    running = GraphProcess(path)
    try:
        # The add_two_ints server starts 1 s late; once its client has an answer, every node runs.
        running.wait_for("Result of add_two_ints")
        yield running
    finally:
        running.stop()


def actors(graph: GraphProcess, *args: str, timeout: float = 30) -> subprocess.CompletedProcess[str]:
    """Run ``python -m actors ARGS --graph NAME``."""
    return subprocess.run(
        [sys.executable, "-m", "actors", *args, "--graph", graph.name],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def started(graph: GraphProcess, *args: str) -> subprocess.Popen[str]:
    """``python -m actors ARGS --graph NAME`` started in the background, its output piped."""
    return subprocess.Popen(
        [sys.executable, "-m", "actors", *args, "--graph", graph.name],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def ok(graph: GraphProcess, *args: str, timeout: float = 30) -> str:
    """The stdout of a command that must succeed without a word on stderr."""
    result = actors(graph, *args, timeout=timeout)
    assert (result.returncode, result.stderr) == (0, ""), result
    return result.stdout


COURSE_NODES = {
    "/minimal_publisher",
    "/minimal_subscriber",
    "/heartbeat",
    "/minimal_client_async",
    "/minimal_service",
    "/num_publisher",
    "/num_subscriber",
    "/add_three_ints_server",
    "/add_three_ints_client",
    "/minimal_param_node",
}


@pytest.mark.slow
def test_node_list_shows_every_node_and_no_hidden_one(graph):
    names = ok(graph, "node", "list").split()
    assert set(names) >= COURSE_NODES
    assert names == sorted(names) and not [n for n in names if n.rsplit("/", 1)[1].startswith("_")]


@pytest.mark.slow
def test_node_info_prints_ros2s_sections(graph):
    out = ok(graph, "node", "info", "/minimal_publisher")
    assert out.startswith(
        "/minimal_publisher\n  Subscribers:\n\n  Publishers:\n"
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent\n"  # every ROS node's, as ros2 lists them
        "    /rosout: rcl_interfaces/msg/Log\n"
        "    /topic: std_msgs/msg/String\n"
    )
    assert (
        "  Service Servers:\n    /minimal_publisher/describe_parameters: rcl_interfaces/srv/DescribeParameters\n" in out
    )
    assert out.endswith("  Service Clients:\n\n  Action Servers:\n\n  Action Clients:\n\n")


@pytest.mark.slow
def test_topic_list_and_info(graph):
    assert "/topic [std_msgs/msg/String]" in ok(graph, "topic", "list", "-t").splitlines()
    assert "/topic" in ok(graph, "topic", "list").splitlines()
    assert ok(graph, "topic", "info", "/topic") == (
        "Type: std_msgs/msg/String\nPublisher count: 1\nSubscription count: 1\n"
    )
    verbose = ok(graph, "topic", "info", "topic", "-v")
    assert "Node name: minimal_subscriber\nNode namespace: /\n" in verbose
    assert "  Reliability: RELIABLE\n  History (Depth): KEEP_LAST (10)\n" in verbose
    assert "Dropped: 0\n" in verbose


# What real rclpy (Kilted) prints for a talker's publisher on /topic (ros2 topic info -v prints
# TopicEndpointInfo's str), the GID aside; History as rmw_zenoh reports it (Fast DDS says UNKNOWN).
PUBLISHER_INFO = """\
Node name: minimal_publisher
Node namespace: /
Topic type: std_msgs/msg/String
Topic type hash: RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18
Endpoint type: PUBLISHER
GID: <gid>
QoS profile:
  Reliability: RELIABLE
  History (Depth): KEEP_LAST (10)
  Durability: VOLATILE
  Lifespan: Infinite
  Deadline: Infinite
  Liveliness: AUTOMATIC
  Liveliness lease duration: Infinite
"""


@pytest.mark.slow
def test_topic_info_verbose_prints_each_endpoint_as_ros2_does(graph):
    verbose = ok(graph, "topic", "info", "/topic", "-v")
    gids = re.findall(r"^GID: ((?:[0-9a-f]{2}\.){15}[0-9a-f]{2})$", verbose, re.MULTILINE)
    assert len(set(gids)) == 2  # one per endpoint, and not the same
    shape = re.sub(r"^GID: .*$", "GID: <gid>", verbose, flags=re.MULTILINE)
    head = f"Type: std_msgs/msg/String\n\nPublisher count: 1\n\n{PUBLISHER_INFO}\nSubscription count: 1\n\n"
    assert shape.startswith(head), shape
    subscription = shape.removeprefix(head)
    expected = PUBLISHER_INFO.replace("minimal_publisher", "minimal_subscriber").replace("PUBLISHER", "SUBSCRIPTION")
    assert subscription == f"{expected}Queued: 0\nDropped: 0\n\n"  # our two lines after ros2's


@pytest.mark.slow
def test_topic_echo_once_prints_one_yaml_document(graph):
    out = ok(graph, "topic", "echo", "/topic", "--once")
    document, rest = out.split("---\n")
    assert rest == ""
    assert re.fullmatch(r"Hello World: \d+", yaml.safe_load(document)["data"])
    field = ok(graph, "topic", "echo", "/topic", "--once", "--field", "data")
    assert re.fullmatch(r"Hello World: \d+", yaml.safe_load(field.split("---\n")[0]))


@pytest.mark.slow
def test_topic_delay_reports_the_odometrys_header_delay_as_ros2_prints_it(graph):
    out = ok(graph, "topic", "delay", "/odom", "--count", "1")
    report = re.fullmatch(
        r"average delay: (\d+\.\d{3})\n\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: (\d+)\n", out
    )
    assert report and float(report[1]) < 0.5 and int(report[2]) >= 1, out  # stamped as published, in one process
    no_header = actors(graph, "topic", "delay", "/topic", "--count", "1")
    assert no_header.returncode == 2, no_header
    assert no_header.stderr == "actors: /topic carries std_msgs/msg/String, which has no header to take a delay from\n"


@pytest.mark.slow
def test_topic_hz_reports_about_two_hertz(graph):
    out = ok(graph, "topic", "hz", "/topic", "--count", "2")
    rates = [float(r) for r in re.findall(r"^average rate: (\d+\.\d{3})$", out, re.MULTILINE)]
    assert len(rates) == 2 and 1.5 <= rates[-1] <= 2.5, out
    assert re.search(r"^\tmin: 0\.\d{3}s max: 0\.\d{3}s std dev: \d\.\d{5}s window: \d+$", out, re.MULTILINE)


@pytest.mark.slow
def test_topic_type_and_find(graph):
    assert ok(graph, "topic", "type", "/topic") == "std_msgs/msg/String\n"
    found = ok(graph, "topic", "find", "std_msgs/msg/Bool").splitlines()
    assert {"/kill", "/sim/contact"} <= set(found) and "/topic" not in found
    assert ok(graph, "topic", "find", "std_msgs/Bool", "-c") == f"{len(found)}\n"  # short form
    assert ok(graph, "topic", "find", "nope_msgs/msg/Nope") == ""  # as ros2: nothing of it
    assert ok(graph, "service", "find", "example_interfaces/srv/AddTwoInts") == "/add_two_ints\n"
    count = int(ok(graph, "service", "find", "rcl_interfaces/srv/ListParameters", "-c"))
    assert count >= len(COURSE_NODES)  # every node has its parameter services


@pytest.mark.slow
def test_topic_echo_with_a_type_waits_for_a_topic_that_does_not_exist_yet(graph):
    echo = started(graph, "topic", "echo", "/cli_later", "std_msgs/msg/Int64", "--once")
    try:
        for _ in range(100):  # until the echo's subscription has made the topic
            if "/cli_later" in ok(graph, "topic", "list").splitlines():
                break
        ok(graph, "topic", "pub", "/cli_later", "std_msgs/msg/Int64", "data: 7", "--once")
        out, err = echo.communicate(timeout=30)
    finally:
        echo.kill()
    assert (echo.returncode, out, err) == (0, "data: 7\n---\n", "")


@pytest.mark.slow
def test_topic_echo_no_arr_summarises_the_scan(graph):
    out = ok(graph, "topic", "echo", "/scan", "sensor_msgs/msg/LaserScan", "--once", "--no-arr")
    assert "\nranges: '<sequence type: float, length: 360>'\n" in out
    assert "\nintensities: '<sequence type: float, length: 0>'\n" in out


@pytest.mark.slow
def test_topic_bw_counts_the_scans_cdr_bytes(graph):
    out = ok(graph, "topic", "bw", "/scan", "--count", "1")
    lines = out.splitlines()
    assert lines[0] == "Subscribed to [/scan]"
    rate = re.fullmatch(r"(\d+\.\d\d) KB/s from (\d+) messages", lines[1])
    # 1504 bytes ten times a second, or fewer times on a loaded machine: the wall-clock graph lags.
    assert rate and 0 < float(rate[1]) < 20, out
    # 360 float32 ranges, the header and frame id: the size ROS puts on the wire.
    assert lines[2] == "\tMessage size mean: 1.50 KB min: 1.50 KB max: 1.50 KB"


@pytest.mark.slow
def test_topic_pub_once_and_times(graph):
    out = ok(graph, "topic", "pub", "/kill", "std_msgs/msg/Bool", "data: true", "--once")
    assert out == "publisher: beginning loop\npublishing #1: std_msgs.msg.Bool(data=True)\n\n"
    # Nobody subscribes to /cli_test: -w 0 publishes anyway (-t would wait for one, as ros2's does).
    out = ok(graph, "topic", "pub", "/cli_test", "std_msgs/msg/Int64", "{data: 7}", "-r", "50", "-t", "3", "-w", "0")
    assert re.findall(r"publishing #(\d): std_msgs\.msg\.Int64\(data=7\)", out) == ["1", "2", "3"]


@pytest.mark.slow
def test_service_list_type_and_call(graph):
    assert "/add_two_ints [example_interfaces/srv/AddTwoInts]" in ok(graph, "service", "list", "-t").splitlines()
    assert ok(graph, "service", "type", "/add_two_ints") == "example_interfaces/srv/AddTwoInts\n"
    out = ok(
        graph,
        "service",
        "call",
        "/add_two_ints",
        "example_interfaces/srv/AddTwoInts",
        "{a: 2, b: 3}",
    )
    assert out.splitlines() == [
        "requester: making request: example_interfaces.srv.AddTwoInts_Request(a=2, b=3)",
        "",
        "response:",
        "example_interfaces.srv.AddTwoInts_Response(sum=5)",
        "sum: 5",
        "",
    ]


@pytest.mark.slow
def test_param_set_reaches_the_node_and_get_list_dump_read_it(graph):
    mark = len(graph.lines)
    assert ok(graph, "param", "set", "/minimal_param_node", "my_parameter", "earth") == "Set parameter successful\n"
    graph.wait_for("[minimal_param_node]: Hello earth!", after=mark)
    assert ok(graph, "param", "get", "/minimal_param_node", "my_parameter") in (
        "String value is: world\n",
        "String value is: earth\n",
    )
    assert ok(graph, "param", "get", "minimal_client_async", "a") == "Integer value is: 41\n"
    assert (
        ok(graph, "param", "list", "/minimal_param_node")
        == "  my_parameter\n  use_sim_time\n"  # every ROS node has use_sim_time; one node: no header, as ros2
    )
    assert "/minimal_client_async:\n  a\n  b\n  use_sim_time\n" in ok(graph, "param", "list")
    dumped = yaml.safe_load(ok(graph, "param", "dump", "/minimal_client_async"))
    assert dumped == {"/minimal_client_async": {"ros__parameters": {"a": 41, "b": 1, "use_sim_time": False}}}


@pytest.mark.slow
def test_a_refused_param_set_says_why_and_exits_1(graph):
    result = actors(graph, "param", "set", "/minimal_param_node", "my_parameter", "3")
    assert (result.returncode, result.stdout) == (1, "")
    # On stderr, as ros2 param set prints it.
    assert (
        result.stderr == "Setting parameter failed: Wrong parameter type, expected 'Type.STRING' got 'Type.INTEGER'\n"
    )


@pytest.mark.slow
def test_doctor_passes_the_demo_with_warnings_only(graph):
    # As ros2doctor: a publisher nobody subscribes to (the robot's /scan) is a warning.
    out = ok(graph, "doctor")
    assert re.search(r"^All \d+ checks passed$", out, re.MULTILINE), out
    assert "WARNING: publishers without subscribers: /scan (sensor_msgs/msg/LaserScan)" in out
    strict = ok(graph, "doctor", "--include-warnings")
    assert re.search(r"^\d+/\d+ checks failed$", strict, re.MULTILINE), strict
    report = ok(graph, "doctor", "--report")
    for section in (
        "PLATFORM INFORMATION",
        "PACKAGE VERSIONS",
        "GRAPH",
        "NODES",
        "TOPICS",
        "LOOP LAG",
        "CHECKS",
    ):
        assert f"\n   {section}\n" in report


@pytest.mark.slow
def test_graph_writes_a_dot_file(graph, tmp_path):
    target = tmp_path / "x.dot"
    assert ok(graph, "graph", "--output", str(target)) == f"wrote {target}\n"
    dot = target.read_text()
    assert dot.startswith(f'digraph "{graph.name}" {{\n')
    assert '"n:/minimal_publisher" -> "t:/topic";' in dot and '"t:/topic" -> "n:/minimal_subscriber";' in dot
    assert "/rosout" not in dot


@pytest.mark.parametrize(
    ("args", "error"),
    [
        (("topic", "echo", "/nowhere", "--once"), "unknown topic /nowhere"),
        (("topic", "info", "/nowhere"), "unknown topic /nowhere"),
        (("topic", "hz", "/nowhere"), "unknown topic /nowhere"),
        (("node", "info", "/nobody"), "unknown node /nobody"),
        (("param", "get", "/nobody", "x"), "unknown node /nobody"),
        (
            ("param", "get", "/minimal_param_node", "nothing"),
            "parameter 'nothing' is not set on /minimal_param_node",
        ),
        (("service", "type", "/nothing"), "unknown service /nothing"),
        (("topic", "type", "/nowhere"), "unknown topic /nowhere"),
        (("topic", "bw", "/nowhere"), "unknown topic /nowhere"),
        (
            ("topic", "echo", "/topic", "std_msgs/msg/Bool", "--once"),
            "topic /topic carries std_msgs/msg/String, not std_msgs/msg/Bool",
        ),
        (("topic", "echo", "/x", "nope_msgs/msg/Nope"), "unknown interface type 'nope_msgs/msg/Nope'"),
        (("service", "call", "/nothing", "std_srvs/srv/Trigger"), "unknown service /nothing"),
        (
            ("service", "call", "/add_two_ints", "std_srvs/srv/Trigger"),
            "service /add_two_ints has type example_interfaces/srv/AddTwoInts, not std_srvs/srv/Trigger",
        ),
        (
            ("topic", "pub", "/x", "nope_msgs/msg/Nope"),
            "unknown interface type 'nope_msgs/msg/Nope'",
        ),
        (
            ("topic", "pub", "/topic", "std_msgs/msg/Bool", "--once"),
            "topic /topic carries std_msgs/msg/String, not std_msgs/msg/Bool",
        ),
        (
            ("topic", "pub", "/kill", "std_msgs/msg/Bool", "data: [unclosed"),
            "std_msgs/msg/Bool: invalid YAML",
        ),
        (
            ("topic", "pub", "/kill", "std_msgs/msg/Bool", "data: 3"),
            "field 'data' of std_msgs/msg/Bool: expected a bool, got the integer 3",
        ),
        (
            ("service", "call", "/add_two_ints", "example_interfaces/srv/AddTwoInts", "{a: [1"),
            "example_interfaces/srv/AddTwoInts_Request: invalid YAML",
        ),
        (
            ("param", "set", "/minimal_param_node", "my_parameter", "[1, "),
            "parameter value '[1, ' is not valid YAML",
        ),
        (
            ("topic", "echo", "/topic", "--once", "--field", "nope"),
            "std_msgs/msg/String has no field 'nope'",
        ),
    ],
)
@pytest.mark.slow
def test_user_errors_exit_2_with_one_line(graph, args, error):
    result = actors(graph, *args)
    assert result.returncode == 2, result
    assert "beginning loop" not in result.stdout  # topic pub: the publisher never began
    assert len(result.stderr.splitlines()) == 1 and result.stderr.startswith(f"actors: {error}"), result.stderr
    assert "Traceback" not in result.stdout + result.stderr


@pytest.mark.slow
def test_a_closed_stdout_pipe_ends_echo_quietly(graph):
    proc = started(graph, "topic", "echo", "/topic")
    try:
        assert proc.stdout is not None and proc.stdout.readline().startswith("data:")
        proc.stdout.close()  # what `| head -1` does after its line
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert proc.returncode == 141 and err == ""


def test_with_no_running_graph_every_verb_says_so_in_one_line(tmp_path, monkeypatch, capsys):
    # In this process: what is checked is the command line's answer, not anything of a child's.
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    bag = tmp_path / "nothing"
    for args in (
        ("node", "list"),
        ("topic", "echo", "/topic"),
        ("doctor",),
        ("graph",),
        ("bag", "record", "-a", "-o", str(bag)),
    ):
        assert main(list(args)) == 2
        assert capsys.readouterr().err == (
            "actors: no running actors graph found (start one with: python -m actors.run graph.toml)\n"
        )
    assert not bag.exists()  # and a retry once the graph runs does not find it "already exists"


@pytest.fixture(scope="module")
def turtlebot(tmp_path_factory: pytest.TempPathFactory) -> Iterator[GraphProcess]:
    path = tmp_path_factory.mktemp("turtlebot") / f"cli_turtlebot_{os.getpid()}.toml"
    # The robot graph prints nothing while it drives; a talker tells when it runs.
    path.write_text(
        (ROOT / "graphs" / "turtlebot.toml").read_text() + '\n[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n'
    )
    running = GraphProcess(path)
    try:
        running.wait_for("Publishing")
        yield running
    finally:
        running.stop()


@pytest.mark.slow
def test_a_kill_message_stops_the_robot(turtlebot):
    def odom_twist() -> tuple[float, float]:
        out = ok(turtlebot, "topic", "echo", "/odom", "--once", "--field", "twist.twist")
        twist = yaml.safe_load(out.split("---\n")[0])
        return twist["linear"]["x"], twist["angular"]["z"]

    assert odom_twist()[0] > 0  # driving at constant speed
    out = ok(turtlebot, "topic", "pub", "/kill", "std_msgs/msg/Bool", "data: true", "--once")
    assert out.endswith("publishing #1: std_msgs.msg.Bool(data=True)\n\n")
    turtlebot.wait_for("[constant_control]: kill received")
    assert odom_twist() == (0.0, 0.0)  # the burger model brakes at once (no acceleration limit)


@pytest.mark.slow
def test_graph_draws_a_png_with_graphviz_or_pillow(graph, tmp_path):
    target = tmp_path / "graph.png"
    out = ok(graph, "graph", "-o", str(target))
    assert out == f"wrote {tmp_path / 'graph.dot'}\nwrote {target}\n"
    assert target.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
