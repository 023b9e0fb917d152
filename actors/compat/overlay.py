"""The import overlay: ``import rclpy`` and ``from std_msgs.msg import String`` resolve to actors.

While installed, a finder first on ``sys.meta_path`` answers for ``rclpy``,
``rclpy.<module>`` (the modules of :mod:`actors.compat.rclpy`), ``tf2_ros``,
``tf2_geometry_msgs`` and ``tf_transformations`` (tf2's Python side),
``ament_index_python`` (packages as :mod:`actors.launch.packages` finds them),
``launch`` and ``launch_ros`` (launch files' API), and every shipped
interface package (``std_msgs``, ``std_msgs.msg``, ``example_interfaces.srv``...,
the modules of ``interfaces.<pkg>``).  The names are aliases: ``rclpy.node`` *is*
``actors.compat.rclpy.node``, so ``std_msgs.msg.String is
interfaces.std_msgs.msg.String``.  Uninstalling removes the aliases and puts
back whatever those names held before, so a real rclpy in the same environment
keeps working outside the overlay.  A ROS package that nothing provides
(``nav2_msgs``, ``cv_bridge``, Jazzy's ``turtlesim`` interfaces) fails with a
word on what actors ships (:class:`MissingHint`).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from types import ModuleType
from typing import Any

from actors.messages.discovery import discovered

__all__ = ["install", "uninstall", "installed", "overlaid", "OverlayFinder", "MissingHint"]

_INTERFACES = "interfaces"
# The Python packages of ROS that the overlay provides, by the name programs import them as.
_PROVIDED = {
    "rclpy": "actors.compat.rclpy",
    "tf2_ros": "actors.compat.tf2_ros",
    "tf2_geometry_msgs": "actors.compat.tf2_geometry_msgs",
    "tf_transformations": "actors.compat.tf_transformations",
    "ament_index_python": "actors.compat.ament_index_python",
    "launch": "actors.compat.launch",
    "launch_ros": "actors.compat.launch_ros",
}


class OverlayFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Maps ``rclpy[.x]`` to ``actors.compat.rclpy[.x]`` and ``<pkg>[.x]`` to ``interfaces.<pkg>[.x]``.

    ``tf2_ros``, ``tf2_geometry_msgs`` and ``tf_transformations`` are provided too (``actors.compat``'s).

    ``<pkg>`` is a shipped interface package or one found in a workspace or a
    ROS install (:mod:`actors.messages.discovery`).
    """

    def __init__(self) -> None:
        self.packages = _interface_packages()

    def target(self, fullname: str) -> str | None:
        """The actors module that ``fullname`` stands for, or None if the overlay leaves it alone."""
        top, _, rest = fullname.partition(".")
        if top in _PROVIDED:
            return _PROVIDED[top] + (f".{rest}" if rest else "")
        if top in self.packages or (top.isidentifier() and top in discovered()):
            return f"{_INTERFACES}.{fullname}"
        return None

    def find_spec(
        self, fullname: str, path: Sequence[str] | None = None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        real = self.target(fullname)
        if real is None:
            return None
        # Only find the module here: finders run under the interpreter's global import lock, and
        # importing under it deadlocks with another thread importing the same module (partner
        # scripts import rclpy at the same time).  create_module imports it, under its own lock.
        try:
            found = importlib.util.find_spec(real)
        except ModuleNotFoundError as exc:
            if exc.name != real and not real.startswith(f"{exc.name}."):
                raise
            found = None
        if found is None:
            if fullname.partition(".")[0] in _PROVIDED:
                raise ModuleNotFoundError(
                    f"No module named {fullname!r}: actors' rclpy overlay does not provide it",
                    name=fullname,
                ) from None
            return None
        spec = importlib.machinery.ModuleSpec(fullname, self, is_package=found.submodule_search_locations is not None)
        spec.loader_state = real
        return spec

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        module = importlib.import_module(spec.loader_state)
        return _Alias(module, spec.name)  # type: ignore[return-value]  # a stand-in: exec_module swaps in the module

    def exec_module(self, module: ModuleType) -> None:
        sys.modules[object.__getattribute__(module, "_name")] = object.__getattribute__(module, "_target")


class _Alias:
    """Stands in for an aliased module while the import system sets attributes on it.

    The import system writes ``__spec__``, ``__loader__`` and friends on the
    module that ``create_module`` returns; writing them on the real module would
    rename it.  This shell takes those writes, and ``exec_module`` then puts the
    real module in ``sys.modules`` under the alias name.
    """

    def __init__(self, target: ModuleType, name: str) -> None:
        object.__setattr__(self, "_target", target)
        object.__setattr__(self, "_name", name)

    def __getattr__(self, name: str) -> Any:
        return getattr(object.__getattribute__(self, "_target"), name)

    def __setattr__(self, name: str, value: Any) -> None:
        if not name.startswith("__"):
            setattr(object.__getattribute__(self, "_target"), name, value)


class MissingHint(importlib.abc.MetaPathFinder):
    """Last on ``sys.meta_path``: a ROS package that nothing provides fails with a word on what ships.

    While the overlay is installed, ``importlib.util.find_spec`` of such a name raises
    ModuleNotFoundError (with the word) where it would return None: a probe for an optional ROS
    package catches ImportError, as a probe by import does.
    """

    # ROS Python packages that programs import and actors has no stand-in for.
    KNOWN = frozenset(
        {"cv_bridge", "message_filters", "image_geometry", "laser_geometry", "sensor_msgs_py", "rosbag2_py"}
        | {"nav2_simple_commander", "tf2_py", "launch_testing", "rqt_gui", "rqt_gui_py", "ros2cli"}
    )

    def find_spec(
        self, fullname: str, path: Sequence[str] | None = None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        if path is not None or "." in fullname:
            return None  # a submodule: its package says what is missing
        if fullname == "turtlesim":
            raise ModuleNotFoundError(
                "No module named 'turtlesim': since ROS 2 Kilted turtlesim's interfaces are the package "
                "turtlesim_msgs (from turtlesim_msgs.srv import Spawn), which actors ships",
                name=fullname,
            )
        if fullname in self.KNOWN or fullname.endswith(("_msgs", "_srvs", "_interfaces")):
            raise ModuleNotFoundError(
                f"No module named {fullname!r}: actors does not ship it ('actors interface packages' lists "
                "the interface packages it has; a package of your own imports by name from a workspace's src/)",
                name=fullname,
            )
        return None


def _interface_packages() -> frozenset[str]:
    """The shipped interface packages: the folders of ``interfaces`` that are packages."""
    spec = importlib.util.find_spec(_INTERFACES)
    folders = spec.submodule_search_locations if spec is not None else None
    return frozenset(
        entry.name
        for folder in folders or ()
        for entry in Path(folder).iterdir()
        if entry.name.isidentifier() and (entry / "__init__.py").is_file()
    )


_HINT = MissingHint()
_lock = threading.Lock()
_state: dict[str, Any] = {"finder": None, "depth": 0, "saved": {}}


def installed() -> bool:
    """Whether the overlay is installed now."""
    return _state["finder"] is not None


def install() -> None:
    """Make ``rclpy`` and the interface packages resolve to actors, until :func:`uninstall`.

    Calls nest: the overlay stays until every install has been undone.
    Modules already imported under those names (a real rclpy) are set aside and
    put back by :func:`uninstall`.
    """
    with _lock:
        _state["depth"] += 1
        if _state["finder"] is not None:
            return
        finder = OverlayFinder()
        saved = {name: module for name, module in sys.modules.items() if finder.target(name) is not None}
        for name in saved:
            del sys.modules[name]
        _state["saved"] = saved
        _state["finder"] = finder
        sys.meta_path.insert(0, finder)
        sys.meta_path.append(_HINT)
        importlib.invalidate_caches()


def uninstall() -> None:
    """Undo one :func:`install`; the last one removes the aliases and restores what they hid."""
    with _lock:
        if _state["depth"] == 0:
            return
        _state["depth"] -= 1
        finder: OverlayFinder | None = _state["finder"]
        if _state["depth"] or finder is None:
            return
        for installed_finder in (finder, _HINT):
            if installed_finder in sys.meta_path:
                sys.meta_path.remove(installed_finder)
        for name in [n for n in sys.modules if finder.target(n) is not None]:
            del sys.modules[name]
        sys.modules.update(_state["saved"])
        _state["saved"] = {}
        _state["finder"] = None
        importlib.invalidate_caches()


@contextmanager
def overlaid() -> Iterator[None]:
    """``with overlaid(): import rclpy`` gets actors' rclpy inside the block only."""
    install()
    try:
        yield
    finally:
        uninstall()
