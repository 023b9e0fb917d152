"""A grader's failure starts with what the student's code did wrong, in the student's own frames."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from conftest import ROOT

from actors.errors import MessageValidationError, ParameterNotDeclaredException, ScriptEnded
from actors.testing import run_node, run_script
from interfaces.std_msgs.msg import Bool

STUDENTS = ROOT / "tests" / "students"


def grade(student: str) -> None:
    """The heartbeat grader: one Int64 count a second."""
    with run_script(STUDENTS / student) as run:
        beats = run.record("/heartbeat")
        run.wait(3.5)
        assert [b.data for b in beats] == [0, 1, 2], "one beat a second, counting from 0"


def grade_node(target: str) -> None:
    with run_node(f"{STUDENTS / 'native_heartbeat.py'}:{target}") as run:
        beats = run.record("/heartbeat")
        run.wait(3.5)
        assert [b.data for b in beats] == [0, 1, 2], "one beat a second, counting from 0"


def shown_frames(excinfo: pytest.ExceptionInfo[BaseException]) -> list[tuple[str, str]]:
    """(file name, function) of each frame pytest shows for the failure, from the grader on."""
    shown = [(Path(entry.path).name, entry.name) for entry in excinfo.traceback.filter(excinfo)]
    return shown[1:]  # the first is the test function that called the grader


def test_the_exercise_done_right_passes():
    grade("good.py")
    grade_node("Heartbeat")


def test_a_missing_module_is_the_failure_at_once():
    with pytest.raises(ModuleNotFoundError, match="No module named 'heartbeat_helpers'") as excinfo:
        grade("imports_missing.py")
    assert shown_frames(excinfo) == [("test_grading_failures.py", "grade"), ("imports_missing.py", "<module>")]


def test_a_constructor_that_raises_is_the_failure_at_once():
    with pytest.raises(ParameterNotDeclaredException, match="'period' is not declared") as excinfo:
        grade("raises_in_init.py")
    assert shown_frames(excinfo) == [
        ("test_grading_failures.py", "grade"),
        ("raises_in_init.py", "<module>"),
        ("raises_in_init.py", "__init__"),
        ("raises_in_init.py", "read_period"),
    ]


def test_a_callback_that_raises_is_the_failure_not_the_missing_beats():
    with pytest.raises(MessageValidationError, match="field 'data' of std_msgs/msg/Int64") as excinfo:
        grade("raises_in_callback.py")
    assert shown_frames(excinfo) == [
        ("test_grading_failures.py", "grade"),
        ("raises_in_callback.py", "<module>"),
        ("raises_in_callback.py", "beat"),
    ]
    assert excinfo.traceback[-1].lineno + 1 == 10  # pytest counts lines from 0: the publish line


def test_a_script_that_ends_early_says_so_before_the_graders_own_error():
    with pytest.raises(ScriptEnded) as excinfo:
        grade("exits_early.py")
    assert str(excinfo.value) == "exits_early.py ended by itself at 0.000 s (exit code 0), before the test was done"
    assert excinfo.value.__notes__ == [
        "then the test failed: LookupError: nobody uses /heartbeat yet: give its type, e.g. record('/heartbeat', Twist)"
    ]


def test_a_script_that_ignores_kill_fails_with_where_it_was(monkeypatch):
    def nobody_reads_other_threads_frames() -> None:
        raise AssertionError("sys._current_frames() was called")

    # The script's thread recorded where it parked, itself (Turn.where): grading reads no frames.
    monkeypatch.setattr(sys, "_current_frames", nobody_reads_other_threads_frames)
    student = ROOT / "tests" / "rclpy_scripts" / "ignores_kill.py"
    with pytest.raises(AssertionError, match="it should stay put") as excinfo, run_script(student) as run:
        run.publish("/kill", Bool(data=True))
        commands = run.record("/cmd_vel")
        run.wait(1.0)
        assert not commands, "it should stay put"
    (note,) = excinfo.value.__notes__
    lines = note.splitlines()
    assert lines[0] == "ignores_kill.py was running, at:"
    assert lines[1].endswith('ignores_kill.py", line 23, in <module>')
    assert lines[2].strip() == "rclpy.spin(Stubborn())"


def test_an_error_while_stopping_comes_before_the_test_that_failed_first(tmp_path):
    student = tmp_path / "saves_on_exit.py"
    student.write_text(
        "import rclpy\n"
        "rclpy.init()\n"
        "node = rclpy.create_node('saver')\n"
        "try:\n"
        "    rclpy.spin(node)\n"
        "finally:\n"
        "    open('/nonexistent/log.txt', 'w')\n"
    )
    with pytest.raises(FileNotFoundError) as excinfo, run_script(student):
        raise AssertionError("no beats")
    assert excinfo.value.__notes__ == ["then the test failed: AssertionError: no beats"]
    assert shown_frames(excinfo) == [("saves_on_exit.py", "<module>")]


def test_run_node_runs_a_native_node_and_its_crash_is_the_failure():
    with pytest.raises(RuntimeError, match="lost count") as excinfo:
        grade_node("Faltering")
    assert shown_frames(excinfo) == [("test_grading_failures.py", "grade_node"), ("native_heartbeat.py", "beat")]


def test_run_node_refuses_anything_but_a_node_class_at_once():
    with pytest.raises(TypeError, match=r"takes an rclpy or an actors node class, got <class '.*Int64'>"):
        grade_node("Int64")
