"""A turtlesim driven by ``ros2`` commands from its own launch file: a spawn, a colour, a check."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, LogInfo, RegisterEventHandler, TimerAction
from launch.event_handlers import OnExecutionComplete, OnProcessIO, OnProcessStart, OnShutdown
from launch.substitutions import FindExecutable, LaunchConfiguration, LocalSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    where = LaunchConfiguration("where")
    ros2 = FindExecutable(name="ros2")
    pond = Node(package="turtlesim", executable="turtlesim_node", namespace=where, name="pond")
    spawn = ExecuteProcess(
        cmd=[ros2, "service", "call", [where, "/spawn"], "turtlesim_msgs/srv/Spawn", "{x: 2.0, y: 8.0, name: visitor}"]
    )
    paint = ExecuteProcess(cmd=[ros2, "param", "set", [where, "/pond"], "background_b", LaunchConfiguration("blue")])
    check = ExecuteProcess(cmd=[ros2, "param", "get", [where, "/pond"], "background_b"], output="screen")
    return LaunchDescription(
        [
            DeclareLaunchArgument("where", default_value="garden", description="the namespace of the pond"),
            DeclareLaunchArgument("blue", default_value="180", description="the pond's new blue"),
            pond,
            RegisterEventHandler(OnProcessStart(target_action=pond, on_start=[spawn])),
            RegisterEventHandler(
                OnProcessIO(
                    target_action=spawn,
                    on_stdout=lambda event: (
                        LogInfo(msg=["the pond answered: ", event.text.decode().strip()])
                        if event.text.startswith(b"turtlesim_msgs")
                        else None
                    ),
                )
            ),
            RegisterEventHandler(
                OnExecutionComplete(
                    target_action=spawn, on_completion=[paint, TimerAction(period=1.0, actions=[check])]
                )
            ),
            RegisterEventHandler(
                OnShutdown(on_shutdown=[LogInfo(msg=["stopping: ", LocalSubstitution("event.reason")])])
            ),
        ]
    )
