"""The import overlay: rclpy and the message packages resolve to actors inside it, and only there."""

from __future__ import annotations

import importlib
import subprocess
import sys
import textwrap

import pytest
from conftest import ROOT, python_env

from actors.compat import install, installed, overlaid, uninstall

RCLPY_MODULES = [
    "rclpy",
    "rclpy.node",
    "rclpy.qos",
    "rclpy.executors",
    "rclpy.callback_groups",
    "rclpy.time",
    "rclpy.duration",
    "rclpy.clock",
    "rclpy.parameter",
    "rclpy.logging",
    "rclpy.task",
    "rclpy.exceptions",
    "rclpy.utilities",
    "rclpy.wait_for_message",
    "rclpy.signals",
]


def test_rclpy_and_its_modules_are_actors_inside_the_overlay():
    with overlaid():
        for name in RCLPY_MODULES:
            module = importlib.import_module(name)
            assert module is importlib.import_module("actors.compat." + name), name
        from rclpy.node import Node

        from actors.compat.rclpy.node import Node as OverlayNode

        assert Node is OverlayNode
    assert not installed()


def test_every_shipped_interface_package_is_importable_by_its_ros_name():
    with overlaid():
        from example_interfaces.srv import AddTwoInts
        from geometry_msgs.msg import Twist
        from std_msgs.msg import String

        import interfaces.example_interfaces.srv
        import interfaces.geometry_msgs.msg
        import interfaces.std_msgs.msg

        assert String is interfaces.std_msgs.msg.String
        assert Twist is interfaces.geometry_msgs.msg.Twist
        assert AddTwoInts is interfaces.example_interfaces.srv.AddTwoInts
        assert importlib.import_module("std_msgs") is importlib.import_module("interfaces.std_msgs")


def test_a_module_the_overlay_lacks_is_named_in_the_error():
    with overlaid(), pytest.raises(ModuleNotFoundError, match=r"rclpy\.experimental.*overlay does not provide it"):
        importlib.import_module("rclpy.experimental")


def _shadowable() -> dict[str, object]:
    return {n: m for n, m in sys.modules.items() if n.split(".")[0] in ("rclpy", "std_msgs")}


def test_installs_nest_and_uninstall_puts_back_what_was_there():
    before = _shadowable()  # a real rclpy or std_msgs, if another test imported them
    install()
    install()
    uninstall()
    assert installed()
    importlib.import_module("rclpy.node")
    importlib.import_module("std_msgs.msg")
    uninstall()
    assert not installed()
    assert _shadowable() == before
    uninstall()  # one too many does nothing


REAL_RCLPY = textwrap.dedent(
    """
    import rclpy, std_msgs.msg
    real = rclpy.__file__
    from actors.compat import overlaid
    with overlaid():
        import rclpy as inside
        import std_msgs.msg as inside_msgs
        assert inside.__name__ == "actors.compat.rclpy", inside
        assert inside_msgs.__name__ == "interfaces.std_msgs.msg"
    import rclpy
    import std_msgs.msg
    assert rclpy.__file__ == real, rclpy.__file__
    assert std_msgs.msg.String.__module__.startswith("std_msgs"), std_msgs.msg.String.__module__
    rclpy.init()
    node = rclpy.create_node("real_one")
    print(type(node).__module__)
    rclpy.shutdown()
    """
)


def test_a_real_rclpy_keeps_working_outside_the_overlay(tmp_path):
    pytest.importorskip("rclpy")
    env = {
        **python_env(),
        "ROS_LOG_DIR": str(tmp_path),
        "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp",
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
    }
    done = subprocess.run(
        [sys.executable, "-c", REAL_RCLPY], cwd=ROOT, env=env, capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "rclpy.node"


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("turtlesim", "turtlesim's interfaces are the package turtlesim_msgs (from turtlesim_msgs.srv import Spawn)"),
        ("nav2_msgs", "actors does not ship it ('actors interface packages' lists the interface packages it has"),
        ("cv_bridge", "actors does not ship it"),
    ],
)
def test_a_ros_package_nothing_provides_fails_with_a_word_on_what_ships(name, words):
    with overlaid(), pytest.raises(ModuleNotFoundError) as raised:
        importlib.import_module(name)
    assert raised.value.name == name and words in str(raised.value)
    with pytest.raises(ModuleNotFoundError) as raised:  # the overlay gone, so is the word
        importlib.import_module(name)
    assert str(raised.value) == f"No module named {name!r}"


def test_other_missing_modules_fail_as_python_says():
    with overlaid(), pytest.raises(ModuleNotFoundError) as raised:
        importlib.import_module("not_a_ros_thing")
    assert str(raised.value) == "No module named 'not_a_ros_thing'"


def test_the_ros_python_packages_a_newcomer_imports_first_are_provided():
    # The list: of tf2_ros, turtlesim, visualization_msgs and ament_index_python, all but
    # turtlesim (an interface package no longer, since Kilted: see above) ship under the overlay.
    with overlaid():
        from ament_index_python.packages import get_package_share_directory
        from tf2_ros import Buffer, TransformBroadcaster
        from visualization_msgs.msg import Marker, MarkerArray

        import interfaces.visualization_msgs.msg as shipped

        assert (Marker, MarkerArray) == (shipped.Marker, shipped.MarkerArray)
        assert Buffer.__module__.startswith("actors.compat.tf2_ros")
        assert TransformBroadcaster.__module__.startswith("actors.compat.tf2_ros")
        assert get_package_share_directory("turtlesim")
