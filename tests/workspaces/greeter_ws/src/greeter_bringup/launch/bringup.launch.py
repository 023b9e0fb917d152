from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription(
        [
            DeclareLaunchArgument("count", default_value="true", description="Whether a counter runs"),
            GroupAction(
                [
                    PushRosNamespace("robot1"),
                    IncludeLaunchDescription(
                        PythonLaunchDescriptionSource(
                            PathJoinSubstitution([FindPackageShare("greeter"), "launch", "greeter.launch.py"])
                        ),
                        launch_arguments={"text": "Hi from robot1", "with_listener": "false"}.items(),
                    ),
                    Node(
                        package="greeter_bringup",
                        executable="counter",
                        parameters=[{"report_every": 2}],
                        condition=IfCondition(LaunchConfiguration("count")),
                    ),
                ]
            ),
        ]
    )
