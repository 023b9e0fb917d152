"""``actors pkg list|executables|prefix|xml|create``: ROS packages, as ``ros2 pkg`` shows and makes them.

``list``, ``executables [PKG] [--full-path]``, ``prefix PKG [--share]`` and
``xml PKG [--tag TAG]`` print what ``ros2 pkg`` prints, for the packages of the
workspace, the shipped ones and ``AMENT_PREFIX_PATH``'s
(:mod:`actors.launch.packages`); a package not found is one line, exit 2.

``create NAME`` writes a package.  With ``--build-type ament_python`` it is
the layout ``ros2 pkg create --build-type ament_python`` writes (``package.xml``,
``setup.py``, ``setup.cfg``, ``resource/NAME``, ``NAME/__init__.py`` and, with
``--node-name N``, ``NAME/N.py`` whose ``main`` is the console script ``N``),
which runs at once with ``actors run NAME N`` from its workspace: no build
step.  ament's lint tests (``test/test_flake8.py``...) are left out: they need
ament's linters.  The default build type, ``actors``, writes a package of
actors nodes, runnable and tested as made::

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
import getpass
import importlib.util
import keyword
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import Any

from actors.errors import ControlError, PackageError

__all__ = ["register", "create", "list_packages", "executables", "prefix", "xml"]


def register(subparsers: Any) -> None:
    """Add the ``pkg`` group and its verbs."""
    parser = subparsers.add_parser("pkg", help="list, inspect and create packages")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    verbs.add_parser("list", help="output a list of available packages").set_defaults(func=list_packages)
    executables_ = verbs.add_parser("executables", help="output a list of package specific executables")
    executables_.add_argument("package_name", nargs="?", metavar="PKG", help="the package (default: every one)")
    executables_.add_argument("--full-path", action="store_true", help="show the full path of each executable")
    executables_.set_defaults(func=executables)
    prefix_ = verbs.add_parser("prefix", help="output the prefix path of a package")
    prefix_.add_argument("package_name", metavar="PKG")
    prefix_.add_argument("--share", action="store_true", help="show the package's share directory")
    prefix_.set_defaults(func=prefix)
    xml_ = verbs.add_parser("xml", help="output the XML of the package manifest or a specific tag")
    xml_.add_argument("package_name", metavar="PKG")
    xml_.add_argument("-t", "--tag", help="the XML tag to output (e.g. 'version')")
    xml_.set_defaults(func=xml)
    create_ = verbs.add_parser(
        "create", help="write a package: ament_python as ros2 makes it, or actors nodes with a graph and a test"
    )
    create_.add_argument("package_name", metavar="NAME", help="e.g. my_pkg (lower case, digits, _)")
    create_.add_argument(
        "--build-type",
        choices=("actors", "ament_python"),
        default="actors",
        help="ament_python: the layout of ros2 pkg create --build-type ament_python, run by actors run NAME N; "
        "actors (default): actors nodes with a graph file and a test",
    )
    create_.add_argument("--node-name", metavar="N", help="the node's name and module (default: NAME_node)")
    create_.add_argument(
        "--destination-directory",
        default=".",
        metavar="DIR",
        help="where to create the package's folder (default: here)",
    )
    create_.add_argument("--description", default="TODO: Package description", help="ament_python: package.xml's")
    create_.add_argument("--license", default="TODO: License declaration", help="ament_python: package.xml's")
    create_.add_argument("--maintainer-name", default=getpass.getuser(), help="ament_python: package.xml's")
    create_.add_argument("--maintainer-email", help="ament_python: package.xml's (default: NAME@todo.todo)")
    create_.add_argument("--dependencies", nargs="+", default=[], metavar="DEP", help="ament_python: <depend>s")
    create_.set_defaults(func=create)


def list_packages(args: argparse.Namespace) -> None:
    """Every package's name, sorted."""
    from actors.launch.packages import packages

    for name in packages():
        print(name)


def executables(args: argparse.Namespace) -> None:
    """``PKG EXE`` per executable (of one package, or all), or each one's path with ``--full-path``."""
    from actors.launch.packages import find_package, packages

    found = [find_package(args.package_name)] if args.package_name else list(packages().values())
    for package in found:
        for name, executable in package.executables().items():
            if args.full_path:
                print(executable.path or (package.prefix / "lib" / package.name / name))
            else:
                print(package.name, name)


def prefix(args: argparse.Namespace) -> None:
    """The package's prefix, or its share directory."""
    from actors.launch.packages import find_package

    package = find_package(args.package_name)
    print(package.share if args.share else package.prefix)


def xml(args: argparse.Namespace) -> None:
    """The package's manifest, or the text of each element ``--tag`` names."""
    from actors.launch.packages import find_package

    manifest = find_package(args.package_name).manifest
    try:
        tree = ElementTree.parse(manifest)
    except (ElementTree.ParseError, OSError) as exc:
        raise PackageError(f"{manifest}: not a package manifest: {exc}") from None
    if args.tag is None:
        sys.stdout.write(manifest.read_text(encoding="utf-8"))
        return
    elements = tree.getroot().findall(args.tag)
    if not elements:
        raise PackageError(f"{manifest}: XML tag not found: {args.tag}")
    for element in elements:
        print(element.text)


def create(args: argparse.Namespace) -> None:
    """Write the package; ControlError (exit 2) for a bad name or an existing folder."""
    from actors.messages.idl import PACKAGE_NAME
    from actors.ros.names import validate_node_name

    package = args.package_name
    ament = args.build_type == "ament_python"
    node = args.node_name or (None if ament else f"{package}_node")
    if not PACKAGE_NAME.fullmatch(package) or "__" in package or package.endswith("_"):
        raise ControlError(
            f"invalid package name {package!r}: lower-case letters, digits and single "
            "underscores, starting with a letter (e.g. my_pkg)"
        )
    if node is not None:
        validate_node_name(node)  # InvalidNameError says what is wrong
    for name, what in ((package, "package"), (node, "node")):
        if name is not None and (keyword.iskeyword(name) or name in ("tests", "test")):
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
    print("going to create a new package")
    print(f"package name: {package}")
    print(f"destination directory: {Path(args.destination_directory).resolve()}")
    if ament:
        email = args.maintainer_email or f"{args.maintainer_name}@todo.todo"
        print("package format: 3")
        print("version: 0.0.0")
        print(f"description: {args.description}")
        print(f"maintainer: [{f'{args.maintainer_name} <{email}>'!r}]")
        print(f"licenses: [{args.license!r}]")
        print("build type: ament_python")
        print(f"dependencies: {args.dependencies!r}")
        values = {
            "package": package,
            "node": node or "",
            "description": args.description,
            "license": args.license,
            "maintainer": args.maintainer_name,
            "email": email,
            "depends": "".join(f"  <depend>{dep}</depend>\n" for dep in args.dependencies),
            "scripts": f"\n            '{node} = {package}.{node}:main'," if node else "",
        }
        templates = {**_AMENT, **(_AMENT_NODE if node else {})}
        folders = (root, root / package, root / "resource")
    else:
        values = {"package": package, "node": node or "", "cls": "".join(p.title() for p in (node or "").split("_"))}
        templates = _TEMPLATES
        folders = (root, root / package, root / "tests")
    if node:
        print(f"node_name: {node}")
    files = {name.format(**values): text.format(**values) for name, text in templates.items()}
    for folder in folders:
        print(f"creating folder {folder}")
        folder.mkdir(parents=True)
    for relative, text in files.items():
        path = root / relative
        print(f"creating {path}")
        path.write_text(text, encoding="utf-8")


_AMENT = {
    "package.xml": """\
<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
<package format="3">
  <name>{package}</name>
  <version>0.0.0</version>
  <description>{description}</description>
  <maintainer email="{email}">{maintainer}</maintainer>
  <license>{license}</license>

{depends}
  <test_depend>ament_copyright</test_depend>
  <test_depend>ament_flake8</test_depend>
  <test_depend>ament_pep257</test_depend>
  <test_depend>python3-pytest</test_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
""",
    "resource/{package}": "",
    "setup.cfg": """\
[develop]
script_dir=$base/lib/{package}
[install]
install_scripts=$base/lib/{package}
""",
    "setup.py": """\
from setuptools import find_packages, setup

package_name = '{package}'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='{maintainer}',
    maintainer_email='{email}',
    description='{description}',
    license='{license}',
    entry_points={{
        'console_scripts': [{scripts}
        ],
    }},
)
""",
    "{package}/__init__.py": "",
}

_AMENT_NODE = {
    "{package}/{node}.py": """\
def main():
    print('Hi from {package}.')


if __name__ == '__main__':
    main()
""",
}


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
