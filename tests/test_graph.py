"""Graph files: the schema, and one clear line naming file and key path for every mistake."""

from __future__ import annotations

import pytest

from actors.errors import GraphFileError
from actors.graph import load_graph
from actors.supervisor import RestartType, Strategy


def write(tmp_path, text):
    path = tmp_path / "g.toml"
    path.write_text(text)
    return path


def test_the_full_schema_decodes(tmp_path):
    path = write(
        tmp_path,
        """
[runtime]
clock = "virtual"
duration = 10
log_level = "debug"

[supervisor]
strategy = "rest_for_one"
intensity = 5
period = 2.5
backoff = 0.2
max_backoff = 1.0

[[nodes]]
use = "nodes.talker:MinimalPublisher"
name = "talker"
namespace = "robot1"
params = { rate = 2.0 }
remap = { topic = "chatter" }
restart = "permanent"
""",
    )
    graph, classes = load_graph(path)
    assert graph.runtime.clock == "virtual" and graph.runtime.duration == 10.0
    assert graph.supervisor.policy().strategy is Strategy.REST_FOR_ONE
    (node,) = graph.nodes
    assert (node.name, node.namespace, node.restart) == ("talker", "robot1", RestartType.PERMANENT)
    assert node.params == {"rate": 2.0} and node.remap == {"topic": "chatter"}
    assert classes[0].__name__ == "MinimalPublisher"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ('[runtime]\nclok = "wall"\n', "runtime.clok: unknown key"),
        ("[supervisor]\nintensity = \"three\"\n", "supervisor.intensity: expected an integer, got a string"),
        ('[runtime]\nclock = "sundial"\n', "runtime.clock: invalid enum value 'sundial'"),
        ("[runtime]\nduration = -1\n", "runtime.duration: expected a number >= 0"),
        ('[[nodes]]\nname = "x"\n', "nodes[0].use: missing required key"),
        ('[[nodes]]\nuse = "nodes.nope:Missing"\n', "nodes[0].use: cannot import 'nodes.nope'"),
        ('[[nodes]]\nuse = "nodes.talker:Nope"\n', "nodes[0].use: module 'nodes.talker' has no 'Nope'"),
        ('[[nodes]]\nuse = "nodes.talker"\n', "nodes[0].use: expected 'module:Class'"),
        ('[[nodes]]\nuse = "actors:Runtime"\n', "nodes[0].use: 'actors:Runtime' is not a subclass"),
        ('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nname = "bad name"\n', "nodes[0].name: invalid node name"),
        ('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nrestart = "always"\n', "nodes[0].restart: invalid enum value"),
        ("[runtime\n", "TOML syntax error"),
    ],
)
def test_mistakes_name_the_file_and_key_path(tmp_path, text, expected):
    path = write(tmp_path, text)
    with pytest.raises(GraphFileError) as info:
        load_graph(path)
    message = str(info.value)
    assert message.startswith(f"{path}: ")
    assert expected in message
    assert "\n" not in message


def test_a_missing_file(tmp_path):
    with pytest.raises(GraphFileError, match="cannot read"):
        load_graph(tmp_path / "absent.toml")
