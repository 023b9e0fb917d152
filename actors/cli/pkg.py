"""``actors pkg create NAME [--node-name N]``: a package of one's own, runnable and tested as made.

What ``ros2 pkg create --build-type ament_python`` is to a ROS workspace: a
folder with a node (a publisher on a timer, with a parameter), the graph file
that runs it, a test of it on the virtual clock, a README, and a
``pyproject.toml`` (pytest's settings, and ``pip install -e .`` if wanted)::

    my_pkg/
      README.md  graph.toml  pyproject.toml
      my_pkg/__init__.py  my_pkg/my_node.py
      tests/test_my_node.py

It prints what it does as ``ros2 pkg create`` does.  A name that is not a
ROS package (or node) name, a name some importable module already has, or a
folder that exists is refused with one line (exit 2), and nothing is written.
"""

from __future__ import annotations

import argparse
import importlib.util
import keyword
from pathlib import Path
from typing import Any

from actors.errors import ControlError

__all__ = ["register", "create"]


def register(subparsers: Any) -> None:
    """Add the ``pkg`` group and its ``create`` verb."""
    parser = subparsers.add_parser("pkg", help="create a package of your own")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    create_ = verbs.add_parser(
        "create", help="write a package: a node, its graph, a test on the virtual clock, a README"
    )
    create_.add_argument("package_name", metavar="NAME", help="e.g. my_pkg (lower case, digits, _)")
    create_.add_argument("--node-name", metavar="N", help="the node's name and module (default: NAME_node)")
    create_.add_argument(
        "--destination-directory",
        default=".",
        metavar="DIR",
        help="where to create the package's folder (default: here)",
    )
    create_.set_defaults(func=create)


def create(args: argparse.Namespace) -> None:
    """Write the package; ControlError (exit 2) for a bad name or an existing folder."""
    from actors.messages.idl import PACKAGE_NAME
    from actors.ros.names import validate_node_name

    package = args.package_name
    node = args.node_name or f"{package}_node"
    if not PACKAGE_NAME.fullmatch(package) or "__" in package or package.endswith("_"):
        raise ControlError(
            f"invalid package name {package!r}: lower-case letters, digits and single "
            "underscores, starting with a letter (e.g. my_pkg)"
        )
    validate_node_name(node)  # InvalidNameError says what is wrong
    for name, what in ((package, "package"), (node, "node")):
        if keyword.iskeyword(name) or name in ("tests", "test"):
            raise ControlError(f"{what} name {name!r} cannot be a Python module's: choose another")
    if node == package:
        raise ControlError(f"the node cannot be named as its package ({package!r}): choose another")
    root = Path(args.destination_directory) / package
    if root.exists():
        raise ControlError(f"{root} already exists: remove it, or choose another name or --destination-directory")
    spec = importlib.util.find_spec(package)
    if spec is not None:
        where = spec.origin or ", ".join(spec.submodule_search_locations or ())
        raise ControlError(
            f"a module named {package!r} can already be imported ({where}): your package would "
            "hide it or be hidden by it; choose another name"
        )
    files = _files(package, node, "".join(part.title() for part in node.split("_")))
    print("going to create a new package")
    print(f"package name: {package}")
    print(f"destination directory: {Path(args.destination_directory).resolve()}")
    print(f"node_name: {node}")
    for folder in (root, root / package, root / "tests"):
        print(f"creating folder {folder}")
        folder.mkdir(parents=True)
    for relative, text in files.items():
        path = root / relative
        print(f"creating {path}")
        path.write_text(text, encoding="utf-8")


def _files(package: str, node: str, cls: str) -> dict[str, str]:
    """Each file of the package, by its path in the package's folder."""
    values = {"package": package, "node": node, "cls": cls}
    return {name.format(**values): text.format(**values) for name, text in _TEMPLATES.items()}


_TEMPLATES = {
    "README.md": """\
# {package}

A package of actors nodes, made by `actors pkg create`.

- `{package}/{node}.py`: the node `{node}` (class `{cls}`), which publishes a greeting on
  `chatter` once a second; the text comes from its parameter `greeting`
- `graph.toml`: the graph that runs it (add your other nodes there)
- `tests/test_{node}.py`: its test, on the virtual clock

Run the graph (Ctrl-C stops it), or for 3 seconds of virtual time:

```sh
python -m actors.run graph.toml
python -m actors.run graph.toml --clock virtual --duration 3
```

Test it (pytest and pytest-asyncio 1.4+ installed: `pip install -e '.[test]'`):

```sh
python -m pytest
```
""",
    "pyproject.toml": """\
[build-system]
requires = ["setuptools>=69"]
build-backend = "setuptools.build_meta"

[project]
name = "{package}"
version = "0.0.0"
description = "TODO: Package description"
requires-python = ">=3.11"
dependencies = ["actors"]

[project.optional-dependencies]
test = ["pytest>=8.4", "pytest-asyncio>=1.4"]

[tool.setuptools.packages.find]
include = ["{package}*"]

[tool.pytest.ini_options]
testpaths = ["tests"]
pythonpath = ["."]
asyncio_default_fixture_loop_scope = "function"
""",
    "graph.toml": """\
# The package's graph: python -m actors.run graph.toml (or: actors launch graph.toml)
[runtime]
clock = "wall"

[[nodes]]
use = "{package}.{node}:{cls}"
params = {{ greeting = "Hello from {node}" }}
""",
    "{package}/__init__.py": '"""The nodes of the package {package}."""\n',
    "{package}/{node}.py": '''\
"""The node {node}: publishes a greeting on ``chatter`` once a second."""

from actors import Node
from interfaces.std_msgs.msg import String


class {cls}(Node):
    """Publishes ``<greeting>: <count>`` on ``chatter`` every second; ``greeting`` is a parameter."""

    def __init__(self):
        super().__init__("{node}")
        self.declare_parameter("greeting", "Hello")
        self.publisher = self.create_publisher(String, "chatter", 10)
        self.timer = self.create_timer(1.0, self.timer_callback)
        self.count = 0

    def timer_callback(self):
        msg = String(data=f"{{self.get_parameter('greeting').value}}: {{self.count}}")
        self.publisher.publish(msg)
        self.get_logger().info(f'Publishing: "{{msg.data}}"')
        self.count += 1
''',
    "tests/test_{node}.py": '''\
"""{node} on the virtual clock: seconds of graph time take milliseconds."""

import anyio
import pytest

from actors import Node, Runtime
from interfaces.std_msgs.msg import String
from {package}.{node} import {cls}


class Recorder(Node):
    """Keeps what arrives on ``chatter``."""

    def __init__(self):
        super().__init__("recorder")
        self.heard = []
        self.create_subscription(String, "chatter", lambda msg: self.heard.append(msg.data), 10)


@pytest.mark.virtual_time
async def test_{node}_publishes_its_greeting_once_a_second():
    async with Runtime() as rt:
        recorder = rt.spawn(Recorder)
        rt.spawn({cls}, params={{"greeting": "Hi"}})
        await anyio.sleep(3.5)
    assert recorder.heard == ["Hi: 0", "Hi: 1", "Hi: 2"]
''',
}
