"""``ament_index_python`` under the overlay: packages of the workspace, of actors and of AMENT_PREFIX_PATH.

Where a package is and which one wins is :mod:`actors.launch.packages`'
business; this is ament_index_python's API over it, so that launch files and
nodes that look up ``get_package_share_directory("my_pkg")`` find the
workspace's files where colcon would have installed them.
"""

from actors.compat.ament_index_python.constants import RESOURCE_INDEX_SUBFOLDER
from actors.compat.ament_index_python.packages import (
    PackageNotFoundError,
    get_package_prefix,
    get_package_share_directory,
    get_package_share_path,
    get_packages_with_prefixes,
)
from actors.compat.ament_index_python.resources import (
    InvalidResourceNameError,
    InvalidResourceTypeNameError,
    get_resource,
    get_resource_types,
    get_resources,
    has_resource,
)
from actors.compat.ament_index_python.search_paths import get_search_paths

__all__ = [
    "get_package_prefix",
    "get_package_share_directory",
    "get_package_share_path",
    "get_packages_with_prefixes",
    "get_resource",
    "get_resources",
    "get_search_paths",
    "get_resource_types",
    "has_resource",
    "InvalidResourceTypeNameError",
    "InvalidResourceNameError",
    "PackageNotFoundError",
    "RESOURCE_INDEX_SUBFOLDER",
]
