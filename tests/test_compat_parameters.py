"""rclpy's parameter helpers and AsyncParameterClient on a script node."""

from __future__ import annotations

from typing import Any

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.parameter import (
    Parameter,
    get_parameter_value,
    parameter_dict_from_yaml_file,
    parameter_value_to_python,
)
from actors.compat.rclpy.parameter_client import AsyncParameterClient
from actors.node import Node as NativeNode

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
        super().__init__("blackboard", allow_undeclared_parameters=True,
                         automatically_declare_parameters_from_overrides=True)


def test_parameter_dict_from_yaml_file(tmp_path):
    path = tmp_path / "p.yaml"
    path.write_text(PARAMS)
    every = parameter_dict_from_yaml_file(path)
    assert sorted(every) == ["int_parameter", "nested.text", "shared", "x"]
    assert parameter_value_to_python(every["nested.text"].value) == "hi"
    one = parameter_dict_from_yaml_file(path, target_nodes=["blackboard"], namespace="ns")
    assert sorted(one) == ["ns.int_parameter", "ns.nested.text"]
    with_wildcard = parameter_dict_from_yaml_file(path, use_wildcard=True, target_nodes=["/blackboard"])
    assert sorted(with_wildcard) == ["int_parameter", "nested.text", "shared"]
    with pytest.raises(RuntimeError, match="does not contain parameters for"):
        parameter_dict_from_yaml_file(path, target_nodes=["missing"])


@pytest.mark.parametrize(("text", "value"), [("2", 2), ("2.5", 2.5), ("true", True), ("[1, 2]", [1, 2]),
                                             ("hello", "hello"), ("a: [", "a: [")])
def test_get_parameter_value_reads_yaml(text, value):
    assert parameter_value_to_python(get_parameter_value(text)) == value


def test_async_parameter_client_with_rclpy_futures(session, tmp_path):
    session.call(session.runtime.spawn, Blackboard)
    node = rclpy.create_node("asker")
    client = AsyncParameterClient(node, "blackboard")
    assert client.wait_for_services(3.0)

    def finish(future: Any) -> Any:
        rclpy.spin_until_future_complete(node, future)
        return future.result()

    done: list[Any] = []
    result = finish(client.set_parameters([Parameter("int_parameter", Parameter.Type.INTEGER, 10)],
                                          callback=done.append))
    assert [r.successful for r in result.results] == [True]
    rclpy.spin_once(node, timeout_sec=0)  # the done callback is a task of the node's executor, as in rclpy
    assert len(done) == 1
    path = tmp_path / "p.yaml"
    path.write_text(PARAMS)
    loaded = finish(client.load_parameter_file(path))
    assert all(r.successful for r in loaded.results)
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
