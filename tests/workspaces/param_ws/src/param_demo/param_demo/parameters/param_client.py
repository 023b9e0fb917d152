"""Sets, lists, reads, loads from a file and deletes the blackboard's parameters through AsyncParameterClient."""

import os
import sys

import rclpy
from ament_index_python import get_package_share_directory
from rclpy.parameter import Parameter, parameter_dict_from_yaml_file, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient


def ask(node, future):
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def main():
    file_name = sys.argv[1] if len(sys.argv) > 1 else "params.yaml"
    with rclpy.init():
        node = rclpy.create_node("param_client")
        log = node.get_logger()
        client = AsyncParameterClient(node, "parameter_blackboard")
        if not client.wait_for_services(3.0):
            raise RuntimeError("no parameter_blackboard")
        names = ["speed", "name"]
        done = ask(node, client.set_parameters([Parameter("speed", value=1), Parameter("name", value="set")]))
        log.info(f"set: {[result.successful for result in done.results]}")
        log.info(f"listed: {list(ask(node, client.list_parameters(names, 10)).result.names)}")
        values = ask(node, client.get_parameters(names)).values
        log.info(f"got: {[parameter_value_to_python(value) for value in values]}")
        path = os.path.join(get_package_share_directory("param_demo"), file_name)
        loaded = ask(node, client.load_parameter_file(path))
        from_file = parameter_dict_from_yaml_file(path, target_nodes=["parameter_blackboard"])
        for (name, parameter), result in zip(from_file.items(), loaded.results):
            log.info(f"loaded {name} = {parameter_value_to_python(parameter.value)}: {result.successful}")
        deleted = ask(node, client.delete_parameters(["enabled"]))
        log.info(f"deleted: {[(result.successful, result.reason) for result in deleted.results]}")
