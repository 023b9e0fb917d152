"""``launch.launch_description_sources``: launch files by path, of any of the three front ends.

The launch service reads them (:mod:`actors.compat.launch.loading`).
"""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import (
    LaunchContext,
    LaunchDescription,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

__all__ = [
    "LaunchDescriptionSource",
    "PythonLaunchDescriptionSource",
    "AnyLaunchDescriptionSource",
    "FrontendLaunchDescriptionSource",
    "XMLLaunchDescriptionSource",
    "YAMLLaunchDescriptionSource",
]


class LaunchDescriptionSource:
    """Where an included description comes from: a path (text or substitutions)."""

    def __init__(self, launch_file_path: Any) -> None:
        self.path = normalize_to_list_of_substitutions(launch_file_path)

    def location(self, context: LaunchContext) -> str:
        """The path, in ``context``."""
        return perform_substitutions(context, self.path)

    def get_launch_description(self, context: LaunchContext, where: str | None = None) -> LaunchDescription:
        """Read the file (the context's launch service reads it: it knows every front end)."""
        return context.service.load(self.location(context), where)


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """A ``.launch.py`` file."""


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """A launch file of any front end, told by its extension."""


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    """An XML or YAML launch file."""


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A ``.launch.xml`` file."""


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A ``.launch.yaml`` file."""
