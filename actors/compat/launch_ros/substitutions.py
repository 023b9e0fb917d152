"""``launch_ros.substitutions``: where a package is."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import (
    LaunchContext,
    Substitution,
    caller_location,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from actors.errors import LaunchFileError, PackageError

__all__ = ["FindPackageShare", "FindPackagePrefix", "FindPackage"]


class FindPackagePrefix(Substitution):
    """The install prefix of a package."""

    def __init__(self, package: Any) -> None:
        self.package = normalize_to_list_of_substitutions(package)
        self.where = caller_location()

    def find(self, context: LaunchContext) -> Any:
        from actors.launch.packages import find_package

        name = perform_substitutions(context, self.package)
        try:
            return find_package(name)
        except PackageError as exc:
            raise LaunchFileError(f"{self.where or 'launch'}: {exc}") from None

    def perform(self, context: LaunchContext) -> str:
        return str(self.find(context).prefix)

    def describe(self) -> str:
        return f"{type(self).__name__}({''.join(s.describe() for s in self.package)})"


class FindPackage(FindPackagePrefix):
    """The prefix of a package (as ``FindPackagePrefix``)."""


class FindPackageShare(FindPackagePrefix):
    """The share directory of a package: ``<prefix>/share/<package>``."""

    def perform(self, context: LaunchContext) -> str:
        return str(self.find(context).share)

    def find_package_share(self, context: LaunchContext) -> str:
        """The share directory."""
        return self.perform(context)
