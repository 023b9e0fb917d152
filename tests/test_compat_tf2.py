"""tf2_ros, tf2_geometry_msgs and tf_transformations under the overlay; the tf2 tutorials' programs with turtlesim."""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT, python_env

from actors.compat import overlaid
from interfaces.geometry_msgs.msg import PointStamped, PoseStamped, TransformStamped, Vector3Stamped

SCRIPTS = ROOT / "scripts"
RIG = ROOT / "tests" / "rclpy_scripts"
GRAPH = str(ROOT / "graphs" / "turtlesim.toml")


def test_the_overlay_provides_tf2s_python_modules():
    with overlaid():
        import tf2_geometry_msgs
        import tf2_ros
        import tf_transformations
        from tf2_ros.buffer import Buffer
        from tf2_ros.transform_listener import TransformListener

        assert tf2_ros.Buffer is Buffer and tf2_ros.TransformListener is TransformListener
        assert issubclass(tf2_ros.ExtrapolationException, tf2_ros.TransformException)
        assert tf2_geometry_msgs.do_transform_point is not None
        q = tf_transformations.quaternion_from_euler(0.1, -0.2, 0.3)
        assert tf_transformations.euler_from_quaternion(q) == pytest.approx((0.1, -0.2, 0.3))
        assert list(tf_transformations.quaternion_from_euler(0, 0, math.pi / 2)) == pytest.approx(
            [0, 0, math.sqrt(0.5), math.sqrt(0.5)]
        )
        with pytest.raises(ModuleNotFoundError, match="overlay does not provide it"):
            import tf2_ros.no_such_module
        with pytest.raises(ValueError, match="sxyz"):
            tf_transformations.quaternion_from_euler(0, 0, 0, axes="rzyx")


def test_buffer_transform_moves_points_vectors_and_poses_into_the_target_frame():
    with overlaid():
        import tf2_geometry_msgs  # noqa: F401  (registers the types, as in ROS)
        from tf2_ros import Buffer

        buffer = Buffer()
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = "world", "turtle1"
        t.transform.translation.x = 2.0
        t.transform.rotation.z, t.transform.rotation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)  # 90° left
        buffer.set_transform_static(t, "test")
        point = PointStamped()
        point.header.frame_id, point.point.x = "turtle1", 1.0
        moved = buffer.transform(point, "world")
        assert (moved.header.frame_id, moved.point.x, moved.point.y) == (
            "world",
            pytest.approx(2.0),
            pytest.approx(1.0),
        )
        vector = Vector3Stamped()
        vector.header.frame_id, vector.vector.x = "turtle1", 1.0
        turned = buffer.transform(vector, "world").vector
        assert (turned.x, turned.y) == (pytest.approx(0.0), pytest.approx(1.0))  # no translation for directions
        pose = PoseStamped()
        pose.header.frame_id, pose.pose.orientation.w = "turtle1", 1.0
        placed = buffer.transform(pose, "world").pose
        assert (placed.position.x, placed.orientation.z) == (pytest.approx(2.0), pytest.approx(math.sqrt(0.5)))


def follow(*args: str, partners: tuple[str, ...] = (), duration: float = 16) -> subprocess.CompletedProcess[str]:
    """The tf2 demo: turtlesim, broadcasters for both turtles, a leader driving turtle1, and the listener."""
    command = [sys.executable, "-m", "actors", "run", "--clock", "virtual", "--duration", str(duration)]
    command += ["--graph", GRAPH]
    for name in ("turtle1", "turtle2"):
        command += [
            "--with",
            f"{SCRIPTS / 'turtle_tf2_broadcaster.py'} --ros-args -p turtlename:={name} -r __node:=b_{name}",
        ]
    command += ["--with", f"{SCRIPTS / 'turtle_leader.py'} 15"]
    for partner in partners:
        command += ["--with", partner]
    command += [str(SCRIPTS / "turtle_tf2_listener.py"), *args]
    return subprocess.run(command, cwd=ROOT, env=python_env(), capture_output=True, text=True, timeout=120)


def where_turtle1(stdout: str) -> tuple[float, float]:
    words = re.search(r"^turtle1 (\S+) (\S+)", stdout, re.M)
    assert words, stdout
    return float(words[1]), float(words[2])


def where(done: subprocess.CompletedProcess[str]) -> dict[str, tuple[float, float]]:
    words = re.search(r"^turtle1 .*$", done.stdout, re.M)
    assert words, done.stdout + done.stderr
    parts = words.group(0).split()
    return {parts[0]: (float(parts[1]), float(parts[2])), parts[3]: (float(parts[4]), float(parts[5]))}


@pytest.mark.slow
@pytest.mark.parametrize("mode", ["latest", "now"])
def test_the_second_turtle_follows_the_first(mode):
    done = follow(mode)
    assert done.returncode == 0, done.stderr
    turtles = where(done)
    assert math.dist(turtles["turtle1"], turtles["turtle2"]) < 2.5  # it set off from 3.8 m away and kept up
    assert "Successfully spawned turtle2" in done.stderr
    assert "extrapolation" not in done.stderr


@pytest.mark.slow
def test_a_lookup_at_now_without_waiting_fails_into_the_future_in_tf2s_words():
    done = follow("now-nowait", duration=6)
    assert done.returncode == 0, done.stderr
    assert re.search(
        r"Could not transform turtle2 to turtle1: Lookup would require extrapolation into the future\.  "
        r"Requested time 5\.000000 but the latest data is at time 4\.99\d000, when looking up transform "
        r"from frame \[turtle1\] to frame \[turtle2\]",
        done.stderr,
    ), done.stderr


@pytest.mark.slow
def test_time_travel_and_an_added_frame():
    done = follow("travel")
    assert done.returncode == 0, done.stderr
    assert "not yet five seconds" in done.stderr and "extrapolation" not in done.stderr
    turtles = where(done)
    assert math.dist(turtles["turtle2"], (4.0, 2.0)) > 1.0  # it moved, chasing where turtle1 was
    carrot = follow(
        "--ros-args", "-p", "target_frame:=carrot1", partners=(str(SCRIPTS / "fixed_frame_tf2_broadcaster.py"),)
    )
    assert carrot.returncode == 0, carrot.stderr
    turtles = where(carrot)
    assert 1.0 < math.dist(turtles["turtle1"], turtles["turtle2"]) < 3.0  # beside turtle1, not on it


@pytest.mark.slow
def test_a_static_frame_is_reached():
    goal = f"{SCRIPTS / 'static_turtle_tf2_broadcaster.py'} goal 8 8 0 0 0 0"
    done = follow("--ros-args", "-p", "target_frame:=goal", partners=(goal,))
    assert done.returncode == 0, done.stderr
    assert math.dist(where(done)["turtle2"], (8.0, 8.0)) < 0.3


def actors_run(*args: str, stdin: str = "") -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "actors", "run", *args]
    return subprocess.run(command, cwd=ROOT, env=python_env(), input=stdin, capture_output=True, text=True, timeout=120)


@pytest.mark.slow
def test_tf2_echo_and_static_transform_publisher_run_as_tf2_ros_executables():
    publisher = "tf2_ros static_transform_publisher --x 1 --y 2 --yaw 0.5 --frame-id world --child-frame-id mystatic"
    done = actors_run(
        "--clock", "virtual", "--duration", "2.5", "--with", publisher, "tf2_ros", "tf2_echo", "world", "mystatic"
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("At time 0.0\n- Translation: [1.000, 2.000, 0.000]\n")  # first at 1 s
    assert "- Rotation: in RPY (radian) [0.000, -0.000, 0.500]\n" in done.stdout
    assert "from 'world' to 'mystatic'" in done.stderr
    bad = actors_run("tf2_ros", "tf2_echo", "world", "mystatic", "fast")
    assert (bad.returncode, bad.stderr) == (2, "tf2_echo: echo_rate 'fast' is not a positive number of Hz\n")
    wrong = actors_run("tf2_ros", "static_transform_publisher", "--x", "1")
    assert wrong.returncode == 2 and "both --frame-id and --child-frame-id are required" in wrong.stderr


@pytest.mark.slow
def test_turtlesim_and_its_teleop_run_as_ros2_run_starts_them():
    leader = f"{SCRIPTS / 'turtle_leader.py'} 1.5 --still"
    done = actors_run(
        "--clock",
        "virtual",
        "--duration",
        "2",
        "--with",
        "turtlesim turtlesim_node",
        "--with",
        leader,
        "turtlesim",
        "turtle_teleop_key",
        stdin="\x1b[A",
    )
    assert done.returncode == 0, done.stderr
    assert "Use arrow keys to move the turtle." in done.stdout
    x, y = where_turtle1(done.stdout)
    assert (round(x, 3), round(y, 3)) == (7.496, 5.544)  # 2 m/s for a second, forward from the centre


def frames(dump: str) -> dict[str, dict[str, str]]:
    """The last ``all_frames_as_yaml`` dump of the output: each frame's parent and rate, as printed."""
    found: dict[str, dict[str, str]] = {}
    for child, parent, rate in re.findall(
        r"^(\w+): \n  parent: '(\w+)'\n  broadcaster: '\w+'\n  rate: (\S+)", dump, re.M
    ):
        found[child] = {"parent": parent, "rate": rate}
    return found


@pytest.mark.slow
def test_broadcasters_shaped_like_examples_tf2_pys_run_and_their_frames_add_up():
    # Our programs make examples_tf2_py's calls: a tuple of static transforms; a TransformBroadcaster
    # fed by a JointState subscription, beside a 20 Hz timer's node in one SingleThreadedExecutor;
    # `with rclpy.init()`; a Buffer without a node, a listener without a thread, all_frames_as_yaml.
    done = actors_run(
        "--clock",
        "virtual",
        "--duration",
        "2.5",
        "--with",
        str(RIG / "rig_static.py"),
        "--with",
        str(RIG / "rig_pan.py"),
        str(RIG / "rig_watch.py"),
    )
    assert (done.returncode, done.stderr) == (0, ""), done.stderr
    tree = frames(done.stdout)
    parents = {child: f["parent"] for child, f in tree.items()}
    # the encoder's "tilt" moves no frame
    assert parents == {"mast": "base"} | dict.fromkeys(["camera", "lidar", "pan_left", "pan_right"], "mast")
    assert tree["camera"]["rate"] == "10000.000"  # static: tf2's rate for one sample
    assert tree["pan_left"]["rate"] == "20.526"  # 39 stamps, 0.05 s to 1.95 s: tf2's count over span
    numbers = re.findall(r"^lidar->camera at 0\.0: (.*)$", done.stdout, re.M)
    # the camera, turned 30 degrees on the mast, seen from the lidar, turned -90: 120 degrees, 0.1 m to its left
    x, y, z, qx, qy, qz, qw = map(float, numbers[-1].split())
    assert (x, y, z) == (pytest.approx(0.0, abs=1e-12), pytest.approx(0.1), pytest.approx(-0.05))
    assert (qx, qy, qz, qw) == (0.0, 0.0, pytest.approx(math.sin(math.radians(60))), pytest.approx(0.5))
    head = re.findall(r"^base->pan_left at (\S+): (.*)$", done.stdout, re.M)
    stamp, values = float(head[-1][0]), [float(v) for v in head[-1][1].split()]
    assert stamp == 1.95 and values == pytest.approx([0.0, 0.2, 0.5, 0.0, 0.0, math.sin(0.975), math.cos(0.975)])


GEOMETRY2 = os.environ.get("ACTORS_GEOMETRY2", "")


@pytest.mark.slow
@pytest.mark.skipif(
    not GEOMETRY2,
    reason="ros2/geometry2's examples_tf2_py is on no package registry and its code stays out of this "
    "repository: set ACTORS_GEOMETRY2 to a checkout of ros2/geometry2 to run its programs unmodified",
)
def test_geometry2s_examples_tf2_py_broadcasters_run_unmodified(tmp_path):
    package = Path(GEOMETRY2) / "examples_tf2_py"
    assert (package / "setup.py").is_file(), f"ACTORS_GEOMETRY2={GEOMETRY2} holds no examples_tf2_py package"
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "examples_tf2_py").symlink_to(package)  # a workspace around the checkout, as colcon's
    run = [sys.executable, "-m", "actors", "run", "--clock", "virtual", "--duration", "2.5"]
    static, dynamic = "examples_tf2_py static_broadcaster", "examples_tf2_py dynamic_broadcaster"
    given = {"cwd": tmp_path, "env": python_env(), "capture_output": True, "text": True, "timeout": 120}
    done = subprocess.run([*run, "--with", static, "--with", dynamic, "examples_tf2_py", "frame_dumper"], **given)
    assert (done.returncode, done.stderr) == (0, ""), done.stderr
    tree = frames(done.stdout)
    parents = {child: f["parent"] for child, f in tree.items()}
    on_the_platform = dict.fromkeys(["camera", "sonar_0", "sonar_1", "sonar_2"], "platform")
    assert parents == on_the_platform | dict.fromkeys(["platform", "port_wheel", "starboard_wheel"], "base_link")
    assert tree["port_wheel"]["rate"] == "30.517"  # 59 stamps at 30 Hz, 1/30 s to 59/30 s: count over span
    echo = subprocess.run([*run, "--with", static, "tf2_ros", "tf2_echo", "platform", "sonar_2"], **given)
    assert echo.returncode == 0, echo.stderr
    # sonar_2 sits 45 degrees right of ahead, 5 cm out, turned by the quaternion the program writes out
    assert (
        "- Translation: [0.035, -0.035, 0.000]\n- Rotation: in Quaternion [0.000, 0.000, -0.487, 0.873]" in echo.stdout
    )
