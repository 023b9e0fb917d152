"""``ament_index_python.search_paths``: the prefixes looked in, first wins."""

from __future__ import annotations

from actors.launch.packages import search_paths

__all__ = ["get_search_paths"]


def get_search_paths() -> list[str]:
    """The prefixes, first wins: the workspace's packages', the shipped packages', then ``AMENT_PREFIX_PATH``'s
    that exist.  Unlike ament's, never an error when ``AMENT_PREFIX_PATH`` is unset: actors needs no ROS install."""
    return [str(path) for path in search_paths() if path.exists()]
