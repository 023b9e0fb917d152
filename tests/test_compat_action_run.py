"""``actors run --with SERVER.py CLIENT.py``: an rclpy action server and its client, two unmodified
programs in one runtime on the virtual clock, with what they log (scripts/fibonacci_action_*.py)."""

from __future__ import annotations

import pytest
from conftest import ROOT
from test_compat_launcher import actors_run, messages

pytestmark = pytest.mark.slow  # every test runs the two scripts in a child process

SERVER = str(ROOT / "scripts" / "fibonacci_action_server.py")
CLIENT = str(ROOT / "scripts" / "fibonacci_action_client.py")


def pair(server_args: str = "", *client_args: str, timeout: float = 60):
    done = actors_run(
        "--clock",
        "virtual",
        "--duration",
        "60",
        "--with",
        f"{SERVER} {server_args}",
        CLIENT,
        *client_args,
        timeout=timeout,
    )
    assert done.returncode == 0, done.stderr
    return done


def test_feedback_in_order_then_the_result_each_line_at_its_virtual_second():
    done = pair("", "3")
    # Each node's lines in their order; between the two nodes, lines of one virtual instant come in
    # whichever order their threads ran (the server's execute callback runs on a pool thread while
    # the client's script thread takes the goal response), as on ROS 2.
    lines = done.stderr.splitlines()
    assert [line for line in lines if "[fibonacci_server]" in line] == [
        "[INFO] [0.000000000] [fibonacci_server]: order 3 accepted",
        "[INFO] [0.000000000] [fibonacci_server]: next: 1",
        "[INFO] [1.000000000] [fibonacci_server]: next: 2",
        "[INFO] [2.000000000] [fibonacci_server]: done: [0, 1, 1, 2]",
    ]
    assert [line for line in lines if "[fibonacci_client]" in line] == [
        "[INFO] [0.000000000] [fibonacci_client]: looking for the server",
        "[INFO] [0.000000000] [fibonacci_client]: the server took it",
        "[INFO] [0.000000000] [fibonacci_client]: so far: [0, 1, 1]",
        "[INFO] [1.000000000] [fibonacci_client]: so far: [0, 1, 1, 2]",
        "[INFO] [2.000000000] [fibonacci_client]: succeeded: [0, 1, 1, 2]",
    ]
    assert len(lines) == 9
    # What one node says because of the other comes after it.
    for cause, effect in [
        ("order 3 accepted", "the server took it"),
        ("next: 1", "so far: [0, 1, 1]"),
        ("next: 2", "so far: [0, 1, 1, 2]"),
        ("done: [0, 1, 1, 2]", "succeeded"),
    ]:
        assert next(i for i, line in enumerate(lines) if cause in line) < next(
            i for i, line in enumerate(lines) if effect in line
        )


def test_the_client_cancels_an_executing_goal():
    done = pair("", "6", "cancel")
    assert messages(done, "fibonacci_client")[-4:] == [
        "so far: [0, 1, 1, 2, 3]",
        "asking to cancel",
        "the server is canceling",
        "canceled: [0, 1, 1, 2, 3]",
    ]
    assert "[INFO] [3.000000000] [fibonacci_server]: canceled at 3" in done.stderr.splitlines()


def test_a_goal_the_server_refuses():
    done = pair("", "50")
    assert messages(done, "fibonacci_server") == ["order 50 is too long, refused"]
    assert messages(done, "fibonacci_client") == ["looking for the server", "the server said no"]


def test_spin_until_future_complete_in_main():
    done = pair("", "2", "blocking")
    assert messages(done, "fibonacci_client") == [
        "looking for the server",
        "the server took it",
        "so far: [0, 1, 1]",
        "succeeded: [0, 1, 1]",
    ]


def test_a_deferred_goal_starts_on_a_timer_of_the_server():
    done = pair("delayed", "2")
    lines = done.stderr.splitlines()
    assert "[INFO] [0.000000000] [fibonacci_server]: starting in 2 s" in lines
    assert lines[-1] == "[INFO] [3.000000000] [fibonacci_client]: succeeded: [0, 1, 1]"


def test_asyncio_tasks_send_two_goals_at_once_and_a_reentrant_server_runs_them_side_by_side():
    done = pair("", "2", "asyncio")
    client = [line for line in done.stderr.splitlines() if "[fibonacci_client]" in line and "succeeded" in line]
    assert sorted(client[:2]) == [
        "[INFO] [1.050000000] [fibonacci_client]: first: succeeded with 3 numbers",
        "[INFO] [1.050000000] [fibonacci_client]: second: succeeded with 3 numbers",
    ]
    assert client[2] == "[INFO] [2.150000000] [fibonacci_client]: third: succeeded with 3 numbers"


@pytest.mark.parametrize(
    ("policy", "outcomes", "log"),
    [
        ("queue", ["succeeded with 3 numbers", "succeeded with 3 numbers"], "1 goal(s) waiting"),
        (
            "latest",
            ["aborted with 3 numbers", "succeeded with 4 numbers"],
            "a newer goal came: aborting the running one",
        ),
    ],
)
def test_a_server_that_queues_goals_or_keeps_only_the_latest(policy, outcomes, log):
    done = pair(policy, "3" if policy == "latest" else "2", "asyncio")
    assert log in messages(done, "fibonacci_server")
    ends = [
        m.split(": ", 1)[1]
        for m in messages(done, "fibonacci_client")
        if m.startswith(("first:", "second:")) and "took it" not in m
    ]
    assert sorted(ends) == sorted(outcomes)


def test_each_script_sees_its_own_command_line_and_a_failing_partner_fails_the_run(tmp_path):
    failing = tmp_path / "fails.py"
    failing.write_text("import sys\nprint('partner argv', sys.argv[1:], file=sys.stderr)\nraise SystemExit(3)\n")
    done = actors_run(
        "--clock", "virtual", "--duration", "60", "--with", f"{failing} x 'y z'", "--with", SERVER, CLIENT, "1"
    )
    assert done.returncode == 1
    assert "partner argv ['x', 'y z']" in done.stderr.splitlines()
    assert messages(done, "fibonacci_client")[-1] == "succeeded: [0, 1]"  # the client read its own "1"


@pytest.mark.parametrize(
    ("partner", "problem"),
    [
        ("nowhere.py", "error: nowhere.py: no such script"),
        ("'unclosed", "error: --with: No closing quotation"),
    ],
)
def test_a_bad_partner_is_one_line_and_exit_2(partner, problem):
    done = actors_run("--clock", "virtual", "--duration", "60", "--with", partner, CLIENT)
    assert (done.returncode, done.stderr.strip()) == (2, problem)


def test_the_end_of_the_duration_stops_a_goal_that_sleeps_on_a_pool_thread():
    # The server's execute callback is in time.sleep on a pool thread when the run ends: the run ends.
    done = actors_run("--clock", "virtual", "--duration", "2.5", "--with", SERVER, CLIENT, "20", timeout=60)
    assert done.returncode == 0, done.stderr
    assert messages(done, "fibonacci_client")[-1] == "so far: [0, 1, 1, 2, 3]"
