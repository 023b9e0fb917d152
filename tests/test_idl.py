"""Tests for actors.messages.idl and actors.messages.generate: parsing .msg/.srv/.action text,
generating modules, drift."""

from __future__ import annotations

import importlib
import sys
from array import array
from pathlib import Path

import pytest

from actors import codec
from actors.errors import IdlError, InterfaceError, MessageValidationError
from actors.messages import generate as idl_gen
from actors.messages import idl

THING = """\
# A user's message: every kind of field.
uint8 RED=1
string NAME="thing # not a comment"
float64 SCALE=2.5

int32[] counts
float32[3] weights
string<=5 tag "abc"
int64 limit 5
float64[] gains [1.0, 2]
bool enabled true
uint8[] blob
byte[4] raw
string[<=2] labels ["a", "b"]
Part part
Part[2] parts
std_msgs/Header header
Header local_header
"""
PART = "int16\tid -3  # tab-separated, trailing comment\nwstring note\n"
HEADER = "# a Header of this package, not std_msgs'\nuint32 seq\n"
LOOKUP = "string key\nPart template\n---\nThing thing\nbool found\n"
MOVE = "# where to\nPart target\nfloat64 speed 0.5\n---\nbool arrived\n---\n# progress\nfloat32 left\n"


def write_root(base: Path, name: str, files: dict[str, str]) -> Path:
    root = base / name
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root


@pytest.fixture
def user_root(tmp_path, monkeypatch):
    """A generated user root ``my_root`` with package ``my_pkg``, importable; forgotten afterwards."""
    root = write_root(
        tmp_path,
        "my_root",
        {
            "my_pkg/msg/Thing.msg": THING,
            "my_pkg/msg/Part.msg": PART,
            "my_pkg/msg/Header.msg": HEADER,
            "my_pkg/srv/Lookup.srv": LOOKUP,
            "my_pkg/action/Move.action": MOVE,
        },
    )
    idl_gen.generate([root])
    monkeypatch.syspath_prepend(str(tmp_path))
    importlib.invalidate_caches()
    yield root
    for name in [name for name in sys.modules if name.split(".")[0] == "my_root"]:
        del sys.modules[name]


# --------------------------------------------------------------------------- parsing


def test_parse_message_fields_constants_and_defaults():
    spec = idl.parse_message(THING, path="Thing.msg", pkg="my_pkg", name="Thing")
    assert spec.ros_type == "my_pkg/msg/Thing"
    assert [(c.name, c.value) for c in spec.constants] == [
        ("RED", 1),
        ("NAME", "thing # not a comment"),
        ("SCALE", 2.5),
    ]
    fields = {f.name: f for f in spec.fields}
    assert list(fields)[:3] == ["counts", "weights", "tag"]
    assert fields["weights"].type == idl.FieldType("float32", array="fixed", size=3)
    assert fields["tag"].type.string_bound == 5 and fields["tag"].default == "abc"
    assert fields["gains"].default == [1.0, 2.0]
    assert fields["enabled"].default is True
    assert fields["labels"].type.array == "bounded" and fields["labels"].default == ["a", "b"]
    assert fields["part"].type.ros_type == "my_pkg/msg/Part"
    assert fields["header"].type.ros_type == "std_msgs/msg/Header"
    assert fields["limit"].line == 9
    assert spec.text == THING


def test_parse_type_forms_resolve_to_full_names():
    spec = idl.parse_message(
        "Point a\ngeometry_msgs/Point b\ngeometry_msgs/msg/Point c\n", pkg="geometry_msgs", name="X"
    )
    assert {f.type.ros_type for f in spec.fields} == {"geometry_msgs/msg/Point"}


def test_parse_service_splits_request_and_response():
    spec = idl.parse_service(LOOKUP, path="Lookup.srv", pkg="my_pkg", name="Lookup")
    assert spec.ros_type == "my_pkg/srv/Lookup"
    assert spec.request.ros_type == "my_pkg/srv/Lookup_Request"
    assert [f.name for f in spec.request.fields] == ["key", "template"]
    assert spec.request.fields[1].type.ros_type == "my_pkg/msg/Part"  # bare name: same package's msg
    assert [(f.name, f.line) for f in spec.response.fields] == [("thing", 4), ("found", 5)]
    assert spec.response.text == "Thing thing\nbool found\n"


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("int32 a\nint32 a\n", 2, "duplicate name 'a'"),
        ("int32\n", 1, "expected 'TYPE NAME'"),
        ("\n\nint32[x] a\n", 3, "malformed type"),
        ("int32<=3 a\n", 1, "only strings take a bound"),
        ("int32 Bad\n", 1, "invalid field name 'Bad'"),
        ("int32 a__b\n", 1, "invalid field name"),
        ("int32 class\n", 1, "reserved in Python"),
        ("int32 list\n", 1, "reserved in Python"),
        ("uint8 a 256\n", 1, "out of range for uint8"),
        ("int8 a x\n", 1, "expected a int8 value"),
        ("bool a maybe\n", 1, "expected true or false"),
        ("float64[2] a [1.0]\n", 1, "expected 2 values"),
        ("int32[<=1] a [1, 2]\n", 1, "at most 1 values"),
        ("int32[] a 1\n", 1, "an array default must look like"),
        ("string<=2 a toolong\n", 1, "longer than its bound"),
        ("string[] a ['x]\n", 1, "unterminated string"),
        ("int32[] A=1\n", 1, "primitive, non-array"),
        ("int32 lower=1\n", 1, "invalid constant name"),
        ("int32 A=\n", 1, "has no value"),
        ("Point p 1\n", 1, "cannot have a default"),
        ("a/b/c/D x\n", 1, "unknown type"),
    ],
)
def test_parse_errors_name_the_line(text, line, problem):
    with pytest.raises(IdlError) as caught:
        idl.parse_message(text, path="pkg/msg/Bad.msg", pkg="pkg", name="Bad")
    assert (caught.value.path, caught.value.line) == ("pkg/msg/Bad.msg", line)
    assert problem in caught.value.problem
    assert str(caught.value).startswith(f"pkg/msg/Bad.msg:{line}: ")


@pytest.mark.parametrize(("text", "line"), [("int32 a\n", 1), ("---\n---\n", 2)])
def test_service_needs_exactly_one_separator(text, line):
    with pytest.raises(IdlError, match="exactly one '---'") as caught:
        idl.parse_service(text, path="S.srv", pkg="p", name="S")
    assert caught.value.line == line


def test_service_errors_count_lines_from_the_file_start():
    with pytest.raises(IdlError) as caught:
        idl.parse_service("int32 a\n---\nint32 b\nint32 b\n", path="S.srv", pkg="p", name="S")
    assert caught.value.line == 4


def test_parse_action_splits_goal_result_feedback():
    spec = idl.parse_action(MOVE, path="Move.action", pkg="my_pkg", name="Move")
    assert spec.ros_type == "my_pkg/action/Move"
    assert [p.ros_type for p in (spec.goal, spec.result, spec.feedback)] == [
        "my_pkg/action/Move_Goal",
        "my_pkg/action/Move_Result",
        "my_pkg/action/Move_Feedback",
    ]
    assert spec.goal.fields[0].type.ros_type == "my_pkg/msg/Part"  # bare name: same package's msg
    assert spec.goal.fields[1].default == 0.5
    assert [(f.name, f.line) for f in spec.result.fields] == [("arrived", 5)]
    assert [(f.name, f.line) for f in spec.feedback.fields] == [("left", 8)]
    assert spec.text == MOVE


def test_parse_action_derives_the_wire_types_as_rosidl_does():
    spec = idl.parse_action(MOVE, pkg="my_pkg", name="Move")

    def shape(message: idl.MessageSpec) -> list[tuple[str, str]]:
        return [(f.name, f.type.ros_type) for f in message.fields]

    assert spec.send_goal.ros_type == "my_pkg/action/Move_SendGoal"
    assert spec.send_goal.request.ros_type == "my_pkg/action/Move_SendGoal_Request"
    assert shape(spec.send_goal.request) == [
        ("goal_id", "unique_identifier_msgs/msg/UUID"),
        ("goal", "my_pkg/action/Move_Goal"),
    ]
    assert shape(spec.send_goal.response) == [("accepted", "bool"), ("stamp", "builtin_interfaces/msg/Time")]
    assert spec.get_result.ros_type == "my_pkg/action/Move_GetResult"
    assert shape(spec.get_result.request) == [("goal_id", "unique_identifier_msgs/msg/UUID")]
    assert shape(spec.get_result.response) == [("status", "int8"), ("result", "my_pkg/action/Move_Result")]
    assert spec.feedback_message.ros_type == "my_pkg/action/Move_FeedbackMessage"
    assert shape(spec.feedback_message) == [
        ("goal_id", "unique_identifier_msgs/msg/UUID"),
        ("feedback", "my_pkg/action/Move_Feedback"),
    ]


@pytest.mark.parametrize(("text", "line"), [("int32 a\n---\nint32 b\n", 3), ("---\n---\n---\n", 3)])
def test_action_needs_exactly_two_separators(text, line):
    with pytest.raises(IdlError, match="exactly 2 '---' lines") as caught:
        idl.parse_action(text, path="A.action", pkg="p", name="A")
    assert caught.value.line == line


def test_action_errors_count_lines_from_the_file_start():
    with pytest.raises(IdlError) as caught:
        idl.parse_action("---\n---\nint32 b\nint32 b\n", path="A.action", pkg="p", name="A")
    assert (caught.value.path, caught.value.line) == ("A.action", 4)


def test_only_an_actions_parts_are_action_types():
    spec = idl.parse_message("p/action/Move_Goal g\n", pkg="p", name="X")
    assert spec.fields[0].type.ros_type == "p/action/Move_Goal"
    with pytest.raises(IdlError, match="unknown type"):
        idl.parse_message("p/action/Move g\n", pkg="p", name="X")


def test_strip_comment_ignores_hashes_in_quotes():
    assert idl.strip_comment('string s "a#b" # note') == 'string s "a#b" '
    assert idl.strip_comment("string s 'it\\'s#' #x") == "string s 'it\\'s#' "


# --------------------------------------------------------------------------- generation


def test_shipped_modules_do_not_drift_from_their_sources():
    rendered = idl_gen.render([idl.shipped_root()])
    sources = [path for kind in ("msg", "srv", "action") for path in idl.shipped_root().glob(f"*/*/*.{kind}")]
    assert any(path.suffix == ".action" for path in sources)
    assert {source.parent / "__init__.py" for source in sources} <= set(rendered)
    for path, text in rendered.items():
        assert path.exists(), f"{path} is missing: run python -m actors interface generate"
        assert path.read_text(encoding="utf-8") == text, f"{path} drifted: run python -m actors interface generate"


def test_generated_module_says_where_it_comes_from():
    text = (idl.shipped_root() / "std_msgs/msg/__init__.py").read_text(encoding="utf-8")
    first = text.splitlines()[0]
    assert "std_msgs/msg/*.msg" in first and "python -m actors interface generate" in first
    assert "do not edit" in first


def test_user_root_types_behave_like_shipped_ones(user_root):
    from my_root.my_pkg.msg import Header, Part, Thing
    from my_root.my_pkg.srv import Lookup

    from interfaces.std_msgs.msg import Header as StdHeader

    thing = Thing()
    assert (Thing.RED, Thing.NAME, Thing.SCALE) == (1, "thing # not a comment", 2.5)
    assert thing.counts == array("i") and thing.weights == array("f", [0.0, 0.0, 0.0])
    assert (thing.tag, thing.limit, thing.gains, thing.enabled) == ("abc", 5, array("d", [1.0, 2.0]), True)
    assert [(type(a), a.typecode) for a in (thing.counts, thing.weights, thing.gains)] == [
        (array, "i"),
        (array, "f"),
        (array, "d"),
    ]
    assert (thing.blob, thing.raw, thing.labels) == (b"", bytes(4), ["a", "b"])
    assert thing.parts == [Part(), Part()] and thing.parts[0] is not thing.parts[1]
    assert type(thing.header) is StdHeader and type(thing.local_header) is Header
    assert Part().id == -3 and Part().note == ""
    thing.part.id = 7
    assert Thing().part.id == -3  # defaults are never shared
    assert Thing.__ros_type__ == "my_pkg/msg/Thing" and Thing.__ros_definition__ == THING
    assert Lookup.__ros_type__ == "my_pkg/srv/Lookup"
    assert Lookup.Response(thing=thing).thing.part.id == 7
    assert codec.decode(codec.encode(thing), Thing) == thing
    assert codec.decode_json(codec.encode_json(thing), Thing) == thing


def test_user_root_actions_have_rclpys_shape(user_root):
    from my_root.my_pkg import action
    from my_root.my_pkg.action import Move
    from my_root.my_pkg.msg import Part

    from interfaces.action_msgs.msg import GoalStatusArray
    from interfaces.action_msgs.srv import CancelGoal
    from interfaces.unique_identifier_msgs.msg import UUID

    assert Move.__ros_type__ == "my_pkg/action/Move" and Move.__ros_definition__ == MOVE
    assert (Move.Goal, Move.Result, Move.Feedback) == (action.Move_Goal, action.Move_Result, action.Move_Feedback)
    assert Move.Goal().speed == 0.5 and type(Move.Goal().target) is Part
    impl = Move.Impl
    assert impl.CancelGoalService is CancelGoal and impl.GoalStatusMessage is GoalStatusArray
    request = impl.SendGoalService.Request(goal_id=UUID(uuid=bytes(range(16))), goal=Move.Goal(speed=2.0))
    assert impl.SendGoalService.Request.__ros_type__ == "my_pkg/action/Move_SendGoal_Request"
    assert codec.decode(codec.encode(request), impl.SendGoalService.Request) == request
    assert impl.GetResultService.Response().result == Move.Result()
    feedback = impl.FeedbackMessage(feedback=Move.Feedback(left=1.5))
    assert feedback.goal_id.uuid == bytes(16) and feedback.feedback.left == 1.5
    with pytest.raises(MessageValidationError):  # a UUID is exactly 16 bytes
        codec.convert({"goal_id": {"uuid": [1, 2]}}, impl.FeedbackMessage)


@pytest.mark.parametrize(
    ("change", "path"),
    [
        ({"tag": "toolong"}, "tag"),
        ({"weights": [1.0]}, "weights"),
        ({"raw": [1, 2]}, "raw"),
        ({"labels": ["a", "b", "c"]}, "labels"),
        ({"part": {"id": 40000}}, "part.id"),
    ],
)
def test_user_root_bounds_are_enforced_on_decode(user_root, change, path):
    from my_root.my_pkg.msg import Thing

    with pytest.raises(MessageValidationError) as caught:
        codec.convert(change, Thing)
    assert str(caught.value).startswith(f"field '{path}' of my_pkg/msg/Thing: expected ")


def test_user_root_is_found_by_name_once_registered(user_root, monkeypatch):
    for registry in ("_roots", "_types"):  # forget the registration afterwards
        monkeypatch.setattr(codec, registry, type(getattr(codec, registry))())
    codec.register_root(user_root)
    from my_root.my_pkg.msg import Thing

    assert codec.get_type("my_pkg/Thing") is Thing
    assert codec.get_type("my_pkg/srv/Lookup_Request").__ros_type__ == "my_pkg/srv/Lookup_Request"
    assert {"my_pkg/msg/Thing", "my_pkg/srv/Lookup", "my_pkg/action/Move", "std_msgs/msg/String"} <= set(
        codec.list_types()
    )
    assert codec.get_type("my_pkg/Move").Goal.__ros_type__ == "my_pkg/action/Move_Goal"
    assert codec.get_type("my_pkg/action/Move_SendGoal_Response").__ros_type__.endswith("_SendGoal_Response")
    # Two classes named Header: the schema still titles each with its ROS name.
    titles = {d["title"] for d in codec.json_schema(Thing)["$defs"].values()}
    assert {"std_msgs/msg/Header", "my_pkg/msg/Header", "my_pkg/msg/Part"} <= titles


def test_user_root_gets_init_files_and_aliased_imports(user_root):
    assert (user_root / "__init__.py").exists() and (user_root / "my_pkg/__init__.py").exists()
    text = (user_root / "my_pkg/msg/__init__.py").read_text(encoding="utf-8")
    assert "from interfaces.std_msgs.msg import Header as std_msgs_Header" in text
    assert idl_gen.generate([user_root]) == []  # nothing changed, nothing written


def test_generate_reports_a_malformed_line(tmp_path):
    root = write_root(tmp_path, "bad_root", {"pkg/msg/Ok.msg": "int8 a\n", "pkg/msg/Bad.msg": "int8 a\nfloat64 [] b\n"})
    with pytest.raises(IdlError) as caught:
        idl_gen.generate([root])
    assert caught.value.path == str(root / "pkg/msg/Bad.msg") and caught.value.line == 2
    assert not (root / "pkg/msg/__init__.py").exists()


@pytest.mark.parametrize(
    ("files", "where", "problem"),
    [
        ({"pkg/msg/A.msg": "int8 x\nNope n\n"}, ("pkg/msg/A.msg", 2), "unknown type 'pkg/msg/Nope'"),
        ({"pkg/srv/S.srv": "---\nother_pkg/Thing t\n"}, ("pkg/srv/S.srv", 2), "unknown type"),
        ({"pkg/msg/A.msg": "B b\n", "pkg/msg/B.msg": "A a\n"}, ("pkg/msg/B.msg", 1), "contains itself"),
        ({"pkg/action/A.action": "---\n---\nNope n\n"}, ("pkg/action/A.action", 3), "unknown type"),
    ],
)
def test_generate_rejects_unknown_and_recursive_types(tmp_path, files, where, problem):
    root = write_root(tmp_path, "bad_root", files)
    with pytest.raises(IdlError, match=problem) as caught:
        idl_gen.generate([root])
    assert (caught.value.path, caught.value.line) == (str(root / where[0]), where[1])


@pytest.mark.parametrize(
    ("name", "files", "problem"),
    [
        ("not-a-name", {"pkg/msg/A.msg": ""}, "must be a Python identifier"),
        ("interfaces", {"pkg/msg/A.msg": ""}, "already named 'interfaces'"),
        ("good", {"Pkg/msg/A.msg": ""}, "invalid package name"),
        ("good", {"pkg/msg/lower.msg": ""}, "CamelCase"),
        ("good", {"pkg/msg/ClassVar.msg": ""}, "reserved"),
    ],
)
def test_generate_rejects_unusable_names(tmp_path, name, files, problem):
    root = write_root(tmp_path, name, files)
    with pytest.raises(InterfaceError, match=problem):
        idl_gen.generate([root])


def test_module_all_is_honest():
    for module in (idl, importlib.import_module("actors.messages.generate")):
        assert all(hasattr(module, name) for name in module.__all__)


def test_a_service_event_names_its_own_request_and_response():
    spec = idl.parse_service("int32 a\n---\nint32 b\n", pkg="demo", name="Ask")
    event = spec.event
    assert event.ros_type == "demo/srv/Ask_Event"
    assert [(f.name, f.type.ros_type, f.type.array, f.type.size) for f in event.fields] == [
        ("info", "service_msgs/msg/ServiceEventInfo", None, None),
        ("request", "demo/srv/Ask_Request", "bounded", 1),
        ("response", "demo/srv/Ask_Response", "bounded", 1),
    ]
    with pytest.raises(IdlError, match="unknown type 'demo/srv/Ask'"):
        idl.parse_message("demo/srv/Ask whole\n", pkg="demo", name="Holder")
