"""Reading an ament_python package's setup.py (with ast, never run) and setup.cfg (configparser)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from actors.errors import PackageError
from actors.launch.setup_files import parse_entry_point, read_setup


def package(tmp_path: Path, setup_py: str | None = None, setup_cfg: str | None = None) -> Path:
    (tmp_path / "launch").mkdir()
    (tmp_path / "config").mkdir()
    for name in ("launch/a.launch.py", "launch/b.launch.xml", "launch/notes.txt", "config/p.yaml", "package.xml"):
        (tmp_path / name).write_text("")
    if setup_py is not None:
        (tmp_path / "setup.py").write_text(textwrap.dedent(setup_py))
    if setup_cfg is not None:
        (tmp_path / "setup.cfg").write_text(textwrap.dedent(setup_cfg))
    return tmp_path


def test_the_forms_ros_packages_write_their_setup_py_in(tmp_path):
    folder = package(
        tmp_path,
        """\
        import os
        from glob import glob
        from setuptools import find_packages, setup

        package_name = 'demo'
        share = os.path.join('share', package_name)

        setup(
            name=package_name,
            packages=find_packages(exclude=['test']),
            data_files=[
                ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
                ('share/' + package_name, ['package.xml']),
                (os.path.join(share, 'launch'), glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
                (f'{share}/config', glob('config/*.yaml')),
            ],
            entry_points={'console_scripts': ['talker = demo.talker:main', 'node = demo.sub.node:Node']},
        )
        """,
    )
    info = read_setup(folder)
    assert info.name == "demo"
    assert info.console_scripts == {"talker": "demo.talker:main", "node": "demo.sub.node:Node"}
    assert info.data_files == [
        ("share/ament_index/resource_index/packages", ["resource/demo"]),
        ("share/demo", ["package.xml"]),
        ("share/demo/launch", ["launch/a.launch.py", "launch/b.launch.xml"]),
        ("share/demo/config", ["config/p.yaml"]),
    ]


def test_setup_py_is_never_run(tmp_path):
    folder = package(
        tmp_path,
        """\
        import os
        os.makedirs('ran')  # would be made if the file were executed
        from setuptools import setup
        setup(name='quiet', entry_points={'console_scripts': ['x = quiet.x:main']})
        """,
    )
    assert read_setup(folder).console_scripts == {"x": "quiet.x:main"}
    assert not (folder / "ran").exists()


@pytest.mark.parametrize(
    ("argument", "shown"),
    [
        ("data_files=make_list()", "make_list()"),
        ("data_files=[(d, ['package.xml']) for d in DIRS]", "[(d, ['package.xml']) for d in DIRS]"),
        ("name=NAME", "NAME"),
    ],
)
def test_what_cannot_be_read_without_running_it_is_named_with_file_and_line(tmp_path, argument, shown):
    folder = package(tmp_path, f"from setuptools import setup\n\nsetup(\n    {argument},\n)\n")
    with pytest.raises(PackageError) as caught:
        read_setup(folder)
    assert str(caught.value).startswith(f"{folder / 'setup.py'}:4: cannot read {shown!r} without running setup.py")


def test_setup_cfg_alone_and_beside_setup_py(tmp_path):
    cfg = """\
        [metadata]
        name = cfgpkg
        [options.entry_points]
        console_scripts =
            one = cfgpkg.one:main
            two = cfgpkg.two:main
        [options.data_files]
        share/cfgpkg = package.xml
        share/cfgpkg/launch = launch/*.launch.py
        """
    info = read_setup(package(tmp_path, setup_cfg=cfg))
    assert info.name == "cfgpkg"
    assert info.console_scripts == {"one": "cfgpkg.one:main", "two": "cfgpkg.two:main"}
    assert info.data_files == [("share/cfgpkg", ["package.xml"]), ("share/cfgpkg/launch", ["launch/a.launch.py"])]
    # setup.py's arguments win where both say something; what only setup.cfg says stays.
    (tmp_path / "setup.py").write_text(
        "from setuptools import setup\nsetup(entry_points={'console_scripts': ['two = other.two:main']})\n"
    )
    both = read_setup(tmp_path)
    assert both.console_scripts == {"one": "cfgpkg.one:main", "two": "other.two:main"}
    assert both.data_files == info.data_files


@pytest.mark.parametrize("text", ["nothing", "x = ", "x = 1bad:main", "x = mod:", "= mod:main"])
def test_a_malformed_console_script_is_refused(text):
    with pytest.raises(PackageError, match="not a console script"):
        parse_entry_point(text, "here")


def test_a_setup_py_that_is_not_python_names_its_line(tmp_path):
    folder = package(tmp_path, "from setuptools import setup\nsetup(name='x'\n")
    with pytest.raises(PackageError, match=rf"^{folder / 'setup.py'}:2: "):
        read_setup(folder)
