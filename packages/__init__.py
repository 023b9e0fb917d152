"""The ROS packages shipped with actors: ament_python source folders, run without a build (see DESIGN.md)."""
