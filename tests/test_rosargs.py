"""ROS command-line arguments and parameter files, read as rcl reads them."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

import pytest

from actors.errors import RosArgsError
from actors.launch.rosargs import (
    ParamRule,
    Remap,
    load_params_file,
    node_key_matches,
    parameters_for,
    parse,
    remove_ros_args,
)
from actors.ros.log import DEBUG, WARN

PARAMS = """\
/**:
  ros__parameters:
    everyone: 1
talker:
  ros__parameters:
    speed: 0.5
    limits:
      max: [1.0, 2.5]
      name: fast
/robot1:
  driver:
    ros__parameters:
      radius: 0.033
/robot1/*:
  ros__parameters:
    in_robot1: true
"""


@pytest.fixture
def params_file(tmp_path):
    path = tmp_path / "params.yaml"
    path.write_text(PARAMS)
    return path


def test_program_arguments_are_kept_in_order_around_ros_sections():
    argv = ["prog", "a", "--ros-args", "-p", "x:=1", "--", "b", "--ros-args", "-r", "a:=b"]
    ros, rest = parse(argv)
    assert rest == ["prog", "a", "b"]
    assert remove_ros_args(argv) == ["prog", "a", "b"]
    assert ros.params == (ParamRule("/**", {"x": 1}),)
    assert ros.remaps == (Remap("a", "b"),)


def test_parameter_values_are_yaml():
    ros, _ = parse(
        [
            "--ros-args",
            "-p",
            "i:=3",
            "-p",
            "f:=2.5",
            "-p",
            "b:=yes",
            "-p",
            "s:='007'",
            "-p",
            "l:=[1, 2]",
            "--param",
            "t:=hello world",
        ]
    )
    values = ros.for_node("n", None).params
    assert values == {"i": 3, "f": 2.5, "b": True, "s": "007", "l": [1, 2], "t": "hello world"}


def test_rules_with_a_node_prefix_apply_to_that_node_only():
    ros, _ = parse(
        [
            "--ros-args",
            "-p",
            "talker:only:=1",
            "-p",
            "all:=2",
            "-r",
            "talker:chatter:=tc",
            "-r",
            "talker:__node:=speaker",
        ]
    )
    talker = ros.for_node("talker", None)
    other = ros.for_node("listener", None)
    # The parameter rule names the node /talker; renamed to /speaker, it no longer matches (as rcl).
    assert (talker.name, talker.remap, talker.params) == ("speaker", {"chatter": "tc"}, {"all": 2})
    assert (other.name, other.remap, other.params) == ("listener", {}, {"all": 2})
    plain = parse(["--ros-args", "-p", "talker:only:=1"])[0].for_node("talker", None)
    assert plain.params == {"only": 1}


def test_node_and_namespace_remaps_apply_to_every_node_without_a_prefix():
    ros, _ = parse(["--ros-args", "-r", "__node:=n1", "-r", "__ns:=/q"])
    node = ros.for_node("anything", "/elsewhere")
    assert (node.name, node.namespace) == ("n1", "/q")


def test_log_levels():
    ros, _ = parse(["--ros-args", "--log-level", "DEBUG", "--log-level", "talker:=warn"])
    assert ros.log_level == DEBUG
    assert ros.log_levels["talker"] == WARN


def test_accepted_flags_that_change_nothing_here():
    ros, rest = parse(
        [
            "p",
            "--ros-args",
            "--disable-rosout-logs",
            "--enable-stdout-logs",
            "-e",
            "/enclave",
            "--log-file-name",
            "x",
            "--log-config-file",
            "y",
        ]
    )
    assert rest == ["p"]
    assert ros.enclave == "/enclave"


@pytest.mark.parametrize(
    ("argv", "problem"),
    [
        (["--ros-args", "--bogus"], "unknown ROS arguments ['--bogus']"),
        (["--ros-args", "-p"], "-p needs a value"),
        (["--ros-args", "-p", "novalue"], "expected [node:]name:=value"),
        (["--ros-args", "-r", "foo"], "expected [node:]name:=value"),
        (["--ros-args", "-r", "a b:=c"], "remap source '/a b' is invalid"),
        (["--ros-args", "-r", "__node:=1bad"], "invalid node name"),
        (["--ros-args", "-p", "x:=[1, a]"], "one type"),
        (["--ros-args", "-p", "x:=[]"], "empty list"),
        (["--ros-args", "--log-level", "loud"], "unknown level 'loud'"),
        (["--ros-args", "--params-file", "/nonexistent/p.yaml"], "cannot read the parameter file"),
    ],
)
def test_bad_arguments_name_the_problem(argv, problem):
    with pytest.raises(RosArgsError, match=None) as info:
        parse(argv)
    assert problem in str(info.value)


def test_params_file_rules_in_file_order(params_file):
    rules = load_params_file(params_file)
    assert [r.node_key for r in rules] == ["/**", "/talker", "/robot1/driver", "/robot1/*"]
    assert parameters_for(params_file, "/talker") == {
        "everyone": 1,
        "speed": 0.5,
        "limits.max": [1.0, 2.5],
        "limits.name": "fast",
    }
    assert parameters_for(params_file, "/robot1/driver") == {"everyone": 1, "radius": 0.033, "in_robot1": True}
    assert parameters_for(params_file, "/robot2/talker") == {"everyone": 1}


def test_a_node_key_written_twice_keeps_both_entries(tmp_path):
    # rcl reads a parameter file as a stream: a key repeated at the top (or a namespace repeated)
    # adds to what the first one gave, where a plain YAML reading keeps only the last.
    path = tmp_path / "twice.yaml"
    path.write_text(
        "/**:\n  ros__parameters: {rate: 5}\n"
        "robots:\n  arm:\n    ros__parameters: {reach: 0.8}\n"
        "/**:\n  gripper:\n    ros__parameters: {force: 2.0}\n"
        "robots:\n  gripper:\n    ros__parameters: {force: 3.5, width: 0.1}\n"
        "robots:\n  arm:\n    ros__parameters: {reach: 0.9}\n"
    )
    assert parameters_for(path, "/robots/arm") == {"rate": 5, "reach": 0.9}
    assert parameters_for(path, "/robots/gripper") == {"rate": 5, "force": 3.5, "width": 0.1}
    assert parameters_for(path, "/gripper") == {"rate": 5, "force": 2.0}
    # The first place a key was written keeps its turn: /** first, so every node key after it wins.
    assert [rule.node_key for rule in load_params_file(path)] == [
        "/**",
        "/**/gripper",
        "/robots/arm",
        "/robots/gripper",
    ]


def test_a_params_file_with_an_unhashable_key_is_one_clear_error(tmp_path):
    # Reading repeated keys as rcl does must not lose YAML's own refusal of a key that is a list.
    path = tmp_path / "badkey.yaml"
    path.write_text("/**:\n  ros__parameters:\n    [a, b]: 1\n")
    with pytest.raises(RosArgsError, match="not valid YAML: found unhashable key"):
        load_params_file(path)


def test_params_files_and_rules_later_win(params_file):
    ros, _ = parse(["--ros-args", "-p", "speed:=9.0", "--params-file", str(params_file), "-p", "everyone:=3"])
    assert ros.for_node("talker", None).params["speed"] == 0.5
    assert ros.for_node("talker", None).params["everyone"] == 3


@pytest.mark.parametrize(
    ("key", "fqn", "matches"),
    [
        ("talker", "/talker", True),
        ("talker", "/ns/talker", False),
        ("/**", "/a/b/c", True),
        ("/ns/*", "/ns/talker", True),
        ("/ns/*", "/ns/deeper/talker", False),
        ("/ns/**", "/ns/deeper/talker", True),
        ("/**/talker", "/a/b/talker", True),
        ("/*/talker", "/talker", False),
    ],
)
def test_node_keys_match_as_rclpy_matches_them(key, fqn, matches):
    assert node_key_matches(key, fqn) is matches


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("[1, 2]", "expected node names as keys at the top"),
        ("talker: 3", "talker: expected a namespace or a node holding ros__parameters"),
        ("ros__parameters: {a: 1}", "needs a node name above it"),
        ("talker:\n  ros__parameters: 5", "talker/ros__parameters: expected a table"),
        ("talker:\n  ros__parameters:\n    a: [1, 2.5]", "one type"),
        ("talker:\n  ros__parameters:\n    a: null", "a parameter holds"),
        ("1bad:\n  ros__parameters: {a: 1}", "'1bad' is not a valid node name"),
        ("a: [", "not valid YAML"),
    ],
)
def test_malformed_params_files_name_file_and_key(tmp_path, text, problem):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(RosArgsError) as info:
        load_params_file(path)
    assert str(info.value).startswith(f"{path}: ")
    assert problem in str(info.value)


def test_an_empty_params_file_has_no_rules(tmp_path):
    path = tmp_path / "empty.yaml"
    path.write_text("")
    assert load_params_file(path) == []


RCLPY_PROBE = textwrap.dedent(
    """
    import json, sys, rclpy
    from rclpy.node import Node
    rclpy.init(args=sys.argv)
    out = {"rest": rclpy.utilities.remove_ros_args(sys.argv)[1:]}
    for name, ns in [("talker", None), ("driver", "/robot1"), ("listener", "/robot2")]:
        n = Node(name, namespace=ns, automatically_declare_parameters_from_overrides=True)
        params = {p: n.get_parameter(p).value for p in n._parameters
                  if p not in ("use_sim_time", "start_type_description_service")}
        out[name] = [n.get_name(), n.get_namespace(), n.resolve_topic_name("chatter"), params]
        n.destroy_node()
    rclpy.shutdown()
    print(json.dumps(out))
    """
)


def test_same_result_as_rclpy(tmp_path, params_file):
    pytest.importorskip("rclpy")
    argv = [
        "prog",
        "x",
        "--ros-args",
        "-p",
        "g:=5",
        "-p",
        "talker:only:=yes",
        "-r",
        "chatter:=ch",
        "-r",
        "listener:__node:=hearer",
        "-r",
        "driver:chatter:=/abs",
        "--params-file",
        str(params_file),
        "--",
        "y",
    ]
    env = {
        **os.environ,
        "ROS_LOG_DIR": str(tmp_path),
        "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp",
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
    }
    probe = tmp_path / "probe.py"
    probe.write_text(RCLPY_PROBE)
    done = subprocess.run([sys.executable, str(probe), *argv[1:]], capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout.splitlines()[-1])
    ros, rest = parse(argv)
    assert rest[1:] == expected["rest"]
    for name, ns in [("talker", None), ("driver", "/robot1"), ("listener", "/robot2")]:
        node = ros.for_node(name, ns)
        from actors.ros.names import Resolver

        topic = Resolver(node.namespace, node.name, node.remap).resolve("chatter")
        assert [node.name, node.namespace, topic, node.params] == expected[name]


def test_the_first_matching_remap_of_a_name_wins():
    ros, _ = parse(
        ["--ros-args", "-r", "chatter:=first", "-r", "chatter:=second", "-r", "__node:=a", "-r", "__node:=b"]
    )
    node = ros.for_node("n", None)
    assert (node.name, node.remap) == ("a", {"chatter": "first"})
