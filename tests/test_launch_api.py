"""The launch API's semantics, in process: scopes, conditions, substitutions, the front ends' $(...) (issue 31)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from actors.compat.launch.actions import DeclareLaunchArgument, GroupAction, SetLaunchConfiguration
from actors.compat.launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from actors.compat.launch.entities import LaunchContext, LaunchDescription
from actors.compat.launch.frontend import Tag, load_xml, load_yaml, parse_substitutions
from actors.compat.launch.substitutions import (
    AndSubstitution,
    EnvironmentVariable,
    LaunchConfiguration,
    NotSubstitution,
    OrSubstitution,
    PathJoinSubstitution,
    PythonExpression,
)
from actors.compat.launch_ros.actions import NAMESPACE, PushRosNamespace
from actors.errors import LaunchFileError


class Visitor:
    """What the launch service does with a description, without a runtime: visit depth first."""

    def __init__(self) -> None:
        self.context = LaunchContext(service=self)
        self.done: list[object] = []

    def completed(self, action):
        self.done.append(action)

    def visit(self, *entities):
        stack = list(reversed(entities))
        while stack:
            result = stack.pop().visit(self.context)
            if result:
                stack.extend(reversed(list(result)))
        return self.context.launch_configurations


def test_a_scoped_group_forgets_what_it_set_an_unscoped_one_does_not():
    seen = Visitor().visit(
        SetLaunchConfiguration("a", "outer"),
        GroupAction([SetLaunchConfiguration("a", "inner"), SetLaunchConfiguration("b", "x"), PushRosNamespace("ns")]),
    )
    assert seen == {"a": "outer"}
    seen = Visitor().visit(GroupAction([SetLaunchConfiguration("b", "x"), PushRosNamespace("ns")], scoped=False))
    assert seen == {"b": "x", NAMESPACE: "/ns"}


def test_a_group_without_forwarding_starts_from_nothing_but_its_own_configurations():
    visitor = Visitor()
    seen_inside = {}

    class Peek(SetLaunchConfiguration):
        def execute(self, context):
            seen_inside.update(context.launch_configurations)

    visitor.visit(
        SetLaunchConfiguration("a", "outer"),
        GroupAction([Peek("x", "y")], forwarding=False, launch_configurations={"kept": LaunchConfiguration("a")}),
    )
    assert seen_inside == {"kept": "outer"}


def test_namespaces_pushed_in_nested_groups_join_and_an_absolute_one_replaces():
    seen = Visitor().visit(GroupAction([PushRosNamespace("a"), PushRosNamespace("b/c")], scoped=False))
    assert seen[NAMESPACE] == "/a/b/c"
    seen = Visitor().visit(GroupAction([PushRosNamespace("a"), PushRosNamespace("/top")], scoped=False))
    assert seen[NAMESPACE] == "/top"


@pytest.mark.parametrize(("text", "expected"), [("true", True), ("1", True), (" False ", False), ("0", False)])
def test_conditions_read_true_false_1_and_0(text, expected):
    context = LaunchContext()
    assert IfCondition(text).evaluate(context) is expected
    assert UnlessCondition(text).evaluate(context) is not expected


def test_a_condition_that_says_neither_is_an_error_naming_the_line():
    with pytest.raises(LaunchFileError, match=r"test_launch_api.py:\d+: 'yes' is not a condition"):
        IfCondition("yes").evaluate(LaunchContext())


def test_substitutions():
    context = LaunchContext()
    context.launch_configurations.update(mode="slow", n="3")
    context.environment = {"HOME_DIR": "/home/me"}
    assert (
        PathJoinSubstitution([EnvironmentVariable("HOME_DIR"), "ws", LaunchConfiguration("mode")]).perform(context)
        == "/home/me/ws/slow"
    )
    assert EnvironmentVariable("NOPE", default_value="d").perform(context) == "d"
    assert PythonExpression(["sqrt(", LaunchConfiguration("n"), " * 12)"]).perform(context) == "6.0"
    assert LaunchConfiguration("missing", default=["de", "fault"]).perform(context) == "default"
    assert NotSubstitution("true").perform(context) == "false"
    assert AndSubstitution("true", "0").perform(context) == "false"
    assert OrSubstitution("false", "1").perform(context) == "true"
    assert LaunchConfigurationEquals("mode", "slow").evaluate(context)
    with pytest.raises(LaunchFileError, match="launch configuration 'missing' does not exist"):
        LaunchConfiguration("missing").perform(context)


def test_a_required_argument_and_choices():
    with pytest.raises(LaunchFileError, match="launch argument 'x' is required and not given"):
        Visitor().visit(DeclareLaunchArgument("x"))
    visitor = Visitor()
    visitor.context.launch_configurations["x"] = "b"
    with pytest.raises(LaunchFileError, match="launch argument 'x' is 'b', not one of a, c"):
        visitor.visit(DeclareLaunchArgument("x", default_value="a", choices=["a", "c"]))
    assert LaunchDescription([GroupAction([DeclareLaunchArgument("inner")])]).get_launch_arguments()[0].name == "inner"


def test_nested_substitutions_in_the_front_ends():
    tag = Tag("log", {}, [], 7, "f.launch.xml")
    context = LaunchContext()
    context.launch_configurations.update(pkg_var="mode", mode="fast")
    parts = parse_substitutions("at $(var $(var pkg_var)) or $(env NOPE 'two words')!", tag)
    assert "".join(p if isinstance(p, str) else p.perform(context) for p in parts) == "at fast or two words!"
    with pytest.raises(LaunchFileError, match=r"f.launch.xml:7: unclosed \$\("):
        parse_substitutions("$(var x", tag)
    with pytest.raises(LaunchFileError, match=r"f.launch.xml:7: \$\(var ...\) takes 1 to 2 arguments, got 0"):
        parse_substitutions("$(var)", tag)


def test_xml_and_yaml_read_into_the_same_actions(tmp_path: Path):
    (tmp_path / "a.launch.xml").write_text(
        '<launch>\n  <arg name="n" default="1"/>\n  <group scoped="false">\n'
        '    <let name="m" value="$(var n)2"/>\n  </group>\n</launch>\n'
    )
    (tmp_path / "a.launch.yaml").write_text(
        "launch:\n- arg: {name: n, default: '1'}\n- group:\n    scoped: false\n    children:\n"
        "    - let: {name: m, value: $(var n)2}\n"
    )
    for name in ("a.launch.xml", "a.launch.yaml"):
        load = load_xml if name.endswith("xml") else load_yaml
        description = load(str(tmp_path / name))
        assert Visitor().visit(description) == {"n": "1", "m": "12"}
        assert description.entities[1].where == f"{tmp_path / name}:3"


def test_ros2_commands_become_actors_command_lines_only_when_no_ros2_is_on_the_path(tmp_path):
    from actors.compat.launch.translation import holds_time, translated

    environment = {"PATH": str(tmp_path)}
    ours = [sys.executable, "-m", "actors"]
    assert translated(["ros2", "param", "set", "a/b", "x", "1"], False, environment) == [
        *ours, "param", "set", "a/b", "x", "1"
    ]  # fmt: skip
    assert translated(["ros2 service call ", "s", ' t "{x: 1, y: 2}"'], True, environment) == [
        *ours, "service", "call", "s", "t", "{x: 1, y: 2}"
    ]  # fmt: skip
    for shell_line in ("ros2 topic list | grep chatter", "ros2 node list; ls", "ros2 node list > out"):
        assert translated([shell_line], True, environment) is None, shell_line
    assert translated(["echo", "ros2"], False, environment) is None
    real = tmp_path / "ros2"
    real.write_text("#!/bin/sh\n")
    real.chmod(0o755)
    assert translated(["ros2", "node", "list"], False, environment) is None
    assert translated([str(real), "node", "list"], False, {"PATH": ""}) is None
    # Requests hold virtual time while they run; what waits for the graph to move on does not.
    assert holds_time([*ours, "service", "call", "s", "t", "{}"])
    assert holds_time([*ours, "topic", "pub", "--once", "/x", "std_msgs/msg/Empty"])
    assert not holds_time([*ours, "topic", "pub", "-r", "1", "/x", "std_msgs/msg/Empty"])
    assert not holds_time([*ours, "topic", "echo", "/x"])
    assert not holds_time([*ours, "launch", "pkg", "file.launch.py"])


def test_find_executable_gives_a_path_stands_in_for_a_missing_ros2_and_names_any_other(tmp_path, monkeypatch):
    from actors.compat.launch.substitutions import FindExecutable

    tool = tmp_path / "tool"
    tool.write_text("#!/bin/sh\n")
    tool.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    context = LaunchContext()
    assert FindExecutable(name="tool").perform(context) == str(tool)
    assert FindExecutable(name="ros2").perform(context) == "ros2"
    with pytest.raises(LaunchFileError, match="executable 'nothere' not found on the PATH"):
        FindExecutable(name="nothere").perform(context)
