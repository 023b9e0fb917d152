"""Packages as ros2 and ament_index see them: a workspace's, the shipped ones, AMENT_PREFIX_PATH's (issue 31).

The greeter workspace (tests/workspaces/greeter_ws) is ours: two ament_python
packages with setup.py entry points and an interface package beside them;
``greeter`` installs ``config/params.yaml`` and its launch files through
``data_files`` as colcon would.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import pytest
from conftest import TESTS

from actors.cli import main
from actors.compat.overlay import overlaid
from actors.errors import PackageError
from actors.launch.packages import find_executable, find_package, packages, search_paths

WORKSPACE = TESTS / "workspaces" / "greeter_ws"
SRC = WORKSPACE / "src"


@pytest.fixture
def workspace(monkeypatch) -> Path:
    monkeypatch.setenv("ACTORS_WORKSPACE", str(WORKSPACE))
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    return WORKSPACE


def installed_prefix(root: Path, name: str, executables: dict[str, str]) -> Path:
    """A prefix laid out as colcon installs a package: index marker, share/, lib/<pkg>/ programs."""
    (root / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True, exist_ok=True)
    (root / "share" / "ament_index" / "resource_index" / "packages" / name).write_text("")
    (root / "share" / name).mkdir(parents=True)
    (root / "share" / name / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    (root / "lib" / name).mkdir(parents=True)
    for exe, text in executables.items():
        (root / "lib" / name / exe).write_text(text)
        (root / "lib" / name / exe).chmod(0o755)
    return root


def test_a_workspace_its_packages_and_their_executables(workspace):
    found = packages()
    for name in ("greeter", "greeter_bringup", "greeting_interfaces"):
        assert found[name].origin == "workspace"
        assert found[name].manifest == SRC / name / "package.xml"
    assert found["actors_tutorials"].origin == "shipped"
    assert found["greeter"].build_type == "ament_python"
    assert found["greeting_interfaces"].build_type == "ament_cmake"
    assert list(found["greeter"].executables()) == ["greeter", "listener"]
    assert find_executable("greeter_bringup", "counter").target == "greeter_bringup.counter:main"
    assert found["greeting_interfaces"].executables() == {}


def test_data_files_land_where_colcon_installs_them(workspace):
    share = find_package("greeter").share
    assert share == find_package("greeter").prefix / "share" / "greeter"
    assert (share / "config" / "params.yaml").read_text() == (SRC / "greeter" / "config" / "params.yaml").read_text()
    assert (share / "package.xml").resolve() == SRC / "greeter" / "package.xml"
    # glob('launch/*') of greeter_bringup: every file of its launch folder.
    launch = find_package("greeter_bringup").share / "launch"
    assert sorted(p.name for p in launch.iterdir()) == sorted(
        p.name for p in (SRC / "greeter_bringup/launch").iterdir()
    )


def test_a_data_file_the_setup_no_longer_lists_goes_and_an_edit_is_seen_at_once(tmp_path, monkeypatch):
    ws = tmp_path / "ws"
    shutil.copytree(SRC / "greeter", ws / "src" / "greeter")
    monkeypatch.setenv("ACTORS_WORKSPACE", str(ws))
    share = find_package("greeter").share
    (ws / "src/greeter/config/params.yaml").write_text("edited: true\n")
    assert (share / "config/params.yaml").read_text() == "edited: true\n"
    setup = ws / "src/greeter/setup.py"
    setup.write_text(setup.read_text().replace('(f"{share}/config", glob("config/*.yaml")),', ""))
    assert not (find_package("greeter").share / "config/params.yaml").exists()


def test_a_workspace_package_hides_a_shipped_one_which_hides_an_installed_one(tmp_path, monkeypatch):
    prefix = installed_prefix(tmp_path / "install", "actors_tutorials", {})
    installed_prefix(tmp_path / "other", "only_installed", {"tool": "#!/usr/bin/env python3\nprint('tool')\n"})
    monkeypatch.setenv("AMENT_PREFIX_PATH", f"{prefix}:{tmp_path / 'other'}")
    monkeypatch.setenv("ACTORS_WORKSPACE", str(tmp_path / "ws"))
    (tmp_path / "ws" / "src").mkdir(parents=True)
    assert find_package("actors_tutorials").origin == "shipped"
    assert find_package("only_installed").origin == "installed"
    assert find_package("only_installed").prefix == tmp_path / "other"
    assert list(find_package("only_installed").executables()) == ["tool"]
    shutil.copytree(SRC / "greeter", tmp_path / "ws" / "src" / "actors_tutorials")
    (tmp_path / "ws/src/actors_tutorials/package.xml").write_text(
        "<package format='3'><name>actors_tutorials</name></package>"
    )
    assert find_package("actors_tutorials").origin == "workspace"
    assert search_paths()[-2:] == [prefix, tmp_path / "other"]


def test_no_such_package_or_executable_says_what_there_is(workspace):
    with pytest.raises(
        PackageError, match=r"package 'greter' not found \(did you mean 'greeter'\?\); looked in the workspaces around "
    ):
        find_package("greter")
    with pytest.raises(PackageError, match=r"no executable 'talker' in package 'greeter' .*its executables are"):
        find_executable("greeter", "talker")


def test_ament_index_python_under_the_overlay(workspace):
    with overlaid():
        import ament_index_python
        from ament_index_python.packages import (
            PackageNotFoundError,
            get_package_prefix,
            get_package_share_directory,
            get_package_share_path,
            get_packages_with_prefixes,
        )

        share = get_package_share_directory("greeter")
        assert Path(share, "config", "params.yaml").read_text().startswith("# The greeter's words")
        assert get_package_share_path("greeter") == Path(share)
        assert get_package_prefix("greeter") == str(Path(share).parent.parent)
        with_prefixes = get_packages_with_prefixes()
        assert {"greeter", "greeter_bringup", "greeting_interfaces", "actors_tutorials"} <= set(with_prefixes)
        assert with_prefixes["greeter"] == get_package_prefix("greeter")
        with pytest.raises(PackageNotFoundError) as caught:
            get_package_share_directory("nope")
        assert isinstance(caught.value, KeyError)
        assert "package 'nope' not found, searching: [" in str(caught.value)
        with pytest.raises(ValueError, match="not a valid package name"):
            get_package_prefix("a/b")
        assert ament_index_python.has_resource("packages", "greeter") == get_package_prefix("greeter")
        assert ament_index_python.has_resource("packages", "nope") is False
        assert "packages" in ament_index_python.get_resource_types()
    # Outside the overlay nothing is shadowed: the name is gone (a real ament_index_python would import).
    assert not any(name.startswith("ament_index_python") for name in sys.modules)


def test_ament_index_python_warns_about_a_missing_share_folder(tmp_path, monkeypatch):
    prefix = installed_prefix(tmp_path / "install", "bare", {})
    shutil.rmtree(prefix / "share" / "bare")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    with overlaid(), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from ament_index_python import get_package_share_directory

        assert get_package_share_directory("bare") == str(prefix / "share" / "bare")
        assert get_package_share_directory("bare", print_warning=False)
    assert [str(w.message) for w in caught] == [f"Share directory for bare ({prefix}/share/bare) does not exist."]


def test_the_api_has_ament_index_pythons_names():
    ros_python = Path("/tmp/rosvenv/bin/python")  # real rclpy's environment, where there is one
    if not ros_python.exists():
        pytest.skip("no ROS 2 Python environment to compare with")
    names = subprocess.run(
        [str(ros_python), "-c", "import ament_index_python as a; print(*sorted(a.__all__))"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    with overlaid():
        import ament_index_python as ours
    assert sorted(ours.__all__) == names


def pkg(capsys, *args: str) -> tuple[int, str, str]:
    code = main(["pkg", *args])
    out, err = capsys.readouterr()
    return code, out, err


def test_pkg_list_executables_prefix_and_xml_print_what_ros2_pkg_prints(workspace, capsys):
    code, out, _ = pkg(capsys, "list")
    assert code == 0
    assert {"greeter", "greeter_bringup", "greeting_interfaces", "actors_tutorials"} <= set(out.split())
    assert out.splitlines() == sorted(out.splitlines())
    assert pkg(capsys, "executables", "greeter") == (0, "greeter greeter\ngreeter listener\n", "")
    code, out, _ = pkg(capsys, "executables")
    assert "greeter_bringup counter\n" in out and "actors_tutorials talker\n" in out
    code, out, _ = pkg(capsys, "executables", "greeter", "--full-path")
    prefix = find_package("greeter").prefix
    assert out.splitlines() == [str(prefix / "lib/greeter/greeter"), str(prefix / "lib/greeter/listener")]
    assert pkg(capsys, "prefix", "greeter") == (0, f"{prefix}\n", "")
    assert pkg(capsys, "prefix", "--share", "greeter") == (0, f"{prefix / 'share/greeter'}\n", "")
    assert pkg(capsys, "xml", "greeter", "--tag", "version") == (0, "0.2.0\n", "")
    assert pkg(capsys, "xml", "greeter")[1] == (SRC / "greeter/package.xml").read_text()


@pytest.mark.parametrize(
    ("args", "problem"),
    [
        (("prefix", "nope"), "actors: package 'nope' not found"),
        (("executables", "nope"), "actors: package 'nope' not found"),
        (("xml", "greeter", "--tag", "nothing"), f"actors: {SRC / 'greeter/package.xml'}: XML tag not found: nothing"),
    ],
)
def test_pkg_errors_are_one_line_and_exit_2(workspace, capsys, args, problem):
    code, out, err = pkg(capsys, *args)
    assert (code, out) == (2, "")
    assert err.startswith(problem) and err.count("\n") == 1
