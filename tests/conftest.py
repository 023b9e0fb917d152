"""Shared test helpers: running ``python -m`` commands in a subprocess, bounded in time."""

from __future__ import annotations

import asyncio
import io
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
TESTS = Path(__file__).resolve().parent


def pytest_configure(config: pytest.Config) -> None:
    # Types made from workspaces and bags go to a folder of this run, child processes' too, never
    # the user's cache: set before collection, which already lists types (test_codec's parameters).
    cache = tempfile.mkdtemp(prefix="actors-interface-cache-")
    os.environ["ACTORS_INTERFACE_CACHE"] = cache
    config.add_cleanup(lambda: shutil.rmtree(cache, ignore_errors=True))
    # Graphs of one run find each other's control sockets here, not among the user's graphs nor
    # another worker's (pytest -n): a second graph of a name in use would warn in its output.
    sockets = tempfile.mkdtemp(prefix="actors-run-")  # short: a socket's path holds 108 bytes
    os.environ["XDG_RUNTIME_DIR"] = sockets
    config.add_cleanup(lambda: shutil.rmtree(sockets, ignore_errors=True))
    config.addinivalue_line(
        "markers",
        "slow: a test that takes about a third of a second or more (a child Python, a wall-clock wait); "
        "the quick lane leaves them out: pytest -m 'not slow'",
    )


def python_env() -> dict[str, str]:
    """The environment for a child Python: the repo and the test nodes importable."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), str(TESTS), env.get("PYTHONPATH", "")])
    env["PYTHONUNBUFFERED"] = "1"
    return env


@pytest.fixture
def run_module():
    """Run ``python -m MODULE ARGS`` from the repo root; returns the CompletedProcess."""

    def run(module: str, *args: str, timeout: float = 60) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", module, *args],
            cwd=ROOT,
            env=python_env(),
            capture_output=True,
            text=True,
            timeout=timeout,
        )

    return run


def live_loop_timers() -> list[asyncio.TimerHandle]:
    """The running loop's timers that are still armed (asyncio keeps cancelled ones until they come up)."""
    return [h for h in asyncio.get_running_loop()._scheduled if not h.cancelled()]  # type: ignore[attr-defined]


def read_bag(path: Path) -> Any:
    """An MCAP reader of the bag at ``path``, read whole into memory (a test's bags are small).

    Synchronous on purpose: an async test calls it once its graph has stopped, with nothing left on
    the loop to hold up, and a thread to read in would let a virtual-time loop move on meanwhile."""
    from mcap.reader import make_reader

    return make_reader(io.BytesIO(path.read_bytes()))


def generated_package(root: Path, package: str, messages: dict[str, str]) -> None:
    """Write ``messages`` (name -> .msg text) as ``package`` under the interface root ``root``,
    generate its module and register the root, so ``codec.get_type("package/msg/Name")`` finds them."""
    from actors import codec
    from actors.messages import generate as idl_gen

    folder = root / package / "msg"
    folder.mkdir(parents=True)
    for name, text in messages.items():
        (folder / f"{name}.msg").write_text(text)
    idl_gen.generate([root])
    codec.register_root(root)


def protobuf_class(name: str, file_descriptor_set: bytes) -> type:
    """The protobuf message class ``name`` as a serialized FileDescriptorSet (a protobuf schema) defines it."""
    from google.protobuf import descriptor_pb2, descriptor_pool, message_factory

    files = descriptor_pb2.FileDescriptorSet.FromString(file_descriptor_set)
    pool = descriptor_pool.DescriptorPool()
    message_factory.GetMessages(list(files.file), pool=pool)
    return message_factory.GetMessageClass(pool.FindMessageTypeByName(name))


@pytest.fixture
def rclpy_session(rclpy_overlay):
    """The virtual-clock Session under the plugin's rclpy_overlay: the test's thread is the script."""
    return rclpy_overlay.get_default_context().session
