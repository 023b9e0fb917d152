"""rclpy's parameter helpers and AsyncParameterClient on a script node."""

from __future__ import annotations

from typing import Any

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.parameter import (
    Parameter,
    ParameterType,
    get_parameter_value,
    parameter_dict_from_yaml_file,
    parameter_value_to_python,
)
from actors.compat.rclpy.parameter_client import AsyncParameterClient
from actors.ros.node import Node as NativeNode
from interfaces.rcl_interfaces.msg import ParameterValue

PARAMS = """\
/**:
  ros__parameters: {shared: 1}
blackboard:
  ros__parameters: {int_parameter: 3, nested: {text: hi}}
other:
  ros__parameters: {x: 2.5}
"""


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


class Blackboard(NativeNode):
    def __init__(self) -> None:
        super().__init__(
            "blackboard", allow_undeclared_parameters=True, automatically_declare_parameters_from_overrides=True
        )


CASES = [
    {"target_nodes": ["blackboard"]},
    {"target_nodes": ["/blackboard"], "use_wildcard": True},
    {"target_nodes": ["blackboard", "other"], "namespace": "ns."},
    {"target_nodes": ["/robot/driver"]},
    {"use_wildcard": True},
]
NESTED = PARAMS + "/robot:\n  driver:\n    ros__parameters: {radius: 0.5}\n"


def _names(found: dict[str, Any]) -> dict[str, Any]:
    return {name: parameter_value_to_python(msg.value) for name, msg in found.items()}


def test_parameter_dict_from_yaml_file(tmp_path):
    path = tmp_path / "p.yaml"
    path.write_text(NESTED)
    assert _names(parameter_dict_from_yaml_file(path, target_nodes=["blackboard"])) == {
        "int_parameter": 3,
        "nested.text": "hi",
    }
    assert _names(parameter_dict_from_yaml_file(path, True, ["/blackboard"])) == {
        "shared": 1,
        "int_parameter": 3,
        "nested.text": "hi",
    }
    assert _names(parameter_dict_from_yaml_file(path, target_nodes=["/robot/driver"])) == {"radius": 0.5}
    # As Kilted's rclpy: no target node reads no node; a node the file lacks is skipped.
    with pytest.raises(RuntimeError, match="does not contain any valid parameters"):
        parameter_dict_from_yaml_file(path)
    with pytest.raises(RuntimeError, match="does not contain any valid parameters"):
        parameter_dict_from_yaml_file(path, target_nodes=["missing"])


def test_parameter_dict_from_yaml_file_as_rclpy_reads_it(tmp_path):
    pytest.importorskip("rclpy")
    import json
    import subprocess
    import sys

    path = tmp_path / "p.yaml"
    path.write_text(NESTED)
    probe = (
        "import json, sys\nfrom rclpy.parameter import parameter_dict_from_yaml_file, parameter_value_to_python\n"
        "out = []\nfor case in json.loads(sys.argv[2]):\n    try:\n"
        "        found = parameter_dict_from_yaml_file(sys.argv[1], **case)\n"
        "        out.append({k: parameter_value_to_python(v.value) for k, v in found.items()})\n"
        "    except RuntimeError as exc:\n        out.append(str(exc))\nprint(json.dumps(out))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", probe, str(path), json.dumps(CASES)], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    ours = []
    for case in CASES:
        try:
            ours.append(_names(parameter_dict_from_yaml_file(path, **case)))
        except RuntimeError as exc:
            ours.append(str(exc))
    assert ours == expected


@pytest.mark.parametrize(
    ("text", "value"),
    [("2", 2), ("2.5", 2.5), ("true", True), ("[1, 2]", [1, 2]), ("hello", "hello"), ("a: [", "a: [")],
)
def test_get_parameter_value_reads_yaml(text, value):
    assert parameter_value_to_python(get_parameter_value(text)) == value


@pytest.mark.parametrize(
    ("text", "type_", "value"),
    [
        # What YAML reads as nothing, a list of mixed items or a mapping stays the text, a STRING.
        ("", ParameterType.STRING, ""),
        (" ", ParameterType.STRING, " "),
        ("null", ParameterType.STRING, "null"),
        ("[1, 2.5]", ParameterType.STRING, "[1, 2.5]"),
        ("{a: 1}", ParameterType.STRING, "{a: 1}"),
        ("2001-12-14", ParameterType.STRING, "2001-12-14"),
        ("[]", ParameterType.BOOL_ARRAY, []),  # the first list type an empty list fits
        ("[a, b]", ParameterType.STRING_ARRAY, ["a", "b"]),
        ("[0.5, 1.5]", ParameterType.DOUBLE_ARRAY, [0.5, 1.5]),
    ],
)
def test_get_parameter_value_types_text_as_rclpy_guesses(text, type_, value):
    guessed = get_parameter_value(text)
    assert guessed.type == type_
    assert parameter_value_to_python(guessed) == value


def test_get_parameter_value_equals_a_message_built_from_the_same_list():
    assert get_parameter_value("[4, 5]") == ParameterValue(type=ParameterType.INTEGER_ARRAY, integer_array_value=[4, 5])


def test_parameter_value_to_python_gives_lists_and_refuses_unknown_types():
    ints = parameter_value_to_python(ParameterValue(type=ParameterType.INTEGER_ARRAY, integer_array_value=[7, 8]))
    assert type(ints) is list and ints == [7, 8]
    raw = ParameterValue(type=ParameterType.BYTE_ARRAY, byte_array_value=b"ok")
    assert parameter_value_to_python(raw) == [b"o", b"k"]  # rclpy's byte[] items: one-byte bytes
    assert parameter_value_to_python(ParameterValue()) is None
    with pytest.raises(RuntimeError, match="unexpected parameter type 42"):
        parameter_value_to_python(ParameterValue(type=42))


def test_async_parameter_client_with_rclpy_futures(session, tmp_path):
    session.call(session.runtime.spawn, Blackboard)
    node = rclpy.create_node("asker")
    client = AsyncParameterClient(node, "blackboard")
    assert client.wait_for_services(3.0)

    def finish(future: Any) -> Any:
        rclpy.spin_until_future_complete(node, future)
        return future.result()

    done: list[Any] = []
    result = finish(
        client.set_parameters([Parameter("int_parameter", Parameter.Type.INTEGER, 10)], callback=done.append)
    )
    assert [r.successful for r in result.results] == [True]
    rclpy.spin_once(node, timeout_sec=0)  # the done callback is a task of the node's executor, as in rclpy
    assert len(done) == 1
    path = tmp_path / "p.yaml"
    path.write_text(PARAMS)
    loaded = finish(client.load_parameter_file(path))  # the blackboard's entry: int_parameter and nested
    assert all(r.successful for r in loaded.results)
    finish(client.set_parameters([Parameter("x", Parameter.Type.DOUBLE, 2.5)]))
    got = finish(client.get_parameters(["int_parameter", "x", "nested.text"]))
    assert [parameter_value_to_python(v) for v in got.values] == [3, 2.5, "hi"]
    deleted = finish(client.delete_parameters(["x"]))
    assert deleted.results[0].successful
    listed = finish(client.list_parameters(["nested"], 10))
    assert listed.result.names == ["nested.text"]


def test_wait_for_services_times_out_in_virtual_seconds(session):
    node = rclpy.create_node("asker")
    client = AsyncParameterClient(node, "nobody")
    start = session.loop.time()
    assert client.wait_for_services(2.0) is False
    assert session.loop.time() - start == pytest.approx(2.0)


def test_declaring_a_name_alone_warns_as_rclpy_does(session):
    node = rclpy.create_node("terse")
    with pytest.warns(UserWarning, match="'bare', declaring a parameter only providing its name is deprecated"):
        node.declare_parameter("bare")
    with pytest.warns(UserWarning, match="'group.lone'"):
        node.declare_parameters("group", [("lone",), ("given", 3)])
    assert node.get_parameter("group.given").value == 3


def test_the_callback_lists_hold_the_newest_first(session):
    node = rclpy.create_node("listed")

    def first(params):
        return params

    def second(params):
        return params

    node.add_pre_set_parameters_callback(first)
    node.add_pre_set_parameters_callback(second)
    assert node._pre_set_parameters_callbacks == [second, first]
    node.remove_pre_set_parameters_callback(second)
    assert node._pre_set_parameters_callbacks == [first]
    assert first not in node._on_set_parameters_callbacks + node._post_set_parameters_callbacks
    # A pre-set callback that leaves nothing to set fails the set, in rclpy's words.
    node.remove_pre_set_parameters_callback(first)
    node.add_pre_set_parameters_callback(lambda params: [])
    node.declare_parameter("speed", 1)
    (result,) = node.set_parameters([Parameter("speed", value=2)])
    assert not result.successful and result.reason.startswith("parameter list cannot be empty")


def test_graph_queries_rclpy_adds(session):
    node = rclpy.create_node("asker", namespace="/deep")
    assert ("asker", "/deep", "/") in node.get_node_names_and_namespaces_with_enclaves()
    assert node.get_topic_names_and_types(no_demangle=True) == node.get_topic_names_and_types()
