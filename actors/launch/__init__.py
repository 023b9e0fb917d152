"""Launching a graph: graph files, importing the code they name, ROS arguments, spawning their nodes."""

__all__: list[str] = []
