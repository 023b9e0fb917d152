"""Every way an rclpy script blocks ends on SIGINT and SIGTERM, and the run's bounds hold."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import threading

import pytest

from tests.test_compat_launcher import BOUNDED_VIRTUAL, ROOT, actors_run, python_env, script

FORMS = ["spin", "spin_once", "future", "call", "wait_for_service", "rate", "sleep", "input", "busy"]


def _started(*args: str) -> subprocess.Popen[str]:
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors", "run", *args],
        cwd=ROOT,
        env=python_env(),
        stdin=subprocess.PIPE,  # open and silent: input() blocks
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None
    assert proc.stdout.readline() == "ready\n"
    return proc


@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
@pytest.mark.parametrize("form", FORMS)
def test_a_signal_ends_a_script_blocked_in_any_form(form: str, signum: int) -> None:
    proc = _started(script("blocked.py"), form)
    proc.send_signal(signum)
    out, err = proc.communicate(timeout=20)  # it would block forever if the signal did not end it
    assert proc.returncode == 0, err
    assert "Traceback" not in err
    assert "not stopped" not in out


def test_a_signal_the_kernel_gives_another_thread_ends_the_main_threads_wait() -> None:
    # The handler runs on the main thread only when it runs bytecode: its wait, parked in select on
    # the pipe that the signal's wake-up writes to, runs it at once (no poll).  The signal goes to
    # a bare thread here, as the kernel may send a process's signal to any thread.
    from actors.compat.session import Session

    with Session(clock="wall") as session:
        previous = signal.signal(signal.SIGUSR1, lambda *_: session.turn.signal(KeyboardInterrupt()))
        try:

            def kill_me() -> None:
                with session.turn:  # given up by the main thread's wait, as it parks
                    signal.pthread_kill(threading.get_ident(), signal.SIGUSR1)

            other = threading.Thread(target=kill_me)
            waiter, bound = session.waiter(), []
            session.wake_after(30.0, lambda: (bound.append("30 s of wall time"), waiter.wake()))
            with pytest.raises(KeyboardInterrupt), session.turn:
                other.start()
                session.wait_until(lambda: bound, None, waiter)
            assert bound == []  # the handler ran at once, not when something else woke the thread
        finally:
            signal.signal(signal.SIGUSR1, previous)
            other.join()


@pytest.mark.slow
def test_timeout_ends_a_script_that_holds_virtual_time_in_a_busy_loop() -> None:
    done = actors_run("--timeout", "1", *BOUNDED_VIRTUAL, script("blocked.py"), "busy", timeout=30)
    assert done.returncode == 124
    assert done.stdout == "ready\n"
    assert done.stderr.splitlines() == ["[WARN] --timeout: 1 s of wall time are up: stopping the run"]


@pytest.mark.slow
def test_duration_ends_a_script_that_only_sleeps_or_waits_for_a_thread_it_started(tmp_path) -> None:
    sleeper = tmp_path / "sleeper.py"
    sleeper.write_text(
        "import threading, time\n"
        "import rclpy\n"
        "rclpy.init()\n"
        "def tick():\n"
        "    while True:\n"
        "        time.sleep(1.0)\n"
        "        print('tick', flush=True)\n"
        "worker = threading.Thread(target=tick)\n"
        "worker.start()\n"
        "worker.join()\n"
    )
    done = actors_run("--clock", "virtual", "--duration", "3.5", str(sleeper), timeout=30)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "tick\n" * 3


@pytest.mark.parametrize(
    ("args", "error"),
    [
        (("--clock", "virtual"), "error: the virtual clock needs a duration, e.g. --duration 10"),
        (("--timeout", "0"), "error: --timeout must be > 0 seconds, got 0.0"),
        (("--duration", "nan"), "error: --duration must be > 0 seconds, got nan"),
        (("--record", "/no/such/folder/run.mcap"), "error: cannot record to /no/such/folder/run.mcap"),
        (("--topics", "/chatter", "--"), "error: --topics selects what --record records: give --record BAG too"),
    ],
)
def test_runs_without_an_end_or_with_a_bad_bound_are_refused(args: tuple[str, ...], error: str) -> None:
    done = actors_run(*args, script("talker.py"))
    assert done.returncode == 2
    assert done.stderr.startswith(error) and len(done.stderr.splitlines()) == 1


def test_a_launcher_option_after_the_script_is_named_in_a_warning() -> None:
    done = actors_run(*BOUNDED_VIRTUAL, script("blocked.py"), "nothing", "--clock", "wall")
    assert done.returncode == 0, done.stderr
    assert done.stderr.splitlines() == [
        "warning: --clock comes after the script, so it went to the script; put actors run's options before the script"
    ]


@pytest.mark.slow
def test_on_the_wall_clock_a_script_blocked_in_select_keeps_the_graph_running(tmp_path) -> None:
    teleop = tmp_path / f"teleop_{os.getpid()}.py"  # the runtime's name, which the CLI finds it by
    shutil.copy(script("teleop_select.py"), teleop)
    proc = _started("--graph", str(ROOT / "scripts" / "with_talker.toml"), str(teleop))
    try:
        echo = subprocess.run(
            [sys.executable, "-m", "actors", "topic", "echo", "/chatter", "--once", "--graph", teleop.stem],
            cwd=ROOT,
            env=python_env(),
            capture_output=True,
            text=True,
            timeout=30,
        )
        assert echo.returncode == 0, echo.stderr
        assert echo.stdout.startswith("data: 'Hello World: ")  # the graph's talker talks meanwhile
        _, err = proc.communicate("w\nq\n", timeout=20)
    finally:
        proc.kill()
    assert proc.returncode == 0, err


TICKER = """\
import rclpy
from rclpy.node import Node

class Ticker(Node):
    def __init__(self):
        super().__init__("ticker")
        self.create_timer(0.5, lambda: self.get_logger().info("Publishing"))

rclpy.init()
rclpy.spin(Ticker())
"""


@pytest.mark.slow
def test_what_is_due_at_the_end_of_the_duration_runs_for_scripts_as_for_graph_files(tmp_path) -> None:
    # A script's timer and the graph file's talker both fire every 0.5 s: under --duration 1 each
    # fires at t = 1.0 too, as python -m actors.run does for the graph alone.
    graph = tmp_path / "talker.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nname = "graph_talker"\n')
    ticker = tmp_path / "ticker.py"
    ticker.write_text(TICKER)
    done = actors_run("--clock", "virtual", "--duration", "1", "--graph", str(graph), str(ticker))
    assert done.returncode == 0, done.stderr
    stamps = re.findall(r"^\[INFO\] \[(\d+\.\d+)\] \[(\w+)\]: Publishing", done.stderr, re.MULTILINE)
    assert sorted(stamps) == [
        ("0.500000000", "graph_talker"),
        ("0.500000000", "ticker"),
        ("1.000000000", "graph_talker"),
        ("1.000000000", "ticker"),
    ]
