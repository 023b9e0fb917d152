"""``ament_index_python.packages``: a package's prefix and share directory."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

from actors.compat.ament_index_python.resources import get_resource, get_resources
from actors.compat.ament_index_python.search_paths import get_search_paths

__all__ = [
    "PackageNotFoundError",
    "get_packages_with_prefixes",
    "get_package_prefix",
    "get_package_share_directory",
    "get_package_share_path",
]

# REP 127's package names, with the exemptions it allows (upper case, dashes), as ament checks them.
_NAME = re.compile(r"[a-zA-Z0-9][a-zA-Z0-9_-]+", re.ASCII)


class PackageNotFoundError(KeyError):
    """No package of that name in the workspace, among the shipped ones, or in AMENT_PREFIX_PATH."""


def get_packages_with_prefixes() -> dict[str, str]:
    """Every package, name to its prefix."""
    return get_resources("packages")


def get_package_prefix(package_name: str) -> str:
    """The prefix of ``package_name``: ValueError for a malformed name, PackageNotFoundError for an unknown one."""
    if _NAME.fullmatch(package_name) is None:
        raise ValueError(f"{package_name!r} is not a valid package name")
    try:
        return get_resource("packages", package_name)[1]
    except LookupError:
        raise PackageNotFoundError(f"package {package_name!r} not found, searching: {get_search_paths()}") from None


def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
    """``<prefix>/share/<package_name>``; warns (``print_warning``) when that folder is missing."""
    path = str(Path(get_package_prefix(package_name)) / "share" / package_name)
    if print_warning and not Path(path).exists():
        warnings.warn(f"Share directory for {package_name} ({path}) does not exist.", stacklevel=2)
    return path


def get_package_share_path(package_name: str, print_warning: bool = True) -> Path:
    """:func:`get_package_share_directory` as a ``pathlib.Path``."""
    path = Path(get_package_prefix(package_name)) / "share" / package_name
    if print_warning and not path.exists():
        warnings.warn(f"Share directory for {package_name} ({path}) does not exist.", stacklevel=2)
    return path
