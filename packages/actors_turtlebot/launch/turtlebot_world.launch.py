"""The TurtleBot in a world, without a controller: start yours in a second terminal (actors run PKG EXE)."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "world", default_value="signs", description="The world: a shipped one's name, or a file"
            ),
            DeclareLaunchArgument("model", default_value="burger", description="The TurtleBot model"),
            DeclareLaunchArgument("x", default_value="0.0", description="Start x (m)"),
            DeclareLaunchArgument("y", default_value="0.0", description="Start y (m)"),
            DeclareLaunchArgument("theta", default_value="0.0", description="Start heading (rad)"),
            Node(package="actors_turtlebot", executable="world", parameters=[{"world": LaunchConfiguration("world")}]),
            Node(
                package="actors_turtlebot",
                executable="turtlebot",
                parameters=[
                    {
                        "model": LaunchConfiguration("model"),
                        "x": LaunchConfiguration("x"),
                        "y": LaunchConfiguration("y"),
                        "theta": LaunchConfiguration("theta"),
                    }
                ],
            ),
        ]
    )
