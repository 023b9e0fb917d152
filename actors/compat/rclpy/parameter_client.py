"""``rclpy.parameter_client``: AsyncParameterClient with rclpy's Futures and a blocking wait.

The native client builds the requests; here its service clients are the
script node's (their Futures are rclpy's, done once the node is spun), a
``callback=`` is a done callback of that Future, and ``load_parameter_file``
reads ROS parameter files.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any, cast

from actors.compat.rclpy.parameter import parameter_dict_from_yaml_file
from actors.compat.rclpy.task import Future
from actors.ros.param_client import AsyncParameterClient as NativeParameterClient

__all__ = ["AsyncParameterClient"]


class AsyncParameterClient(NativeParameterClient):
    """A client of the parameter services of the node ``remote_node_name``, for a script node."""

    def _call(self, client: Any, request: Any, callback: Callable[[Any], Any] | None) -> Any:
        # The script node's client: its call_async gives rclpy's Future, which ``callback`` is given.
        future = client.call_async(request)
        if callback is not None:
            future.add_done_callback(callback)
        return future

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:  # type: ignore[override]  # rclpy's: blocking
        """Wait until every parameter service exists (``timeout_sec`` of runtime clock at most)."""
        session = self.node._rclpy.session
        end = None if timeout_sec is None else session.loop.time() + timeout_sec
        for client in self._clients:
            left = None if end is None else max(0.0, end - session.loop.time())
            if not client.wait_for_service(timeout_sec=left):
                return False
        return True

    def load_parameter_file(
        self, parameter_file: str | Path, use_wildcard: bool = False, callback: Any = None
    ) -> Future[Any]:
        """Set the parameters a ROS parameter file holds for the remote node (and ``/**``'s with ``use_wildcard``)."""
        parameters = self._file_parameters(parameter_file, use_wildcard)
        return cast("Future[Any]", self.set_parameters(parameters, callback))  # rclpy's, from _call

    def load_parameter_file_atomically(
        self, parameter_file: str | Path, use_wildcard: bool = False, callback: Any = None
    ) -> Future[Any]:
        """As :meth:`load_parameter_file`, all or none."""
        parameters = self._file_parameters(parameter_file, use_wildcard)
        return cast("Future[Any]", self.set_parameters_atomically(parameters, callback))  # likewise

    def _file_parameters(self, parameter_file: str | Path, use_wildcard: bool) -> list[Any]:
        found = parameter_dict_from_yaml_file(parameter_file, use_wildcard, target_nodes=[self.remote_node_name])
        return list(found.values())
