import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory("greeter"), "config", "params.yaml")
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "text", default_value="Hello from the launch file", description="What the greeter says"
            ),
            DeclareLaunchArgument(
                "with_listener", default_value="true", description="Whether a listener logs the greetings"
            ),
            Node(
                package="greeter",
                executable="greeter",
                name="greeter",
                parameters=[params, {"text": LaunchConfiguration("text")}],
                output="screen",
            ),
            Node(
                package="greeter",
                executable="listener",
                condition=IfCondition(LaunchConfiguration("with_listener")),
            ),
        ]
    )
