"""``python -m actors action ...`` (and the action parts of node, topic, service, doctor) against a live graph."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator

import pytest
from test_cli_live import GraphProcess, actors, ok

GRAPH = """
[[nodes]]
use = "nodes.fibonacci_action_server:FibonacciActionServer"
params = { period = 0.05 }

[[nodes]]
use = "nodes.fibonacci_action_client:FibonacciActionClient"
params = { order = 2 }
"""

pytestmark = pytest.mark.slow  # every test runs the command line as a child process, beside a graph in another


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> Iterator[GraphProcess]:
    path = tmp_path_factory.mktemp("graph") / f"cli_action_{os.getpid()}.toml"
    path.write_text(GRAPH)
    running = GraphProcess(path)
    try:
        running.wait_for("Result: array('i', [0, 1, 1])")  # the graph's own client has had its answer
        yield running
    finally:
        running.stop()


def test_action_list(graph):
    assert ok(graph, "action", "list") == "/fibonacci\n"
    assert ok(graph, "action", "list", "-t") == "/fibonacci [example_interfaces/action/Fibonacci]\n"
    assert ok(graph, "action", "list", "-c") == "1\n"


def test_action_info(graph):
    assert ok(graph, "action", "info", "/fibonacci") == (
        "Action: /fibonacci\n"
        "Action clients: 1\n"
        "    /fibonacci_action_client\n"
        "Action servers: 1\n"
        "    /fibonacci_action_server\n"
    )
    assert "    /fibonacci_action_server [example_interfaces/action/Fibonacci]\n" in ok(
        graph, "action", "info", "fibonacci", "-t"
    )
    assert ok(graph, "action", "info", "/fibonacci", "-c") == (
        "Action: /fibonacci\nAction clients: 1\nAction servers: 1\n"
    )
    assert ok(graph, "action", "info", "/nothing") == "Action: /nothing\nAction clients: 0\nAction servers: 0\n"


def test_action_type_and_find(graph):
    assert ok(graph, "action", "type", "/fibonacci") == "example_interfaces/action/Fibonacci\n"
    assert ok(graph, "action", "find", "example_interfaces/action/Fibonacci") == "/fibonacci\n"
    assert ok(graph, "action", "find", "-c", "example_interfaces/action/Nope") == "0\n"
    missing = actors(graph, "action", "type", "/nothing")
    assert (missing.returncode, missing.stdout) == (2, "")
    assert missing.stderr == "actors: unknown action /nothing\n"


def test_send_goal_prints_feedback_then_the_result_as_ros2_does(graph):
    out = ok(
        graph, "action", "send_goal", "/fibonacci", "example_interfaces/action/Fibonacci", "{order: 3}", "--feedback"
    )
    lines = out.split("\n")
    assert lines[:5] == [
        "Waiting for an action server to become available...",
        "Sending goal:",
        "     order: 3",
        "",
        lines[4],
    ]
    assert re.fullmatch(r"Goal accepted with ID: [0-9a-f]{32}", lines[4])
    assert "\n".join(lines[5:]) == (
        "\n"
        "Feedback:\n    sequence:\n- 0\n- 1\n- 1\n\n"
        "Feedback:\n    sequence:\n- 0\n- 1\n- 1\n- 2\n\n"
        "Result:\n    sequence:\n- 0\n- 1\n- 1\n- 2\n\n"
        "Goal finished with status: SUCCEEDED\n"
    )
    quiet = ok(graph, "action", "send_goal", "fibonacci", "example_interfaces/action/Fibonacci", "order: 1")
    assert "Feedback" not in quiet and quiet.endswith(
        "Result:\n    sequence:\n- 0\n- 1\n\nGoal finished with status: SUCCEEDED\n"
    )


@pytest.mark.parametrize(
    ("args", "error"),
    [
        (("/nothing", "example_interfaces/action/Fibonacci"), "unknown action /nothing (no server runs it)"),
        (
            ("/fibonacci", "example_interfaces/srv/AddTwoInts"),
            "example_interfaces/srv/AddTwoInts is not an action type",
        ),
        (("/fibonacci", "example_interfaces/action/Fibonacci", "{order: x}"), "Fibonacci_Goal"),
        (("/fibonacci", "nope_msgs/action/Nope"), "unknown interface type 'nope_msgs/action/Nope'"),
    ],
)
def test_send_goal_errors_are_one_line_and_exit_2(graph, args, error):
    result = actors(graph, "action", "send_goal", *args)
    assert result.returncode == 2 and error in result.stderr and result.stderr.count("\n") == 1
    assert "Traceback" not in result.stderr


def test_node_info_lists_actions_and_hides_their_wire_names(graph):
    server = ok(graph, "node", "info", "/fibonacci_action_server")
    assert "/_action/" not in server
    assert server.endswith(
        "  Action Servers:\n    /fibonacci: example_interfaces/action/Fibonacci\n  Action Clients:\n\n"
    )
    client = ok(graph, "node", "info", "/fibonacci_action_client")
    assert client.endswith("  Action Clients:\n    /fibonacci: example_interfaces/action/Fibonacci\n")
    hidden = ok(graph, "node", "info", "/fibonacci_action_server", "--include-hidden")
    assert "    /fibonacci/_action/send_goal: example_interfaces/action/Fibonacci_SendGoal\n" in hidden


def test_topic_and_service_lists_hide_an_actions_wire_names(graph):
    assert "/_action/" not in ok(graph, "topic", "list") + ok(graph, "service", "list")
    topics = ok(graph, "topic", "list", "-t", "--include-hidden-topics").splitlines()
    assert "/fibonacci/_action/status [action_msgs/msg/GoalStatusArray]" in topics
    services = ok(graph, "service", "list", "--include-hidden-services").splitlines()
    assert {"/fibonacci/_action/send_goal", "/fibonacci/_action/cancel_goal", "/fibonacci/_action/get_result"} <= set(
        services
    )


def test_doctor_is_happy_and_reports_the_action(graph):
    assert ok(graph, "doctor").startswith("All ")
    report = ok(graph, "doctor", "--report")
    assert re.search(
        r"/fibonacci +: example_interfaces/action/Fibonacci, servers: /fibonacci_action_server, "
        r"clients: /fibonacci_action_client",
        report,
    )


@pytest.mark.parametrize("presses", [1, 2])
def test_ctrl_c_cancels_the_goal(graph, presses):
    import signal
    import subprocess
    import sys

    from conftest import ROOT, python_env

    command = [
        sys.executable,
        "-m",
        "actors",
        "action",
        "send_goal",
        "/fibonacci",
        "example_interfaces/action/Fibonacci",
        "{order: 40}",
        "--feedback",
        "--graph",
        graph.name,
    ]
    proc = subprocess.Popen(
        command, cwd=ROOT, env=python_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert proc.stdout is not None
        lines = []
        while not lines or not lines[-1].startswith("Feedback:"):
            lines.append(proc.stdout.readline())
            assert lines[-1], "".join(lines)
        before = len(graph.lines)
        proc.send_signal(signal.SIGINT)
        if presses == 2:  # an impatient second press, once the cancel has begun
            while not lines[-1].startswith("Canceling goal"):
                lines.append(proc.stdout.readline())
                assert lines[-1], "".join(lines)
            proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=20)
    finally:
        proc.kill()
    assert proc.returncode == 0 and err == ""
    assert ("".join(lines) + out).endswith("Canceling goal...\nGoal canceled.\n")
    graph.wait_for("Goal canceled", after=before)  # the server's own word: the goal did not run on
