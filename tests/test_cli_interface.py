"""Tests for ``actors interface list|show|generate`` (actors/cli/interface.py)."""

from __future__ import annotations

import sys

import pytest

from actors import codec
from actors.cli import main


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(["interface", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_show_expands_nested_types_with_tabs(capsys):
    code, out, err = run(capsys, "show", "tutorial_interfaces/msg/Sphere")
    assert (code, err) == (0, "")
    assert out == "geometry_msgs/Point center\n\tfloat64 x\n\tfloat64 y\n\tfloat64 z\nfloat64 radius\n"


def test_show_service_prints_request_separator_response(capsys):
    code, out, _ = run(capsys, "show", "example_interfaces/srv/AddTwoInts")
    assert (code, out) == (0, "int64 a\nint64 b\n---\nint64 sum\n")


def test_show_action_prints_goal_result_feedback(capsys):
    code, out, _ = run(capsys, "show", "example_interfaces/action/Fibonacci")
    assert (code, out) == (
        0,
        "# Goal\nint32 order\n---\n# Result\nint32[] sequence\n---\n# Feedback\nint32[] sequence\n",
    )


def test_show_an_actions_wire_type(capsys):
    _, out, _ = run(capsys, "show", "example_interfaces/action/Fibonacci_FeedbackMessage")
    assert out == (
        "unique_identifier_msgs/UUID goal_id\n"
        "\tuint8[16] uuid\n"
        "example_interfaces/action/Fibonacci_Feedback feedback\n"
        "\tint32[] sequence\n"
    )


def test_show_keeps_top_level_comments_only(capsys):
    _, out, _ = run(capsys, "show", "geometry_msgs/PoseStamped")
    assert out == (
        "# A Pose with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "\tbuiltin_interfaces/Time stamp\n"
        "\t\tint32 sec\n"
        "\t\tuint32 nanosec\n"
        "\tstring frame_id\n"
        "Pose pose\n"
        "\tPoint position\n"
        "\t\tfloat64 x\n"
        "\t\tfloat64 y\n"
        "\t\tfloat64 z\n"
        "\tQuaternion orientation\n"
        "\t\tfloat64 x 0\n"
        "\t\tfloat64 y 0\n"
        "\t\tfloat64 z 0\n"
        "\t\tfloat64 w 1\n"
    )


def test_show_no_comments(capsys):
    _, out, _ = run(capsys, "show", "sensor_msgs/msg/LaserScan", "--no-comments")
    lines = out.splitlines()
    assert "#" not in out and "" not in lines
    assert lines[:2] == ["std_msgs/Header header", "\tbuiltin_interfaces/Time stamp"]
    assert lines[-2:] == ["float32[] ranges", "float32[] intensities"]


def test_show_unknown_type_is_one_line_and_exit_2(capsys):
    code, out, err = run(capsys, "show", "nope_msgs/msg/Nope")
    assert (code, out) == (2, "")
    assert err.count("\n") == 1 and "nope_msgs/msg/Nope" in err


def test_list_prints_messages_then_services_then_actions(capsys):
    code, out, _ = run(capsys, "list")
    lines = out.splitlines()
    assert code == 0 and lines[0] == "Messages:"
    services, actions = lines.index("Services:"), lines.index("Actions:")
    assert "    std_msgs/msg/String" in lines[1:services]
    assert "    example_interfaces/srv/AddTwoInts" in lines[services + 1 : actions]
    assert "    example_interfaces/action/Fibonacci" in lines[actions + 1 :]
    assert all(line.startswith("    ") for line in lines if not line.endswith(":"))


@pytest.mark.parametrize(
    ("flags", "titles"),
    [
        (["-m"], ["Messages:"]),
        (["-s", "--only-actions"], ["Services:", "Actions:"]),
        (["-a", "-m"], ["Messages:", "Actions:"]),
    ],
)
def test_list_prints_only_the_kinds_asked_for_in_ros2s_order(capsys, flags, titles):
    code, out, _ = run(capsys, "list", *flags)
    lines = out.splitlines()
    assert code == 0 and [line for line in lines if not line.startswith("    ")] == titles
    kinds = {"Messages:": "/msg/", "Services:": "/srv/", "Actions:": "/action/"}
    wanted = tuple(kinds[title] for title in titles)
    assert all(any(kind in line for kind in wanted) for line in lines if line.startswith("    "))


def test_generate_and_show_a_user_root(tmp_path, capsys, monkeypatch):
    for registry in ("_roots", "_types"):  # forget the registration afterwards
        monkeypatch.setattr(codec, registry, type(getattr(codec, registry))())
    monkeypatch.setattr(sys, "path", list(sys.path))
    root = tmp_path / "cli_root"
    (root / "robot_msgs/msg").mkdir(parents=True)
    (root / "robot_msgs/msg/Pair.msg").write_text("# a point, a dot\ngeometry_msgs/Point a\nDot b\n")
    (root / "robot_msgs/msg/Dot.msg").write_text("# a dot\nint8 n\n")
    code, out, _ = run(capsys, "generate", str(root))
    assert code == 0 and f"wrote {root / 'robot_msgs/msg/__init__.py'}" in out
    assert run(capsys, "generate", str(root))[1] == "generated modules are up to date\n"
    code, out, _ = run(capsys, "show", "robot_msgs/Pair", "--root", str(root))
    assert out == "# a point, a dot\ngeometry_msgs/Point a\n\tfloat64 x\n\tfloat64 y\n\tfloat64 z\nDot b\n\tint8 n\n"
    assert "    robot_msgs/msg/Pair" in run(capsys, "list", "--root", str(root))[1]
    for name in [name for name in sys.modules if name.split(".")[0] == "cli_root"]:
        del sys.modules[name]


@pytest.mark.parametrize(("text", "line"), [("int8 a\nfloat64 [] b\n", 2), ("uint8 x 999\n", 1)])
def test_generate_malformed_line_reports_file_and_line(tmp_path, capsys, text, line):
    source = tmp_path / "bad_root/pkg/msg/Bad.msg"
    source.parent.mkdir(parents=True)
    source.write_text(text)
    code, out, err = run(capsys, "generate", str(tmp_path / "bad_root"))
    assert (code, out) == (2, "")
    assert err.startswith(f"actors: {source}:{line}: ") and err.count("\n") == 1


@pytest.mark.slow
def test_python_dash_m_actors_interface_show(run_module):
    result = run_module("actors", "interface", "show", "tutorial_interfaces/msg/Sphere")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "geometry_msgs/Point center",
        "\tfloat64 x",
        "\tfloat64 y",
        "\tfloat64 z",
        "float64 radius",
    ]
    missing = run_module("actors", "interface", "show", "std_msgs/msg/Nope")
    assert missing.returncode == 2 and missing.stderr.count("\n") == 1


def test_show_hash_prints_the_rihs01_hash(capsys):
    # ROS 2 Kilted's hashes (std_msgs/msg/String.json, and rosidl's generator for AddTwoInts)
    code, out, _ = run(capsys, "show", "std_msgs/msg/String", "--hash")
    assert (code, out) == (0, "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18\n")
    code, out, _ = run(capsys, "show", "example_interfaces/srv/AddTwoInts", "--hash")
    assert (code, out) == (0, "RIHS01_e118de6bf5eeb66a2491b5bda11202e7b68f198d6f67922cf30364858239c81a\n")
    code, _, err = run(capsys, "show", "nope_msgs/msg/Nope", "--hash")
    assert code == 2 and "unknown interface type" in err


def test_proto_prints_a_default_instance_in_quotes(capsys):
    code, out, _ = run(capsys, "proto", "geometry_msgs/msg/Twist")
    assert code == 0
    assert out == '"linear:\n  x: 0.0\n  y: 0.0\n  z: 0.0\nangular:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n"\n'
    # A service's request, an action's goal, as ros2 interface proto; --no-quotes as it says.
    assert run(capsys, "proto", "example_interfaces/srv/AddTwoInts", "--no-quotes")[1] == "a: 0\nb: 0\n\n"
    assert run(capsys, "proto", "example_interfaces/action/Fibonacci")[1] == '"order: 0\n"\n'
    assert run(capsys, "proto", "std_srvs/srv/Trigger")[1] == '"{}\n"\n'


def test_a_proto_pasted_into_from_yaml_is_the_default_message():
    from interfaces.geometry_msgs.msg import Twist

    assert codec.from_yaml(codec.to_yaml(Twist()), Twist) == Twist()


def test_packages_and_package_list_what_each_defines(capsys):
    code, out, _ = run(capsys, "packages")
    packages = out.splitlines()
    assert code == 0 and packages == sorted(packages)
    assert {"std_msgs", "std_srvs", "example_interfaces", "action_msgs"} <= set(packages)
    assert run(capsys, "packages", "-a")[1].splitlines() == sorted(
        {name.split("/")[0] for name in codec.list_types() if "/action/" in name}
    )
    assert "std_srvs" not in run(capsys, "packages", "--only-msgs")[1].splitlines()
    assert run(capsys, "package", "std_srvs")[1] == ("std_srvs/srv/Empty\nstd_srvs/srv/SetBool\nstd_srvs/srv/Trigger\n")
    lines = run(capsys, "package", "example_interfaces")[1].splitlines()
    kinds = [line.split("/")[1] for line in lines]
    assert kinds == sorted(kinds, key=["msg", "srv", "action"].index) and "action" in kinds
    services = run(capsys, "package", "example_interfaces", "-s")[1].splitlines()
    assert services == [
        "example_interfaces/srv/AddTwoInts",
        "example_interfaces/srv/SetBool",
        "example_interfaces/srv/Trigger",
    ]
    assert run(capsys, "package", "std_srvs", "-a") == (0, "", "")  # none of that kind, as ros2


def test_an_unknown_package_is_one_line_and_exit_2(capsys):
    assert run(capsys, "package", "not_a_package") == (2, "", "actors: unknown package 'not_a_package'\n")
