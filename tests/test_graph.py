"""Graph files: the schema, and one clear line naming file and key path for every mistake."""

from __future__ import annotations

from pathlib import Path

import pytest

from actors.errors import GraphFileError
from actors.launch.graph_file import load_graph
from actors.system.supervisor import RestartType, Strategy


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
        ('[runtime]\nclok = "wall"\n', "runtime.clok: unknown key (did you mean 'clock'?)"),
        ('[supervisor]\nintensity = "three"\n', "supervisor.intensity: expected an integer, got the string 'three'"),
        ('[runtime]\nclock = "sundial"\n', "runtime.clock: 'sundial' is not one of "),
        (
            '[supervisor]\nstrategy = "one_for_al"\n',
            "supervisor.strategy: 'one_for_al' is not one of one_for_one, one_for_all, rest_for_one "
            "(did you mean 'one_for_all'?)",
        ),
        ("[runtime]\nduration = -1\n", "runtime.duration: expected a number >= 0"),
        ('[[nodes]]\nname = "x"\n', "nodes[0].use: missing required key"),
        ('[[nodes]]\nuse = "nodes.nope:Missing"\n', "nodes[0].use: cannot import 'nodes.nope'"),
        ('[[nodes]]\nuse = "nodes.talker:Nope"\n', "nodes[0].use: module 'nodes.talker' has no 'Nope'"),
        ('[[nodes]]\nuse = "nodes.talker"\n', "nodes[0].use: expected 'module:Class'"),
        ('[[nodes]]\nuse = "actors:Runtime"\n', "nodes[0].use: 'actors:Runtime' is not a subclass"),
        ('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nname = "bad name"\n', "nodes[0].name: invalid node name"),
        (
            '[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nrestart = "always"\n',
            "nodes[0].restart: 'always' is not one of permanent, transient, temporary",
        ),
        (
            '[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nparms = {}\n',
            "nodes[0].parms: unknown key (did you mean 'params'?)",
        ),
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


PARAMS_YAML = """\
/**:
  ros__parameters: {everyone: 1}
talker:
  ros__parameters: {rate: 2.0, limits: {max: 3}}
/robot1/talker:
  ros__parameters: {rate: 5.0}
"""


def test_a_params_file_gives_each_node_what_its_full_name_matches(tmp_path):
    (tmp_path / "params.yaml").write_text(PARAMS_YAML)
    path = write(
        tmp_path,
        """
[[nodes]]
use = "nodes.talker:MinimalPublisher"
name = "talker"
params_file = "params.yaml"
params = { everyone = 7 }

[[nodes]]
use = "nodes.talker:MinimalPublisher"
name = "talker"
namespace = "robot1"
params_file = "params.yaml"
""",
    )
    graph, _ = load_graph(path)
    assert graph.nodes[0].params == {"everyone": 7, "rate": 2.0, "limits.max": 3}  # params win over the file
    assert graph.nodes[1].params == {"everyone": 1, "rate": 5.0}


NODES_PY = """\
from actors import Node

NAME = "computed"


class Configured(Node):
    def __init__(self):
        super().__init__("configured")


class Computed(Node):
    def __init__(self):
        super().__init__(NAME)
"""


def nodes_module(folder: Path) -> str:
    """NODES_PY in ``folder`` under a module name of its own (one process imports each name once)."""
    name = f"nodes_{folder.name}"
    (folder / f"{name}.py").write_text(NODES_PY)
    return name


def test_a_params_file_matches_the_name_the_node_gives_itself(tmp_path):
    (tmp_path / "params.yaml").write_text("/configured:\n  ros__parameters: {rate: 2.0}\n")
    use = f"{nodes_module(tmp_path)}:Configured"
    path = write(tmp_path, f'[[nodes]]\nuse = "{use}"\nparams_file = "params.yaml"\n')
    assert load_graph(path)[0].nodes[0].params == {"rate": 2.0}


@pytest.mark.parametrize(
    ("yaml", "name", "expected"),
    [
        (PARAMS_YAML, None, "has parameters for /talker, /robot1/talker: give the node a `name`"),
        ("talker: 3", '"talker"', "params.yaml: talker: expected a namespace or a node holding ros__parameters"),
        (None, '"talker"', "cannot read the parameter file"),
    ],
)
def test_params_file_mistakes_name_the_key(tmp_path, yaml, name, expected):
    if yaml is not None:
        (tmp_path / "params.yaml").write_text(yaml)
    use = f"{nodes_module(tmp_path)}:Computed"  # its name is known only once it runs
    name_line = f"name = {name}\n" if name else ""
    path = write(tmp_path, f'[[nodes]]\nuse = "{use}"\n{name_line}params_file = "params.yaml"\n')
    with pytest.raises(GraphFileError) as info:
        load_graph(path)
    assert str(info.value).startswith(f"{path}: nodes[0].params_file: ")
    assert expected in str(info.value)


def test_a_params_file_of_wildcards_needs_no_name(tmp_path):
    (tmp_path / "params.yaml").write_text("/**:\n  ros__parameters: {everyone: 1}\n")
    path = write(tmp_path, '[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nparams_file = "params.yaml"\n')
    assert load_graph(path)[0].nodes[0].params == {"everyone": 1}
