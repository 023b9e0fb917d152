"""ROS 2 launch files, unmodified, under ``actors launch`` (issue 31): the three front ends, every action and
substitution of the issue's list, launch's semantics, and errors as one line naming file and line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import TESTS, python_env

GREETER_WS = TESTS / "workspaces" / "greeter_ws"

PROBE_SETUP = """\
from setuptools import setup

package_name = "probe"
setup(
    name=package_name,
    packages=[package_name],
    data_files=[("share/" + package_name, ["package.xml"]), ("share/probe/config", ["config/p.yaml"])],
    entry_points={"console_scripts": ["once = probe.once:main", "fail = probe.fail:main"]},
)
"""

ONCE = """\
import sys

import rclpy
from std_msgs.msg import String


def main():
    rclpy.init()
    node = rclpy.create_node("once", automatically_declare_parameters_from_overrides=True)
    wanted = ("speed", "shared", "extra", "from_file")
    values = {n: node.get_parameter(n).value for n in wanted if node.has_parameter(n)}
    topic = node.create_publisher(String, "chatter", 10).topic_name
    node.get_logger().info(f"{node.get_fully_qualified_name()} {values} {topic} {sys.argv[1:2]}")
    rclpy.shutdown()
"""


@pytest.fixture
def probe_ws(tmp_path: Path) -> Path:
    """A workspace with one ament_python package, ``probe``: ``once`` logs what it was given, ``fail`` exits 3."""
    package = tmp_path / "ws" / "src" / "probe"
    (package / "probe").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text("<package format='3'><name>probe</name></package>")
    (package / "setup.py").write_text(PROBE_SETUP)
    (package / "probe" / "__init__.py").write_text("")
    (package / "probe" / "once.py").write_text(ONCE)
    (package / "probe" / "fail.py").write_text("def main():\n    print('failing', flush=True)\n    return 3\n")
    (package / "config" / "p.yaml").write_text("/**:\n  ros__parameters:\n    from_file: yes\n")
    return tmp_path / "ws"


def launch(*args: str, cwd: Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "actors", "launch", *args],
        cwd=cwd, env={**python_env(), **(env or {})}, capture_output=True, text=True, timeout=90,
    )  # fmt: skip


def without_pids(text: str) -> list[str]:
    return [line.split(" with pid")[0] for line in text.splitlines()]


@pytest.mark.slow
@pytest.mark.parametrize("front_end", ["py", "xml", "yaml"])
def test_an_include_with_arguments_a_namespace_group_and_a_condition_in_every_front_end(front_end):
    done = launch(
        "--clock", "virtual", "--duration", "2.2", "greeter_bringup", f"bringup.launch.{front_end}", cwd=GREETER_WS
    )
    assert done.returncode == 0, done.stderr
    assert [line.split(" [pid")[0] for line in without_pids(done.stderr)] == [
        "[INFO] [greeter-1]: process started",
        "[INFO] [counter-1]: process started",
        "[INFO] [0.500000000] [robot1.greeter]: Hi from robot1 #0",
        "[INFO] [1.000000000] [robot1.greeter]: Hi from robot1 #1",
        "[INFO] [1.000000000] [robot1.counter]: 2 greetings so far",
        "[INFO] [1.500000000] [robot1.greeter]: Hi from robot1 #2",
        "[INFO] [2.000000000] [robot1.greeter]: Hi from robot1 #3",
        "[INFO] [2.000000000] [robot1.counter]: 4 greetings so far",
        # The end of --duration stops a launch as Ctrl-C does, and its nodes end with it.
        "[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)",
        "[INFO] [greeter-1]: process has finished cleanly",
        "[INFO] [counter-1]: process has finished cleanly",
    ]
    off = launch(
        "--clock", "virtual", "--duration", "1.2", "greeter_bringup", f"bringup.launch.{front_end}", "count:=false",
        cwd=GREETER_WS,
    )  # fmt: skip
    assert off.returncode == 0, off.stderr
    assert "counter" not in off.stderr and "[robot1.greeter]: Hi from robot1 #1" in off.stderr


@pytest.mark.slow
def test_the_included_files_own_defaults_and_its_params_file_apply_when_launched_alone():
    done = launch("--clock", "virtual", "--duration", "1", "greeter", "greeter.launch.py", cwd=GREETER_WS)
    assert done.returncode == 0, done.stderr
    # params.yaml gives the period (0.5 s) and the text; the launch file's text argument wins over it.
    assert "[INFO] [0.500000000] [greeter]: Hello from the launch file #0" in done.stderr
    assert "[INFO] [0.500000000] [listener]: heard 'Hello from the launch file' #0" in done.stderr


def test_show_args_lists_names_descriptions_and_defaults():
    done = launch("greeter", "greeter.launch.py", "--show-args", cwd=GREETER_WS)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "Arguments (pass arguments as '<name>:=<value>'):",
        "",
        "    'text':",
        "        What the greeter says",
        "        (default: 'Hello from the launch file')",
        "",
        "    'with_listener':",
        "        Whether a listener logs the greetings",
        "        (default: 'true')",
    ]


EVERYTHING = """\
import os
import sys

from launch import LaunchDescription
from launch.actions import (
    DeclareLaunchArgument, EmitEvent, ExecuteProcess, GroupAction, IncludeLaunchDescription, LogInfo,
    OpaqueFunction, RegisterEventHandler, TimerAction,
)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.events import Shutdown
from launch.launch_description_sources import AnyLaunchDescriptionSource, PythonLaunchDescriptionSource
from launch.substitutions import (
    EnvironmentVariable, LaunchConfiguration, PathJoinSubstitution, PythonExpression, TextSubstitution,
    ThisLaunchFileDir,
)
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.substitutions import FindPackageShare


def opaque(context, word):
    return [LogInfo(msg=f"opaque: mode={context.launch_configurations['mode']} {word}")]


def generate_launch_description():
    slow = PythonExpression(["'", LaunchConfiguration('mode'), "' == 'slow'"])
    once = Node(
        package='probe', executable='once', name='first', namespace='ns1',
        parameters=[{'speed': LaunchConfiguration('speed')},
                    PathJoinSubstitution([FindPackageShare('probe'), 'config', 'p.yaml'])],
        remappings=[('chatter', 'talk')], arguments=['--flag'], ros_arguments=['-p', 'extra:=7'],
    )
    process = ExecuteProcess(cmd=[sys.executable, '-c', 'print("subprocess ran")'], name='printer', output='screen')
    here = os.path.dirname(__file__)
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='fast', choices=['fast', 'slow']),
        DeclareLaunchArgument('speed', default_value='2.5'),
        LogInfo(msg=['mode: ', LaunchConfiguration('mode'), TextSubstitution(text='!')]),
        LogInfo(msg=['twice the speed: ', PythonExpression(['2 * ', LaunchConfiguration('speed')])]),
        LogInfo(msg=['word: ', EnvironmentVariable('PROBE_WORD', default_value='unset')]),
        LogInfo(msg=['here: ', ThisLaunchFileDir()]),
        LogInfo(msg='slow only', condition=IfCondition(slow)),
        LogInfo(msg='fast only', condition=UnlessCondition(slow)),
        OpaqueFunction(function=opaque, args=['works']),
        RegisterEventHandler(OnProcessStart(target_action=once, on_start=[LogInfo(msg='once started')])),
        RegisterEventHandler(OnProcessExit(
            target_action=once, on_exit=lambda event, context: [LogInfo(msg=f'once exited: {event.returncode}')])),
        RegisterEventHandler(OnProcessExit(target_action=process, on_exit=[LogInfo(msg='the subprocess ended')])),
        GroupAction([
            DeclareLaunchArgument('inner', default_value='set inside'),
            PushRosNamespace('grp'), SetParameter(name='shared', value=5), SetRemap(src='chatter', dst='group_talk'),
            once,
        ]),
        LogInfo(msg=['after the group: ', LaunchConfiguration('inner', default='forgotten')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(here, 'child.launch.py')),
                                 launch_arguments={'who': 'the parent'}.items()),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(os.path.join(here, 'child.launch.xml')),
                                 launch_arguments=[('who', 'xml')]),
        process,
        TimerAction(period=3.0, actions=[LogInfo(msg='three seconds'), EmitEvent(event=Shutdown(reason='done'))]),
        TimerAction(period=9.0, actions=[LogInfo(msg='never: the launch has ended')]),
    ])
"""

CHILD_PY = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('who'), LogInfo(msg=['child of ', LaunchConfiguration('who')])])
"""

CHILD_XML = """\
<launch>
  <arg name="who"/>
  <log message="xml child of $(var who), in $(dirname), $(eval '1 + 2')"/>
  <timer period="1.5"><log message="xml timer, mode $(var mode)"/></timer>
</launch>
"""


@pytest.mark.slow
def test_every_action_and_substitution(probe_ws, tmp_path):
    (tmp_path / "files").mkdir()
    (tmp_path / "files" / "all.launch.py").write_text(EVERYTHING)
    (tmp_path / "files" / "child.launch.py").write_text(CHILD_PY)
    (tmp_path / "files" / "child.launch.xml").write_text(CHILD_XML)
    # On the wall clock: the printer is a real process, and virtual time would race to the 3 s
    # shutdown while it starts (a loaded machine's Python 3.13 lost that race).
    done = launch(str(tmp_path / "files" / "all.launch.py"), "speed:=4",
                  cwd=probe_ws, env={"PROBE_WORD": "hello"})  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = without_pids(done.stderr)
    files = tmp_path / "files"
    for expected in (
        "[INFO] [launch.user]: mode: fast!",
        "[INFO] [launch.user]: twice the speed: 8",
        "[INFO] [launch.user]: word: hello",
        f"[INFO] [launch.user]: here: {files}",
        "[INFO] [launch.user]: fast only",
        "[INFO] [launch.user]: opaque: mode=fast works",
        "[INFO] [once-1]: process started",
        "[INFO] [launch.user]: after the group: forgotten",
        "[INFO] [launch.user]: child of the parent",
        f"[INFO] [launch.user]: xml child of xml, in {files}, 3",
        "[INFO] [printer-1]: process started",
        "[INFO] [launch.user]: once started",
        "[INFO] [once-1]: process has finished cleanly [pid",
        "[INFO] [launch.user]: once exited: 0",
        "[INFO] [launch.user]: xml timer, mode fast",
        "[INFO] [launch.user]: three seconds",
        "[INFO] [launch]: shutting down: done",
    ):
        assert any(line.startswith(expected) for line in lines), (expected, done.stderr)
    assert "slow only" not in done.stderr and "never" not in done.stderr
    said = next(line for line in lines if "[grp.ns1.first]" in line)
    assert said.endswith(
        # speed:=4 reads as YAML (an integer), as launch_ros reads it; the group's remapping comes first,
        # and the first rule that matches a name is the one applied.
        "[grp.ns1.first]: /grp/ns1/first {'speed': 4, 'shared': 5, 'extra': 7, 'from_file': True} "
        "/grp/ns1/group_talk ['--flag']"
    )
    assert "subprocess ran" in done.stdout
    order = [line for line in lines if "three seconds" in line or "xml timer" in line]
    assert order == ["[INFO] [launch.user]: xml timer, mode fast", "[INFO] [launch.user]: three seconds"]


@pytest.mark.slow
def test_a_node_that_exits_is_respawned_after_its_delay(probe_ws, tmp_path):
    (tmp_path / "respawn.launch.xml").write_text(
        '<launch><node pkg="probe" exec="fail" respawn="true" respawn_delay="1.0"/>'
        '<timer period="2.5"><shutdown reason="enough"/></timer></launch>'
    )
    done = launch("--clock", "virtual", "--duration", "30", str(tmp_path / "respawn.launch.xml"), cwd=probe_ws)
    assert done.returncode == 0, done.stderr
    died = [line for line in done.stderr.splitlines() if "process has died" in line]
    assert [line.split(" [pid")[0] for line in died] == [f"[ERROR] [fail-{i}]: process has died" for i in (1, 2, 3)]
    assert "exit code 3, cmd 'fail --ros-args'" in died[0]
    assert done.stdout.splitlines() == ["failing"] * 3


@pytest.mark.slow
def test_a_launch_with_nothing_left_to_wait_for_ends_by_itself(probe_ws, tmp_path):
    (tmp_path / "once.launch.yaml").write_text("launch:\n- node: {pkg: probe, exec: once, name: alone}\n")
    done = launch(str(tmp_path / "once.launch.yaml"), cwd=probe_ws)  # the wall clock, no duration
    assert done.returncode == 0, done.stderr
    assert "[INFO] [once-1]: process has finished cleanly" in done.stderr


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "text", "problem"),
    [
        ("bad.launch.py", "def generate_launch_description(:\n", "bad.launch.py:1: SyntaxError: "),
        (
            "raises.launch.py",
            "from launch import LaunchDescription\n\ndef generate_launch_description():\n    return 1 / 0\n",
            "raises.launch.py:4: ZeroDivisionError: division by zero",
        ),
        (
            "missing.launch.py",
            "from launch import LaunchDescription\nfrom launch.actions import DeclareLaunchArgument\n\n"
            "def generate_launch_description():\n"
            "    return LaunchDescription([\n        DeclareLaunchArgument('needed'),\n    ])\n",
            "missing.launch.py:6: launch argument 'needed' is required and not given",
        ),
        (
            "nopkg.launch.xml",
            '<launch>\n  <node pkg="nope" exec="x"/>\n</launch>\n',
            "nopkg.launch.xml:2: package 'nope' not found",
        ),
        ("tag.launch.xml", "<launch>\n\n  <nodee pkg='x'/>\n</launch>\n", "tag.launch.xml:3: unknown tag <nodee>"),
        ("sub.launch.yaml", "launch:\n- log:\n    message: $(vr x)\n", "sub.launch.yaml:2: unknown substitution $(vr"),
        ("xml.launch.xml", "<launch>\n<log message='x'>\n</launch>\n", "xml.launch.xml:3: not well-formed XML"),
        (
            "cond.launch.py",
            "from launch import LaunchDescription\nfrom launch.actions import LogInfo\n"
            "from launch.conditions import IfCondition\n\ndef generate_launch_description():\n"
            "    return LaunchDescription([LogInfo(msg='x', condition=IfCondition('maybe'))])\n",
            "cond.launch.py:6: 'maybe' is not a condition",
        ),
    ],
)
def test_an_error_in_a_launch_file_is_one_line_naming_file_and_line_and_exit_2(tmp_path, name, text, problem):
    (tmp_path / name).write_text(text)
    done = launch("--clock", "virtual", "--duration", "5", str(tmp_path / name), cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    assert done.stderr.count("\n") == 1 and done.stderr.startswith(f"error: {tmp_path / problem}"), done.stderr


@pytest.mark.slow
def test_a_launch_argument_outside_its_choices_or_not_name_value(tmp_path):
    (tmp_path / "c.launch.xml").write_text('<launch>\n<arg name="m" default="a" choices="a|b"/>\n</launch>\n')
    done = launch(str(tmp_path / "c.launch.xml"), "m:=z", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr == f"error: {tmp_path}/c.launch.xml:2: launch argument 'm' is 'z', not one of a, b\n"
    done = launch(str(tmp_path / "c.launch.xml"), "m=z", cwd=tmp_path)
    assert (done.returncode, done.stderr) == (2, "error: launch arguments are name:=value, got 'm=z'\n")


TWO_TURTLES = {
    "py": "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
    "def generate_launch_description():\n    return LaunchDescription([\n"
    "        Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim'),\n"
    "        Node(package='turtlesim', namespace='turtlesim2', executable='turtlesim_node', name='sim'),\n    ])\n",
    "xml": '<launch>\n  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="turtlesim1"/>\n'
    '  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="turtlesim2"/>\n</launch>\n',
    "yaml": "launch:\n- node: {pkg: turtlesim, exec: turtlesim_node, name: sim, namespace: turtlesim1}\n"
    "- node: {pkg: turtlesim, exec: turtlesim_node, name: sim, namespace: turtlesim2}\n",
}


@pytest.mark.slow
@pytest.mark.parametrize("front_end", sorted(TWO_TURTLES))
def test_two_shipped_turtlesims_in_namespaces_as_the_launch_tutorial_starts_them(tmp_path, front_end):
    # "Creating a launch file": two turtlesim nodes of one name in two namespaces (its mimic node is not shipped).
    path = tmp_path / f"turtles.launch.{front_end}"
    path.write_text(TWO_TURTLES[front_end])
    done = launch("--clock", "virtual", "--duration", "1", str(path), cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    for namespace in ("turtlesim1", "turtlesim2"):
        assert f"[{namespace}.sim]: Starting turtlesim with node name /{namespace}/sim" in done.stderr
