"""What the ROS 2 launch tutorials use, in our own launch files (issue 31): ``ros2`` commands run against
the launch's own graph, every event handler, the substitutions of "Using substitutions" and "Using event
handlers", turtlesim's mimic in three front ends, and the parameter files of "Managing large projects"."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import python_env

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(shutil.which("ros2") is not None, reason="a real ros2 on the PATH is run as it is"),
]


def launch(path: Path, *args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "actors", "launch", "--clock", "virtual", *args[:2], str(path), *args[2:]],
        cwd=path.parent, env={**python_env(), **(env or {})}, capture_output=True, text=True, timeout=120,
    )  # fmt: skip


def user_lines(text: str) -> list[str]:
    return [line.split("]: ", 1)[1] for line in text.splitlines() if line.startswith("[INFO] [launch.user]: ")]


# A turtlesim whose pen colour is changed through `ros2` commands once it has started, and a turtle
# spawned: each command's output comes back as events, its end starts the next one.
HANDLERS = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler, TimerAction
from launch.conditions import IfCondition
from launch.event_handlers import OnExecutionComplete, OnProcessExit, OnProcessIO, OnProcessStart, OnShutdown
from launch.events import Shutdown
from launch.substitutions import (
    EnvironmentVariable, FindExecutable, LaunchConfiguration, LocalSubstitution, PythonExpression,
)
from launch_ros.actions import Node


def generate_launch_description():
    where = LaunchConfiguration('where')
    sim = Node(package='turtlesim', executable='turtlesim_node', namespace=where, name='pond')
    spawn = ExecuteProcess(
        cmd=[[FindExecutable(name='ros2'), ' service call ', where, '/spawn turtlesim_msgs/srv/Spawn ',
              '"{x: 1.5, y: 3.0, name: second}"']],
        shell=True,
    )
    green = ExecuteProcess(cmd=[FindExecutable(name='ros2'), 'param', 'set', [where, '/pond'], 'background_g', '7'])
    blue = ExecuteProcess(
        cmd=['ros2', 'param', 'set', [where, '/pond'], 'background_b', LaunchConfiguration('blue')],
        condition=IfCondition(PythonExpression([LaunchConfiguration('blue'), ' > 100'])),
    )
    check = ExecuteProcess(cmd=[['ros2 param get ', where, '/pond background_g']], shell=True, output='screen')
    return LaunchDescription([
        DeclareLaunchArgument('where', default_value='pond1'),
        DeclareLaunchArgument('blue', default_value='50'),
        sim,
        RegisterEventHandler(OnProcessStart(target_action=sim, on_start=[LogInfo(msg='the pond is up'), spawn])),
        RegisterEventHandler(OnProcessIO(
            target_action=spawn,
            on_stdout=lambda event: (
                LogInfo(msg='spawn: ' + event.text.decode().strip()) if b'Response' in event.text else None
            ),
        )),
        RegisterEventHandler(OnExecutionComplete(
            target_action=spawn,
            on_completion=[
                LogInfo(msg='spawned'), green,
                TimerAction(period=1.0, actions=[blue]), TimerAction(period=2.0, actions=[check]),
            ],
        )),
        RegisterEventHandler(OnProcessExit(target_action=blue, on_exit=[LogInfo(msg='blue set')])),
        RegisterEventHandler(OnProcessExit(target_action=sim, on_exit=[LogInfo(msg='the pond closed')])),
        RegisterEventHandler(OnProcessExit(target_action=check, on_exit=[
            LogInfo(msg=[EnvironmentVariable('WHO'), ' checked']), EmitEvent(event=Shutdown(reason='all done')),
        ])),
        RegisterEventHandler(OnShutdown(
            on_shutdown=[LogInfo(msg=['asked to end: ', LocalSubstitution('event.reason')])],
        )),
    ])
"""


@pytest.mark.parametrize(("blue", "set_blue"), [("50", False), ("150", True)])
def test_ros2_commands_and_every_event_handler_against_the_launchs_own_graph(tmp_path, blue, set_blue):
    path = tmp_path / "handlers.launch.py"
    path.write_text(HANDLERS)
    done = launch(path, "--duration", "30", "where:=lake", f"blue:={blue}", env={"WHO": "tester"})
    assert done.returncode == 0, done.stderr
    # Virtual time stood still while the spawn request ran: the turtle came at t=0.
    assert "[0.000000000] [lake.pond]: Spawning turtle [second] at x=[1.500000], y=[3.000000]" in done.stderr
    expected = [
        "the pond is up",
        "spawn: turtlesim_msgs.srv.Spawn_Response(name='second')",
        "spawned",
        *(["blue set"] if set_blue else []),
        "tester checked",
        "asked to end: all done",
        "the pond closed",  # the node ends with the launch, and its exit handlers run (nothing new starts)
    ]
    assert user_lines(done.stderr) == expected, done.stderr
    # The last command's own output, on the screen as output='screen' asks, prefixed by its name: as ROS's
    # launch names a process, the base name of its first word (here the whole shell line).
    assert re.search(r"^\[pond background_g-1\] Integer value is: 7$", done.stdout, re.M), done.stdout
    assert "[INFO] [launch]: shutting down: all done" in done.stderr
    assert "[ERROR]" not in done.stderr


SUBSTITUTIONS_YAML = """\
launch:
- arg: {name: where, default: pond1}
- arg: {name: use_red, default: 'False'}
- arg: {name: red, default: '200'}
- node: {pkg: turtlesim, exec: turtlesim_node, name: pond, namespace: '$(var where)'}
- executable:
    cmd: 'ros2 service call $(var where)/spawn turtlesim_msgs/srv/Spawn "{x: 2.5, y: 2.5, theta: 0.5}"'
- timer:
    period: 2.0
    children:
    - executable:
        cmd: 'ros2 param set $(var where)/pond background_r $(var red)'
        if: '$(eval "$(var red) == 200 and $(var use_red)")'
- timer:
    period: 3.0
    children:
    - executable:
        cmd: ros2 param get /$(var where)/pond background_r
        output: screen
"""

SUBSTITUTIONS_XML = """\
<launch>
  <arg name="where" default="pond1"/>
  <arg name="use_red" default="False"/>
  <arg name="red" default="200"/>
  <node pkg="turtlesim" exec="turtlesim_node" name="pond" namespace="$(var where)"/>
  <executable cmd="ros2 service call $(var where)/spawn turtlesim_msgs/srv/Spawn '{x: 2.5, y: 2.5, theta: 0.5}'"/>
  <timer period="2.0">
    <executable cmd="$(find-exec ros2) param set $(var where)/pond background_r $(var red)"
                if="$(eval '$(var red) == 200 and $(var use_red)')"/>
  </timer>
  <timer period="3.0"><executable cmd="ros2 param get /$(var where)/pond background_r" output="screen"/></timer>
</launch>
"""


@pytest.mark.parametrize("front_end", ["yaml", "xml"])
@pytest.mark.parametrize(("use_red", "shown"), [("True", "200"), ("False", "69")])  # turtlesim's own red is 69
def test_commands_a_timer_and_a_condition_in_the_markup_front_ends(tmp_path, front_end, use_red, shown):
    path = tmp_path / f"subst.launch.{front_end}"
    path.write_text(SUBSTITUTIONS_YAML if front_end == "yaml" else SUBSTITUTIONS_XML)
    done = launch(path, "--duration", "4", "where:=sea", f"use_red:={use_red}")
    assert done.returncode == 0, done.stderr
    assert (
        "[0.000000000] [sea.pond]: Spawning turtle [turtle2] at x=[2.500000], y=[2.500000], theta=[0.500000]"
        in done.stderr
    )
    assert f"] Integer value is: {shown}\n" in done.stdout, (done.stdout, done.stderr)
    assert "[ERROR]" not in done.stderr


MIMIC = {
    "py": """\
from launch import LaunchDescription
from launch.actions import ExecuteProcess, TimerAction
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node', namespace='leader', name='sim'),
        Node(package='turtlesim', executable='turtlesim_node', namespace='follower', name='sim'),
        Node(package='turtlesim', executable='mimic', name='copycat',
             remappings=[('/input/pose', '/leader/turtle1/pose'), ('/output/cmd_vel', '/follower/turtle1/cmd_vel')]),
        TimerAction(period=0.5, actions=[ExecuteProcess(cmd=[
            'ros2', 'topic', 'pub', '--once', '/leader/turtle1/cmd_vel', 'geometry_msgs/msg/Twist',
            '{linear: {x: 2.0}, angular: {z: 1.0}}'])]),
    ])
""",
    "xml": """\
<launch>
  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="leader"/>
  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="follower"/>
  <node pkg="turtlesim" exec="mimic" name="copycat">
    <remap from="/input/pose" to="/leader/turtle1/pose"/>
    <remap from="/output/cmd_vel" to="/follower/turtle1/cmd_vel"/>
  </node>
  <timer period="0.5">
    <executable cmd="ros2 topic pub --once /leader/turtle1/cmd_vel geometry_msgs/msg/Twist
                     '{linear: {x: 2.0}, angular: {z: 1.0}}'"/>
  </timer>
</launch>
""",
    "yaml": """\
launch:
- node: {pkg: turtlesim, exec: turtlesim_node, name: sim, namespace: leader}
- node: {pkg: turtlesim, exec: turtlesim_node, name: sim, namespace: follower}
- node:
    pkg: turtlesim
    exec: mimic
    name: copycat
    remap:
    - {from: /input/pose, to: /leader/turtle1/pose}
    - {from: /output/cmd_vel, to: /follower/turtle1/cmd_vel}
- timer:
    period: 0.5
    children:
    - executable:
        cmd: >-
          ros2 topic pub --once /leader/turtle1/cmd_vel geometry_msgs/msg/Twist
          "{linear: {x: 2.0}, angular: {z: 1.0}}"
""",
}


@pytest.mark.parametrize("front_end", sorted(MIMIC))
def test_the_follower_turtle_mimics_the_leader_in_every_front_end(tmp_path, front_end):
    path = tmp_path / f"mimic.launch.{front_end}"
    path.write_text(MIMIC[front_end])
    bag = tmp_path / "poses.mcap"
    done = launch(path, "--duration", "3", "--record", str(bag))
    assert done.returncode == 0, done.stderr
    assert "[ERROR]" not in done.stderr
    from rosbags.highlevel import AnyReader
    from rosbags.typesys import Stores, get_typestore

    last = {}
    with AnyReader([bag], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        for connection, _, raw in reader.messages():
            if connection.topic.endswith("/turtle1/pose"):
                last[connection.topic] = reader.deserialize(raw, connection.msgtype)
    leader, follower = last["/leader/turtle1/pose"], last["/follower/turtle1/pose"]
    # The leader drove for a second; the copycat sent the follower the leader's speeds: both moved
    # the same way from the same start.
    assert leader.x > 6.5 and leader.theta > 0.5
    assert (follower.x, follower.y, follower.theta) == pytest.approx((leader.x, leader.y, leader.theta), abs=0.1)


LARGE = {
    "main.launch.py": """\
import os

from launch import LaunchDescription
from launch.actions import ExecuteProcess, GroupAction, IncludeLaunchDescription, TimerAction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import PushROSNamespace

here = os.path.dirname(__file__)


def include(name, **arguments):
    return IncludeLaunchDescription(PythonLaunchDescriptionSource([here, '/', name]),
                                    launch_arguments=arguments.items())


def ask(node, name):
    return ExecuteProcess(cmd=['ros2', 'param', 'get', node, name], name=f'{node}:{name}', output='screen')


def generate_launch_description():
    return LaunchDescription([
        include('plain.launch.py', background_r='9'),
        GroupAction(actions=[PushROSNamespace('pond2'), include('from_file.launch.py')]),
        include('prefixed.launch.py'),
        TimerAction(period=1.0, actions=[
            ask('/sim', 'background_r'), ask('/sim', 'background_g'),
            ask('/pond2/ns2/sim', 'background_r'), ask('/pond2/ns2/sim', 'background_g'),
            ask('/pond2/ns2/sim', 'background_b'), ask('/ns3/tester_sim', 'background_b'),
        ]),
    ])
""",
    "plain.launch.py": """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, TextSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('background_r', default_value=TextSubstitution(text='0')),
        DeclareLaunchArgument('background_g', default_value=TextSubstitution(text='33')),
        Node(package='turtlesim', executable='turtlesim_node', name='sim', parameters=[{
            'background_r': LaunchConfiguration('background_r'),
            'background_g': LaunchConfiguration('background_g'),
        }]),
    ])
""",
    "from_file.launch.py": """\
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    colours = os.path.join(os.path.dirname(__file__), 'colours.yaml')
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node', namespace='ns2', name='sim', parameters=[colours]),
    ])
""",
    # Keyed for every node, for this one by its full name, and for a node of another namespace.
    "colours.yaml": """\
/**:
  ros__parameters:
    background_g: 86
/pond2/ns2/sim:
  ros__parameters:
    background_b: 255
/ns2/sim:
  ros__parameters:
    background_r: 1
""",
    "prefixed.launch.py": """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('node_prefix', default_value=[EnvironmentVariable('WHO'), '_']),
        Node(package='turtlesim', executable='turtlesim_node', namespace='ns3',
             name=[LaunchConfiguration('node_prefix'), 'sim'],
             parameters=[{'background_b': 12}]),
    ])
""",
}


def test_includes_with_arguments_a_pushed_namespace_and_parameter_files_with_wildcards(tmp_path):
    for name, text in LARGE.items():
        (tmp_path / name).write_text(text)
    done = launch(tmp_path / "main.launch.py", "--duration", "2", env={"WHO": "tester"})
    assert done.returncode == 0, done.stderr
    answers = {line.split("] ")[0][1:].rsplit("-", 1)[0]: line.split("] ")[1] for line in done.stdout.splitlines()}
    assert answers == {
        "/sim:background_r": "Integer value is: 9",  # the include's argument over the declared default
        "/sim:background_g": "Integer value is: 33",  # the declared default
        "/pond2/ns2/sim:background_r": "Integer value is: 69",  # turtlesim's own: the /ns2/sim key is not this node
        "/pond2/ns2/sim:background_g": "Integer value is: 86",  # /** applies to every node
        "/pond2/ns2/sim:background_b": "Integer value is: 255",  # its full name, the pushed namespace in front
        "/ns3/tester_sim:background_b": "Integer value is: 12",  # a name made of substitutions
    }, done.stdout + done.stderr


CHATTER = {
    "py": """\
import launch
import launch_ros.actions


def generate_launch_description():
    return launch.LaunchDescription([
        launch_ros.actions.Node(package='demo_nodes_cpp', executable='talker', name='speaker'),
        launch_ros.actions.Node(package='demo_nodes_py', executable='listener', name='ear'),
    ])
""",
    "xml": '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="speaker"/>\n'
    '  <node pkg="demo_nodes_py" exec="listener" name="ear"/>\n</launch>\n',
    "yaml": "launch:\n\n- node: {pkg: demo_nodes_cpp, exec: talker, name: speaker}\n"
    "- node: {pkg: demo_nodes_py, exec: listener, name: ear}\n",
}

LAUNCH_DATA_FILES = """\
        (os.path.join('share', package_name, 'launch'), glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
"""


def test_a_new_packages_launch_files_installed_by_a_glob_start_the_demo_talker_and_listener(tmp_path):
    # As the tutorial integrating launch files into a package has it: ros2 pkg create, a launch/ folder,
    # data_files globbing it into share/<pkg>/launch, then ros2 launch <pkg> <file> in each front end.
    workspace = tmp_path / "ws"
    (workspace / "src").mkdir(parents=True)
    created = subprocess.run(
        [sys.executable, "-m", "actors", "pkg", "create", "--build-type", "ament_python", "chat_launch"],
        cwd=workspace / "src", env=python_env(), capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert created.returncode == 0, created.stderr
    package = workspace / "src" / "chat_launch"
    setup = (package / "setup.py").read_text()
    setup = "import os\nfrom glob import glob\n" + setup.replace(
        "        ('share/' + package_name, ['package.xml']),\n",
        "        ('share/' + package_name, ['package.xml']),\n" + LAUNCH_DATA_FILES,
    )
    (package / "setup.py").write_text(setup)
    (package / "launch").mkdir()
    for front_end, text in CHATTER.items():
        (package / "launch" / f"chat_launch.{front_end}").write_text(text)
    for front_end in CHATTER:
        done = subprocess.run(
            [sys.executable, "-m", "actors", "launch", "--clock", "virtual", "--duration", "2.5",
             "chat_launch", f"chat_launch.{front_end}"],
            cwd=workspace, env=python_env(), capture_output=True, text=True, timeout=120,
        )  # fmt: skip
        assert done.returncode == 0, done.stderr
        heard = [line for line in done.stderr.splitlines() if "[speaker]" in line or "[ear]" in line]
        assert heard == [
            "[INFO] [1.000000000] [speaker]: Publishing: 'Hello World: 1'",
            "[INFO] [1.000000000] [ear]: I heard: [Hello World: 1]",
            "[INFO] [2.000000000] [speaker]: Publishing: 'Hello World: 2'",
            "[INFO] [2.000000000] [ear]: I heard: [Hello World: 2]",
        ], (front_end, done.stderr)


# Three processes that outlive the launch and a quick one: the quick one's exit must be heard while
# the others still run (readers of long-lived processes once filled a pool and queued the rest).
MANY_PROCESSES = """\
from launch import LaunchDescription
from launch.actions import EmitEvent, ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown


def generate_launch_description():
    quick = ExecuteProcess(cmd=['echo', 'hi'], output='screen')
    return LaunchDescription([
        *(ExecuteProcess(cmd=['sleep', '60']) for _ in range(3)),
        quick,
        RegisterEventHandler(OnProcessExit(target_action=quick, on_exit=[EmitEvent(event=Shutdown(reason='done'))])),
    ])
"""


def test_a_quick_process_is_heard_while_long_ones_run(tmp_path):
    path = tmp_path / "many.launch.py"
    path.write_text(MANY_PROCESSES)
    # On the wall clock: processes take the time they take, and virtual time would race past them.
    done = subprocess.run(
        [sys.executable, "-m", "actors", "launch", str(path)],
        cwd=tmp_path, env=python_env(), capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "[echo-1] hi" in done.stdout
    # The shutdown its exit asked for ended the sleeps: none of them got to finish by itself.
    assert done.stderr.count("process has finished cleanly") == 1, done.stderr


# A message published once, for a subscriber that a timer starts a second later in virtual time.
LATE_LISTENER = """\
from launch import LaunchDescription
from launch.actions import ExecuteProcess, TimerAction
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2', 'topic', 'pub', '--once', '/chatter', 'std_msgs/msg/String', '{data: late}']),
        TimerAction(period=1.0, actions=[Node(package='demo_nodes_py', executable='listener')]),
    ])
"""


def test_a_pub_that_waits_for_a_subscription_lets_virtual_time_go_on(tmp_path):
    # Held, virtual time would never bring the timer that starts the listener, and --duration would
    # never come.  Whether the message reaches it depends on how fast the pub looks in real time.
    path = tmp_path / "late.launch.py"
    path.write_text(LATE_LISTENER)
    done = launch(path, "--duration", "3")
    assert done.returncode == 0, done.stderr
    assert "[listener-1]: process started" in done.stderr, done.stderr
    assert "[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)" in done.stderr  # the end of --duration
