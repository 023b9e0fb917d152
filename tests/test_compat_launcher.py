"""``actors run SCRIPT.py``: unmodified rclpy programs, their arguments, output and exit codes."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import weakref

import pytest
from conftest import ROOT, TESTS, python_env

SCRIPTS = ROOT / "scripts"
TEST_SCRIPTS = TESTS / "rclpy_scripts"

# The virtual clock needs a duration: one long enough that the script ends first.
BOUNDED_VIRTUAL = ("--clock", "virtual", "--duration", "60")


def actors_run(*args: str, timeout: float = 60) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "actors", "run", *args],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def script(name: str) -> str:
    return str(SCRIPTS / name if (SCRIPTS / name).exists() else TEST_SCRIPTS / name)


@pytest.mark.slow
def test_a_publisher_on_the_virtual_clock_logs_on_stderr_with_virtual_stamps():
    done = actors_run("--clock", "virtual", "--duration", "1.1", script("talker.py"))
    assert done.returncode == 0, done.stderr
    assert done.stdout == ""
    assert done.stderr.splitlines() == [f"[INFO] [{0.25 * (i + 1):.9f}] [talker]: sent count {i}" for i in range(4)]


@pytest.mark.slow
def test_a_subscriber_beside_a_graph_hears_its_talker():
    done = actors_run(
        "--graph", str(SCRIPTS / "with_talker.toml"), "--clock", "virtual", "--duration", "1.6", script("listener.py")
    )
    assert done.returncode == 0, done.stderr
    heard = [line for line in done.stderr.splitlines() if "[listener]" in line]
    assert heard == [f"[INFO] [{0.5 * (i + 1):.9f}] [listener]: got Hello World: {i}" for i in range(3)]


@pytest.mark.slow
def test_a_client_waits_for_a_late_service_then_uses_its_arguments():
    done = actors_run(
        "--graph",
        str(SCRIPTS / "with_server.toml"),
        *BOUNDED_VIRTUAL,
        script("add_two_ints_client.py"),
        "2",
        "3",
    )
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    # wait_for_service(timeout_sec=1.0) really waits: one line per virtual second until the server is up.
    assert lines[:2] == [
        "[INFO] [1.000000000] [ask_adder]: no adder yet",
        "[INFO] [2.000000000] [ask_adder]: no adder yet",
    ]
    assert lines[-1] == "[INFO] [2.500000000] [ask_adder]: 2 + 3 = 5"


@pytest.mark.slow
def test_a_service_answers_a_graph_client():
    done = actors_run(
        "--graph",
        str(SCRIPTS / "with_client.toml"),
        "--clock",
        "virtual",
        "--duration",
        "1",
        script("add_two_ints_server.py"),
    )
    assert done.returncode == 0, done.stderr
    assert "[adder]: adding 20 and 22" in done.stderr
    assert "[minimal_client_async]: Result of add_two_ints: for 20 + 22 = 42" in done.stderr


@pytest.mark.slow
def test_the_wall_clock_works_too():
    done = actors_run("--duration", "1.0", script("talker.py"))
    assert done.returncode == 0, done.stderr
    sent = [line.split("]: ")[1] for line in done.stderr.splitlines()]
    # How many ticks fit depends on the machine's load: the timing itself is tested on virtual time.
    assert sent and sent == [f"sent count {i}" for i in range(len(sent))]
    assert float(done.stderr.split("] [")[1]) > 1e9  # wall-clock stamps: seconds since 1970


@pytest.mark.slow
def test_script_arguments_exit_code_and_ros_arguments():
    done = actors_run(script("exits.py"), "7", "x", "--ros-args", "-r", "__ns:=/robot", "--", "y")
    assert done.returncode == 7, done.stderr
    assert done.stdout.splitlines() == ["args: ['7', 'x', 'y']", "namespace: /robot"]


@pytest.mark.slow
def test_a_callback_that_raises_ends_the_script_with_its_traceback():
    done = actors_run("--clock", "virtual", "--duration", "5", script("broken.py"))
    assert done.returncode == 1
    assert "ZeroDivisionError: division by zero" in done.stderr
    assert 'File "' + script("broken.py") in done.stderr
    assert "launcher.py" not in done.stderr and "runpy" not in done.stderr


@pytest.mark.parametrize(
    ("args", "problem"),
    [
        (["nowhere.py"], "error: nowhere.py: no such script"),
        ([script("exits.py"), "--ros-args", "-r", "bad"], "error: --ros-args: -r 'bad': expected [node:]name:=value"),
        (["--graph", "nowhere.toml", script("exits.py")], "nowhere.toml"),
        (["--duration", "-1", script("exits.py")], "error: --duration must be > 0 seconds, got -1.0"),
    ],
)
@pytest.mark.slow
def test_bad_input_is_one_line_and_exit_2(args, problem):
    done = actors_run(*args)
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [done.stderr.strip()]
    assert problem in done.stderr


@pytest.mark.slow
def test_ctrl_c_stops_a_spinning_script_gracefully():
    # talker.py does not catch KeyboardInterrupt: the launcher still exits 0, without a traceback.
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors", "run", script("talker.py")],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stderr is not None
    first = proc.stderr.readline()  # the first message: the script is spinning
    assert "sent count 0" in first
    os.kill(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 0, err
    assert "Traceback" not in err


@pytest.mark.slow
def test_ros_arguments_give_parameters_names_and_log_levels(tmp_path):
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters: {speed: 0.5}\n/robot/tuned:\n  ros__parameters: {label: from_file}\n")
    done = actors_run(
        script("params.py"),
        "--ros-args",
        "-r",
        "__ns:=/robot",
        "--params-file",
        str(params),
        "-p",
        "speed:=2.5",
        "--log-level",
        "debug",
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ["/robot/tuned speed=2.5 label=from_file"]
    assert "[DEBUG]" in done.stderr and "[robot.tuned]: debug is on" in done.stderr
    quiet = actors_run(script("params.py"))
    assert quiet.stdout.splitlines() == ["/tuned speed=1.0 label=none"]
    assert "debug is on" not in quiet.stderr


def stderr_lines(done: subprocess.CompletedProcess[str], node: str | None = None) -> list[str]:
    return [line for line in done.stderr.splitlines() if node is None or f"[{node}]" in line]


def messages(done: subprocess.CompletedProcess[str], node: str) -> list[str]:
    return [line.split(f"[{node}]: ", 1)[1] for line in stderr_lines(done, node)]


@pytest.mark.parametrize("style", ["closure", "sleep"])
@pytest.mark.slow
def test_publishing_from_a_closure_or_a_sleep_loop(style):
    # A reused message changed by a nested function, or time.sleep() between publishes: on the
    # virtual clock, time.sleep sleeps virtual time, so both publish every half second.
    done = actors_run("--clock", "virtual", "--duration", "1.6", script("publishers.py"), style)
    assert done.returncode == 0, done.stderr
    first = 0.5 if style == "closure" else 0.0
    assert stderr_lines(done) == [
        f"[INFO] [{first + 0.5 * i:.9f}] [words]: publishing word {i}" for i in range(3 if first else 4)
    ]


@pytest.mark.slow
def test_a_service_spun_once_at_a_time_from_a_module_level_node():
    done = actors_run(
        "--graph", str(SCRIPTS / "with_client.toml"), "--clock", "virtual", "--duration", "1", script("service_loop.py")
    )
    assert done.returncode == 0, done.stderr
    assert messages(done, "loop_server") == ["sum of 20 and 22"]


@pytest.mark.parametrize("style", ["until", "poll", "coroutine"])
@pytest.mark.slow
def test_three_ways_a_client_waits_for_its_answer(style):
    done = actors_run(
        "--graph",
        str(SCRIPTS / "with_server.toml"),
        *BOUNDED_VIRTUAL,
        script("client_styles.py"),
        style,
    )
    assert done.returncode == 0, done.stderr
    # The server comes up at 2.5 s; the coroutine's timer asks at the next half second after it.
    assert messages(done, f"client_{style}") == ["waiting for add_two_ints"] * 2 + ["41 + 1 = 42"]
    answered = stderr_lines(done, f"client_{style}")[-1]
    assert answered.startswith("[INFO] [3.000000000]" if style == "coroutine" else "[INFO] [2.500000000]")


@pytest.mark.parametrize("mode", ["multi", "composed"])
@pytest.mark.slow
def test_two_timers_in_a_mutually_exclusive_group_and_a_listener(mode):
    done = actors_run("--clock", "virtual", "--duration", "2.1", script("executors_demo.py"), mode)
    assert done.returncode == 0, done.stderr
    assert messages(done, "hearer") == [f"heard tick {i}" for i in range(6)]


@pytest.mark.slow
def test_a_callback_group_of_the_scripts_own_throttles_a_timer():
    done = actors_run("--clock", "virtual", "--duration", "1.6", script("executors_demo.py"), "throttled")
    assert done.returncode == 0, done.stderr
    stamps = [line.split("] [")[1] for line in stderr_lines(done, "throttled")]
    # Three tokens at once, then one per refill every half second.
    assert stamps == ["0.100000000", "0.200000000", "0.300000000", "0.500000000", "1.000000000", "1.500000000"]


@pytest.mark.slow
def test_an_executor_subclass_of_the_scripts_own(tmp_path):
    graph = tmp_path / "alarm.toml"
    graph.write_text(
        '[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nname = "alarm_talker"\nremap = { topic = "alarm" }\n'
    )
    done = actors_run(
        "--graph", str(graph), "--clock", "virtual", "--duration", "1.1", script("executors_demo.py"), "priority"
    )
    assert done.returncode == 0, done.stderr
    assert messages(done, "alarm") == ["ALARM Hello World: 0", "ALARM Hello World: 1"]
    assert messages(done, "hearer") == ["heard tick 0", "heard tick 1", "heard tick 2"]


@pytest.mark.slow
def test_sigterm_stops_a_script_gracefully():
    # SIGTERM shuts the context down without a KeyboardInterrupt, as rclpy's handler does: the
    # listener's spin_once raises ExternalShutdownException, which it catches.
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors", "run", "--graph", str(SCRIPTS / "with_talker.toml"), script("listener.py")],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stderr is not None
    while "[listener]: got" not in proc.stderr.readline():
        pass
    os.kill(proc.pid, signal.SIGTERM)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 0, err
    assert "Traceback" not in err


@pytest.mark.slow
def test_a_guard_condition_whose_callback_shuts_rclpy_down():
    done = actors_run("--clock", "virtual", "--duration", "60", script("guard.py"))
    assert done.returncode == 0, done.stderr
    assert messages(done, "guarded") == [
        "spinning once",
        "timer: triggered",
        "spinning once",
        "guard: shut down",
        "done",
    ]


@pytest.mark.slow
def test_qos_and_argparse_beside_ros_arguments():
    talker = actors_run("--clock", "virtual", "--duration", "60", script("qos_pair.py"), "talker", "-n", "3")
    assert talker.returncode == 0, talker.stderr
    assert messages(talker, "qos_talker") == ["best effort talker", "sent msg 0", "sent msg 1", "sent msg 2"]
    listener = actors_run(
        "--graph",
        str(SCRIPTS / "with_talker.toml"),
        "--clock",
        "virtual",
        "--duration",
        "60",
        script("qos_pair.py"),
        "listener",
        "--reliable",
        "-n",
        "2",
        "--ros-args",
        "-r",
        "__node:=ear",
    )
    assert listener.returncode == 0, listener.stderr
    assert messages(listener, "ear") == ["reliable listener", "got Hello World: 0", "got Hello World: 1"]


@pytest.mark.slow
def test_ctrl_c_landing_in_a_finaliser_still_interrupts_the_script():
    # Python drops what a __del__ or a weakref finaliser raises: the KeyboardInterrupt is asked for
    # again, and the context stops with it (not before: the spin would return as if shut down).
    done = actors_run(script("interrupted_in_finaliser.py"), timeout=30)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "interrupted\n"
    assert "Exception ignored" not in done.stderr and "Traceback" not in done.stderr


def test_a_signal_landing_in_a_finaliser_is_handled_at_the_first_line_after_it(monkeypatch):
    # No real-time retry: the handler runs again at the first line outside the finaliser, so the
    # finaliser ends undisturbed, the context stops only then, and the script's next line never runs.
    import actors.compat.launcher

    stopped = threading.Event()
    monkeypatch.setattr(actors.compat.launcher, "_interrupt_default_context", stopped.set)
    ran: list[str] = []

    class Dropped:
        def __del__(self) -> None:
            signal.raise_signal(signal.SIGINT)  # Python runs the handler at its next check: in here
            ran.append(f"the rest of the finaliser; context stopped: {stopped.is_set()}")

    with actors.compat.launcher._Stop().handling_signals(), pytest.raises(KeyboardInterrupt):
        Dropped()  # collected at once
        ran.append("the next line")
    assert ran == ["the rest of the finaliser; context stopped: False"]
    assert stopped.wait(10.0)  # on a thread of its own, as rclpy's handler does it
    assert sys.gettrace() is None


def test_both_kinds_of_finaliser_are_recognised_where_the_signal_lands():
    from actors.compat.launcher import _in_finaliser

    seen: dict[str, object] = {}

    class Owner:
        def __del__(self) -> None:
            seen["__del__"] = sys._getframe()

    class Task:
        pass

    task = Task()
    weakref.finalize(task, lambda: seen.setdefault("finalize", sys._getframe()))
    Owner()
    del task
    assert set(seen) == {"__del__", "finalize"}
    assert all(_in_finaliser(frame) for frame in seen.values())  # type: ignore[arg-type]
    assert not _in_finaliser(sys._getframe())


@pytest.mark.slow
def test_ctrl_c_while_the_main_thread_holds_the_overlays_lock_does_not_deadlock():
    # The handler runs between two bytecodes of whatever the main thread does: waking the context's
    # spins (here a second thread's) happens on a thread of its own, as in rclpy.
    done = actors_run(script("interrupted_holding_a_lock.py"), timeout=30)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "KeyboardInterrupt\n"
    assert "Traceback" not in done.stderr


@pytest.mark.slow
def test_two_scripts_naming_one_node_alike_get_the_error_on_the_scripts_own_line(tmp_path):
    first, second = tmp_path / "first.py", tmp_path / "second.py"
    for path in (first, second):
        path.write_text("import rclpy\nrclpy.init()\nnode = rclpy.create_node('same')\nrclpy.spin(node)\n")
    done = actors_run("--with", str(second), "--clock", "virtual", "--duration", "1", str(first))
    assert done.returncode == 1
    lines = [line for line in done.stderr.splitlines() if line.strip(" ^~")]  # carets vary by Python
    assert lines == [
        "Traceback (most recent call last):",
        f'  File "{second}", line 3, in <module>',
        "    node = rclpy.create_node('same')",
        "actors.errors.InvalidNameError: a node named /same already runs in runtime 'first'",
    ]
