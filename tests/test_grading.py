"""Grading rclpy exercises: the README's example as written, and what a ScriptRun offers."""

from __future__ import annotations

import re

import pytest
from conftest import ROOT

from actors.testing import run_node, run_script
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_msgs.msg import Bool

SCRIPTS = ROOT / "scripts"
TEST_SCRIPTS = ROOT / "tests" / "rclpy_scripts"


@pytest.fixture(autouse=True)
def at_the_repository_root(monkeypatch):
    monkeypatch.chdir(ROOT)  # the README's example names its files from there


def readme_example() -> dict[str, object]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Grading ROS 2 exercises", 1)[1].split("\n## ", 1)[0]
    (code,) = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    namespace: dict[str, object] = {}
    exec(compile(code, "README.md", "exec"), namespace)
    return namespace


def test_the_readme_example_passes_a_student_who_stops_on_kill():
    example = readme_example()
    example["test_the_robot_drives_until_killed"]()


def test_the_readme_example_fails_a_student_who_ignores_kill():
    example = readme_example()
    example["STUDENT"] = str(TEST_SCRIPTS / "ignores_kill.py")
    with pytest.raises(AssertionError, match="it should stay put"):
        example["test_the_robot_drives_until_killed"]()


def test_a_node_class_instead_of_a_script():
    with run_node(f"{SCRIPTS / 'constant_control.py'}:ConstantControl", graph="graphs/turtlebot_world.toml") as run:
        commands = run.record("/cmd_vel", Twist)
        run.wait(1.0)
        run.publish("/kill", Bool(data=True))
        run.wait(1.0)
    assert [c.linear.x for c in commands] == [0.2] * 5 + [0.0]
    assert run.log[-1] == "[INFO] [1.000000000] [constant_control]: killed: stopping"


def test_calling_a_students_service_and_passing_arguments():
    with run_script(SCRIPTS / "add_two_ints_server.py") as run:
        assert run.call("/add_two_ints", AddTwoInts.Request(a=2, b=3)).sum == 5
        assert run.node("adder").get_name() == "adder"
    with run_script(TEST_SCRIPTS / "exits.py", "3") as run:
        run.wait(1.0)
    assert run.exit_code == 3 and not run.running


def test_a_heartbeat_that_stops_when_the_motor_fails():
    with run_script(TEST_SCRIPTS / "pulse.py") as run:
        beats = run.record("/heartbeat")
        run.wait(3.5)
        assert [b.data for b in beats] == [0, 1, 2]
        run.publish("/health/motor", Bool(data=False))
        run.wait(3.0)
        assert [b.data for b in beats] == [0, 1, 2]
    assert "[FATAL] [3.500000000] [pulse]: motor down, heartbeat stops" in run.log


def test_a_script_whose_helper_thread_parks_outside_rclpy_is_graded():
    # The helper waits in Queue.get from the start: the grader must not wait for it to settle.
    with run_script(TEST_SCRIPTS / "queued_pulse.py") as run:
        beats = run.record("/heartbeat")
        run.wait(3.5)
    assert [b.data for b in beats] == [0, 1, 2]
    assert not [line for line in run.log if "waited 30 s of real time" in line]


def test_what_the_student_raises_fails_the_test():
    with pytest.raises(ZeroDivisionError), run_script(TEST_SCRIPTS / "broken.py") as run:
        run.wait(1.0)
    assert run.exit_code == 1


def test_recording_a_topic_nobody_uses_needs_its_type():
    with run_script(SCRIPTS / "talker.py") as run:
        with pytest.raises(LookupError, match="nobody uses /nothing yet"):
            run.record("/nothing")
        heard = run.record("/chatter")
        run.wait(0.6)
    assert [m.data for m in heard] == ["count 0", "count 1"]


def test_set_parameters_callbacks_of_a_students_node():
    from actors.ros.parameter_store import Parameter
    from interfaces.rcl_interfaces.srv import SetParameters

    def request(**values: float) -> SetParameters.Request:
        return SetParameters.Request(parameters=[Parameter(k, value=v).to_parameter_msg() for k, v in values.items()])

    with run_script(TEST_SCRIPTS / "param_callbacks.py") as run:
        answer = run.call("/tunable/set_parameters", request(speed=3.0))
        assert [r.successful for r in answer.results] == [True]
        refused = run.call("/tunable/set_parameters", request(speed=-1.0))
        assert [(r.successful, r.reason) for r in refused.results] == [(False, "no negatives")]
        run.wait(1.0)
    # The pre-set callback added gain=2.0 to the accepted set; the post-set one kept both.
    assert run.log[-1] == "[INFO] [1.000000000] [tunable]: speed=3.0 gain=2.0"
