"""``ament_index_python.resources``: the resource index (``share/ament_index/resource_index/<type>/<name>``)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Literal

from actors.compat.ament_index_python.search_paths import get_search_paths
from actors.launch.packages import INDEX

__all__ = [
    "InvalidResourceTypeNameError",
    "InvalidResourceNameError",
    "get_resource",
    "get_resources",
    "get_resource_types",
    "has_resource",
]


class InvalidResourceTypeNameError(ValueError):
    """A resource type that is empty or holds a path separator."""


class InvalidResourceNameError(ValueError):
    """A resource name that is empty or holds a path separator."""


_BAD = re.compile(r"[/\\]|^\.\.?$")


def _check(resource_type: str, resource_name: str | None = None) -> None:
    if not resource_type or _BAD.search(resource_type):
        raise InvalidResourceTypeNameError(f"Resource type {resource_type!r} is invalid")
    if resource_name is not None and (not resource_name or _BAD.search(resource_name)):
        raise InvalidResourceNameError(f"Resource name {resource_name!r} is invalid")


def get_resource(resource_type: str, resource_name: str) -> tuple[str, str]:
    """The content of a resource's marker file and the prefix holding it; LookupError when there is none."""
    _check(resource_type, resource_name)
    for prefix in get_search_paths():
        marker = Path(prefix) / INDEX / resource_type / resource_name
        if marker.is_file():
            return marker.read_text(encoding="utf-8"), prefix
    raise LookupError(f"Could not find the resource {resource_name!r} of type {resource_type!r}")


def get_resources(resource_type: str) -> dict[str, str]:
    """Every resource of ``resource_type``, name to the first prefix that has it."""
    _check(resource_type)
    found: dict[str, str] = {}
    for prefix in get_search_paths():
        folder = Path(prefix) / INDEX / resource_type
        if folder.is_dir():
            for entry in sorted(folder.iterdir()):
                if not entry.name.startswith(".") and not entry.is_dir():
                    found.setdefault(entry.name, prefix)
    return found


def get_resource_types() -> set[str]:
    """Every resource type some prefix has."""
    return {
        entry.name
        for prefix in get_search_paths()
        if (Path(prefix) / INDEX).is_dir()
        for entry in (Path(prefix) / INDEX).iterdir()
        if entry.is_dir() and not entry.name.startswith(".")
    }


def has_resource(resource_type: str, resource_name: str) -> str | Literal[False]:
    """The prefix holding the resource, or False."""
    _check(resource_type, resource_name)
    for prefix in get_search_paths():
        if (Path(prefix) / INDEX / resource_type / resource_name).is_file():
            return prefix
    return False
