"""Interface packages found in workspaces and ROS installs, typed on first import with no generate step."""

from __future__ import annotations

import importlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

import anyio
import pytest
import yaml

from actors import Node, Runtime, codec
from actors.cli import main
from actors.compat.overlay import overlaid
from actors.messages import discovery
from actors.messages.discovery import InterfaceImportError
from actors.ops.control import ControlEndpoint

WORKSPACE = Path(__file__).parent / "workspaces" / "course_ws"

# What ROS's own generator (rosidl_adapter + rosidl_generator_type_description, Kilted) hashes
# the test workspace's sources to.
ROS_HASHES = {
    "course_interfaces/msg/Person": "RIHS01_4df9c66c5e1313970f8158d02ac03690eff6e517ab67403798942a8664bf8aab",
    "course_interfaces/msg/Address": "RIHS01_fcee108c823efb36e1f50d61d39f9e5de2f3be72464e35000ef205bc5ecb665f",
    "course_interfaces/srv/Register": "RIHS01_e8ca7cc4c001a716516ad3ad3608a9c4019f37fc1d9b85d9b0001d3d64a6c4e2",
    "course_interfaces/action/Walk": "RIHS01_6fce913f0007ac979f3a5a82a47da42c2c088dcbdbddc4fc1f136579948e872f",
    "course_interfaces/action/Walk_Goal": "RIHS01_dbdde6bf63dfee85ff65295f40010316a4905683712f6973fe5daeceb0193dde",
    "course_interfaces/action/Walk_Feedback": "RIHS01_c0c38b731d6cdbb0ea5183848c15274fb3d0e958be3b8feb1f3b2616dbd9040b",
}


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """Discovery as a new process has it: no workspace named yet, an empty cache, no module imported."""
    monkeypatch.setattr(discovery, "_starts", [])
    monkeypatch.setattr(discovery, "_found", {})
    monkeypatch.setenv("ACTORS_INTERFACE_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("ACTORS_WORKSPACE", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.chdir(tmp_path)
    yield tmp_path
    for name in [n for n in sys.modules if n.split(".")[:2] in (["interfaces", "course_interfaces"],)]:
        del sys.modules[name]
    codec._types.clear()


def copy_workspace(to: Path) -> Path:
    shutil.copytree(WORKSPACE, to)
    return to


def test_a_workspace_package_imports_with_its_nested_type_and_constant(fresh):
    discovery.add_workspace(WORKSPACE / "src" / "course_pkg")  # a folder inside: the workspace is found above it
    from interfaces.course_interfaces.msg import Address, Person

    from interfaces.geometry_msgs.msg import Point

    person = Person(name="ada", age=36)
    assert person.home == Address(street="", where=Point())
    assert Person.MAX_AGE == 150
    assert codec.decode_cdr(codec.encode_cdr(person), "course_interfaces/msg/Person") == person


def test_hashes_equal_what_ros_own_generator_makes(fresh):
    discovery.add_workspace(WORKSPACE)
    assert {name: codec.type_hash(name) for name in ROS_HASHES} == ROS_HASHES


def test_one_class_whatever_the_route(fresh, monkeypatch):
    monkeypatch.setenv("ACTORS_WORKSPACE", str(WORKSPACE))
    from interfaces.course_interfaces.srv import Register

    with overlaid():
        ros = importlib.import_module("course_interfaces.srv")
        assert ros.Register is Register
        assert importlib.import_module("course_interfaces.action").Walk.Goal().steps == 0
    assert codec.get_type("course_interfaces/srv/Register") is Register
    assert codec.get_type("course_interfaces/Register") is Register
    assert "course_interfaces/action/Walk" in codec.list_types()


def test_the_working_directory_is_a_place_to_look(fresh, monkeypatch):
    monkeypatch.chdir(WORKSPACE / "src")
    assert discovery.discovered() == {"course_interfaces": WORKSPACE / "src" / "course_interfaces"}


def test_a_ros_install_is_found_through_ament_prefix_path(fresh, monkeypatch):
    prefix = fresh / "install"
    shutil.copytree(WORKSPACE / "src" / "course_interfaces", prefix / "share" / "course_interfaces")
    monkeypatch.setenv("AMENT_PREFIX_PATH", f"{fresh / 'nothing'}{os.pathsep}{prefix}")
    from interfaces.course_interfaces.msg import Person

    assert Path(discovery.discovered()["course_interfaces"]) == prefix / "share" / "course_interfaces"
    assert codec.type_hash(Person) == ROS_HASHES["course_interfaces/msg/Person"]


def test_a_workspace_wins_over_an_install_and_the_shipped_packages_over_both(fresh, monkeypatch):
    prefix = fresh / "install"
    shutil.copytree(WORKSPACE / "src" / "course_interfaces", prefix / "share" / "course_interfaces")
    (prefix / "share" / "std_msgs" / "msg").mkdir(parents=True)
    (prefix / "share" / "std_msgs" / "msg" / "String.msg").write_text("int32 not_the_real_one\n")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    discovery.add_workspace(WORKSPACE)
    found = discovery.discovered()
    assert found["course_interfaces"] == WORKSPACE / "src" / "course_interfaces"
    assert "std_msgs" not in found
    assert codec.get_type("std_msgs/msg/String")().data == ""


def test_the_generated_module_is_cached_and_made_again_when_a_source_changes(fresh):
    workspace = copy_workspace(fresh / "ws")
    discovery.add_workspace(workspace)
    first = importlib.import_module("interfaces.course_interfaces.msg")
    cached = Path(first.__file__)
    assert cached.parent == fresh / "cache" / "course_interfaces" and cached.is_file()
    (workspace / "src" / "course_interfaces" / "msg" / "Person.msg").write_text("string name\nuint16 age\n")
    del sys.modules["interfaces.course_interfaces.msg"]
    again = importlib.import_module("interfaces.course_interfaces.msg")
    assert Path(again.__file__) != cached
    assert again.Person.__struct_fields__ == ("name", "age")


def test_a_bad_source_is_an_import_error_naming_file_and_line(fresh):
    workspace = copy_workspace(fresh / "ws")
    (workspace / "src" / "course_interfaces" / "msg" / "Person.msg").write_text("string name\nnot_a_type age\n")
    discovery.add_workspace(workspace)
    with pytest.raises(InterfaceImportError, match=r"Person\.msg:2: unknown type 'not_a_type'"):
        importlib.import_module("interfaces.course_interfaces.msg")
    assert not (fresh / "cache" / "course_interfaces").exists() or not any((fresh / "cache").rglob("*.py"))


def test_interface_show_and_package_read_the_workspace_of_the_working_directory(fresh, monkeypatch, capsys):
    monkeypatch.chdir(WORKSPACE)
    assert main(["interface", "package", "course_interfaces"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "course_interfaces/msg/Address",
        "course_interfaces/msg/Person",
        "course_interfaces/srv/Register",
        "course_interfaces/action/Walk",
    ]
    assert main(["interface", "show", "course_interfaces/msg/Person"]) == 0
    shown = capsys.readouterr().out
    assert "Address home\n\tstring street\n\tgeometry_msgs/Point where\n\t\tfloat64 x\n" in shown
    assert shown.endswith("uint8 MAX_AGE=150\n")


@pytest.mark.slow
def test_an_rclpy_script_of_the_workspace_runs_under_actors_run_with_no_generate_step(tmp_path):
    script = WORKSPACE / "src" / "course_pkg" / "course_pkg" / "people.py"
    repository = str(Path(__file__).resolve().parent.parent)  # this checkout's actors, installed or not
    env = {**os.environ, "ACTORS_INTERFACE_CACHE": str(tmp_path / "cache"), "PYTHONPATH": repository}
    done = subprocess.run(
        [sys.executable, "-m", "actors", "run", "--clock", "virtual", "--duration", "1.2", str(script)],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    heard = [line.split("]: ", 1)[1] for line in done.stderr.splitlines() if "heard" in line]
    assert heard == ["heard p0 aged 0 (max 150)", "heard p1 aged 1 (max 150)"]
    assert not list(WORKSPACE.rglob("__init__.py")) and not list(WORKSPACE.rglob("__pycache__"))


class Registry(Node):
    """Publishes people, hears them on /heard, registers them and walks: every kind of the workspace's types."""

    def __init__(self) -> None:
        super().__init__("registry")
        from interfaces.course_interfaces.action import Walk
        from interfaces.course_interfaces.msg import Person
        from interfaces.course_interfaces.srv import Register

        self.heard: list[str] = []
        self.hearing = anyio.Event()
        self.pub = self.create_publisher(Person, "people", 10)
        self.create_subscription(Person, "heard", self.hear, 10)
        self.create_service(Register, "register", self.register)
        self.create_action_server(Walk, "walk", self.walk)
        self.create_timer(0.05, lambda: self.pub.publish(Person(name="grace", age=85)))

    def hear(self, msg) -> None:
        self.heard.append(msg.name)
        self.hearing.set()

    def register(self, request, response):
        response.accepted = request.person.age <= request.person.MAX_AGE
        return response

    async def walk(self, goal_handle):
        from interfaces.course_interfaces.action import Walk
        from interfaces.course_interfaces.msg import Person

        met = []
        for step in range(goal_handle.request.steps):
            met.append(Person(name=f"walker{step}", age=step))
            goal_handle.publish_feedback(Walk.Feedback(done=step + 1))
            await anyio.sleep(0.01)
        goal_handle.succeed()
        return Walk.Result(met=met)


async def test_the_command_line_carries_workspace_types_to_and_from_a_running_graph(fresh, monkeypatch, capsys):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(fresh))
    monkeypatch.chdir(WORKSPACE)  # the command line finds the workspace where it runs, as the graph does

    async def actors(*argv: str) -> str:
        code = await anyio.to_thread.run_sync(main, list(argv))
        out, err = capsys.readouterr()
        assert code == 0, err
        return out

    async with Runtime(name="workspace_types", attach=[ControlEndpoint()]) as rt:
        registry = rt.spawn(Registry)
        echoed = next(yaml.safe_load_all(await actors("topic", "echo", "/people", "--once")))
        assert echoed == {"name": "grace", "age": 85, "home": {"street": "", "where": {"x": 0.0, "y": 0.0, "z": 0.0}}}
        await actors("topic", "pub", "--once", "/heard", "course_interfaces/msg/Person", "{name: ada, age: 36}")
        with anyio.fail_after(5):
            await registry.hearing.wait()
        assert registry.heard == ["ada"]
        called = await actors("service", "call", "/register", "course_interfaces/srv/Register", "{person: {age: 200}}")
        assert "course_interfaces.srv.Register_Response(accepted=False)" in called
        walked = await actors("action", "send_goal", "/walk", "course_interfaces/action/Walk", "{steps: 2}", "-f")
        assert "done: 2" in walked and "name: walker1" in walked
        assert "SUCCEEDED" in walked


def test_the_command_line_takes_a_workspace_by_option(fresh, capsys):
    assert main(["--workspace", str(WORKSPACE), "interface", "show", "course_interfaces/srv/Register"]) == 0
    assert capsys.readouterr().out.endswith("---\nbool accepted\n")
    assert main(["--workspace", str(fresh / "nowhere"), "interface", "list"]) == 2
    assert capsys.readouterr().err == f"actors: {fresh / 'nowhere'}: no such workspace folder\n"


@pytest.mark.virtual_time
async def test_a_bag_of_workspace_types_records_lists_and_plays_back(fresh):
    from actors.recording.player import plan, timeline
    from actors.recording.reader import Bag
    from actors.recording.recorder import Recorder

    discovery.add_workspace(WORKSPACE)
    path = fresh / "people.mcap"
    async with Runtime(attach=[Recorder(path)]) as rt:
        registry = rt.spawn(Registry)
        await anyio.sleep(0.12)  # two ticks of its 0.05 s timer, and a third
        registry.destroy_node()
    bag = Bag(path)
    topic = next(t for t in bag.topics if t.name == "/people")
    assert (topic.type, topic.type_hash) == ("course_interfaces/msg/Person", ROS_HASHES["course_interfaces/msg/Person"])
    assert "MSG: Address\n" in topic.definition or "MSG: course_interfaces/Address\n" in topic.definition
    playable, skipped = plan(bag, topics=["/people"])
    assert skipped == []
    played = [msg for _, _, msg in timeline(bag, playable)]
    assert [(p.name, p.age) for p in played] == [("grace", 85)] * len(played) and len(played) >= 2


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        from interfaces.course_interfaces.msg import Person

        self.heard: list[tuple[str, int]] = []
        self.three = anyio.Event()
        self.create_subscription(Person, "people", self.hear, 10)

    def hear(self, msg) -> None:
        self.heard.append((msg.name, msg.age))
        if len(self.heard) == 3:
            self.three.set()


async def test_bag_info_lists_and_bag_play_replays_workspace_types_into_a_running_graph(fresh, monkeypatch, capsys):
    from actors.recording.bag_writer import BagWriter

    monkeypatch.setenv("XDG_RUNTIME_DIR", str(fresh))
    discovery.add_workspace(WORKSPACE)
    person = codec.get_type("course_interfaces/msg/Person")
    path = fresh / "people.mcap"
    writer = BagWriter(path)
    topic = writer.add_topic(
        "/people", codec.ros_name(person), definition=codec.definition_text(person), type_hash=codec.type_hash(person)
    )
    for i in range(3):
        writer.write(topic, (i + 1) * 10_000_000, codec.encode_cdr(person(name=f"p{i}", age=i)))
    writer.close()
    monkeypatch.chdir(WORKSPACE)
    assert main(["bag", "info", str(path)]) == 0
    assert "Topic: /people | Type: course_interfaces/msg/Person | Count: 3" in capsys.readouterr().out
    async with Runtime(name="people_bag", attach=[ControlEndpoint()]) as rt:
        listener = rt.spawn(Listener)
        code = await anyio.to_thread.run_sync(main, ["bag", "play", str(path)])
        with anyio.fail_after(5):
            await listener.three.wait()  # what play sent is delivered in the loop's next rounds
    assert code == 0
    assert listener.heard == [("p0", 0), ("p1", 1), ("p2", 2)]


def test_a_package_added_to_a_searched_workspace_is_seen_when_the_workspace_is_named_again(fresh):
    workspace = copy_workspace(fresh / "ws")
    discovery.add_workspace(workspace)
    assert set(discovery.discovered()) == {"course_interfaces"}
    late = workspace / "src" / "late_interfaces"
    (late / "msg").mkdir(parents=True)
    (late / "package.xml").write_text('<package format="3"><name>late_interfaces</name></package>\n')
    (late / "msg" / "Late.msg").write_text("int32 n\n")
    assert "late_interfaces" not in discovery.discovered()  # found once, kept
    discovery.add_workspace(workspace)
    assert set(discovery.discovered()) == {"course_interfaces", "late_interfaces"}
