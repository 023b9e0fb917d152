"""``launch_ros`` under the overlay: nodes of packages, and the namespaces, parameters and remappings of groups."""

from actors.compat.launch_ros import actions, substitutions

__all__ = ["actions", "substitutions"]
