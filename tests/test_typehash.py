"""RIHS01 type hashes equal ROS 2 Kilted's for every shipped type (goldens from the real packages)."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest
from goldens.values import shipped_types

from actors import codec
from actors.errors import UnknownInterfaceError
from actors.messages import typehash
from interfaces.std_msgs.msg import Empty

GOLDENS = json.loads((Path(__file__).parent / "goldens" / "hashes.json").read_text())["hashes"]


def _types_with_a_class() -> list[str]:
    names = []
    for name in GOLDENS:
        try:
            codec.get_type(name)
        except UnknownInterfaceError:
            continue
        names.append(name)
    return names


WITH_CLASS = _types_with_a_class()


@pytest.mark.parametrize("name", WITH_CLASS)
def test_hash_equals_ros(name):
    assert codec.type_hash(name) == GOLDENS[name]


def test_every_shipped_type_has_a_golden_hash():
    assert set(shipped_types()) <= set(WITH_CLASS)


def _sub_hash(description: dict, name: str) -> str:
    """ROS's hash of a type that appears only inside another's description (a service's Event)."""
    known = {d["type_name"]: d for d in [description["type_description"], *description["referenced_type_descriptions"]]}
    referenced, waiting = set(), [f["type"]["nested_type_name"] for f in known[name]["fields"]]
    while waiting:
        nested = waiting.pop()
        if nested and nested not in referenced:
            referenced.add(nested)
            waiting += [f["type"]["nested_type_name"] for f in known[nested]["fields"]]
    text = json.dumps(
        {"type_description": known[name], "referenced_type_descriptions": [known[n] for n in sorted(referenced)]},
        separators=(", ", ": "),
    )
    return "RIHS01_" + hashlib.sha256(text.encode()).hexdigest()


def test_service_events_hash_as_ros():
    events = [name for name in GOLDENS if name.endswith("_Event")]
    assert events and set(GOLDENS) == set(WITH_CLASS) | set(events)
    for event in events:
        service = codec.get_type(event.removesuffix("_Event"))
        assert _sub_hash(typehash.type_description(service), event) == GOLDENS[event], event


def test_description_shape():
    description = typehash.type_description(codec.get_type("std_srvs/srv/SetBool"))
    top = description["type_description"]
    assert [f["name"] for f in top["fields"]] == ["request_message", "response_message", "event_message"]
    names = [d["type_name"] for d in description["referenced_type_descriptions"]]
    assert names == sorted(names) and "service_msgs/msg/ServiceEventInfo" in names
    # An empty message has rosidl's placeholder field.
    assert (
        typehash.type_description(Empty)["type_description"]["fields"][0]["name"]
        == "structure_needs_at_least_one_member"
    )


def test_bounded_types_and_arrays_change_the_hash(tmp_path):
    root = tmp_path / "hash_root"
    (root / "hash_pkg" / "msg").mkdir(parents=True)
    definitions = {
        "A": "string<=5 s\n",
        "B": "string s\n",
        "C": "int32[3] v\n",
        "D": "int32[<=3] v\n",
        "E": "int32[] v\n",
    }
    for name, text in definitions.items():
        (root / "hash_pkg" / "msg" / f"{name}.msg").write_text(text)
    from actors.messages import generate as idl_gen

    idl_gen.generate([root])
    codec.register_root(root)
    fields = {
        n: typehash.type_description(codec.get_type(f"hash_pkg/msg/{n}"))["type_description"]["fields"][0]["type"]
        for n in definitions
    }
    assert (fields["A"]["type_id"], fields["A"]["string_capacity"]) == (21, 5)
    assert (fields["C"]["type_id"], fields["C"]["capacity"]) == (54, 3)
    assert (fields["D"]["type_id"], fields["D"]["capacity"]) == (102, 3)
    assert (fields["E"]["type_id"], fields["E"]["capacity"]) == (150, 0)
    assert len({codec.type_hash(f"hash_pkg/msg/{n}") for n in definitions}) == 5
