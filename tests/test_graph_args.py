"""A graph file's launch arguments and includes: ``[args]``, ``$(var name)``, ``[[include]]``, ``--show-args``."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest
from conftest import python_env

from actors.errors import GraphFileError
from actors.launch.graph_file import load_graph

TALKER = 'use = "nodes.talker:MinimalPublisher"'


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def params_of(path, arguments=()):
    graph, _ = load_graph(path, arguments)
    return [(entry.name, entry.namespace, entry.params) for entry in graph.nodes]


def test_defaults_fill_whole_values_with_their_type_and_text_inside_strings(tmp_path):
    graph = write(
        tmp_path / "g.toml",
        f"""
        [args]
        speed = 0.2
        robot = {{ default = "bot", description = "the robot's name" }}
        loud = true

        [[nodes]]
        {TALKER}
        name = "$(var robot)_talker"
        params = {{ speed = "$(var speed)", loud = "$(var loud)", label = "at $(var speed), loud=$(var loud)" }}
        """,
    )
    assert params_of(graph) == [("bot_talker", "", {"speed": 0.2, "loud": True, "label": "at 0.2, loud=true"})]


def test_command_line_values_are_read_as_yaml(tmp_path):
    graph = write(
        tmp_path / "g.toml",
        f"""
        [args]
        speed = 0.2
        label = "x"
        on = false

        [[nodes]]
        {TALKER}
        params = {{ speed = "$(var speed)", label = "$(var label)", on = "$(var on)" }}
        """,
    )
    given = [("speed", "4"), ("label", "hello world"), ("on", "true")]
    assert params_of(graph, given)[0][2] == {"speed": 4, "label": "hello world", "on": True}


@pytest.mark.parametrize(
    ("args", "value", "given", "error"),
    [
        (
            'robot = { description = "its name" }',
            "$(var robot)",
            [],
            "argument 'robot' is required: give it as robot:=",
        ),
        (
            "speed = 0.2",
            "$(var speed)",
            [("sped", "1")],
            "no argument 'sped' (did you mean 'speed'?) (declared: speed)",
        ),
        ("speed = 0.2", "$(var sped)", [], "nodes[0].params.p: no argument 'sped' (did you mean 'speed'?)"),
        ("speed = 0.2", "$(env HOME)", [], "nodes[0].params.p: $(env ...): a graph file substitutes $(var name) only"),
        ("speed = 0.2", "a $(var speed", [], "nodes[0].params.p: $(var: expected $(var name)"),
        (
            "mode = { default = 'a', choices = ['a', 'b'] }",
            "$(var mode)",
            [("mode", "c")],
            "'c' is not one of ['a', 'b']",
        ),
        (
            "mode = { default = 'z', choices = ['a', 'b'] }",
            "$(var mode)",
            [],
            "args.mode: the default 'z' is not one of",
        ),
        ("mode = { default = 'a', colour = 'red' }", "$(var mode)", [], "args.mode: Object contains unknown field"),
    ],
)
def test_each_mistake_is_one_line_naming_the_file_and_key(tmp_path, args, value, given, error):
    graph = write(tmp_path / "g.toml", f'[args]\n{args}\n\n[[nodes]]\n{TALKER}\nparams = {{ p = "{value}" }}\n')
    with pytest.raises(GraphFileError) as raised:
        load_graph(graph, given)
    assert str(raised.value).startswith(f"{graph}: ") and error in str(raised.value)
    assert "\n" not in str(raised.value)


def test_an_include_gives_its_nodes_first_with_arguments_a_namespace_and_its_own_folder(tmp_path):
    # The included file's node module and parameter file sit beside it, not beside the including file;
    # the parameter file matches the node by its name in the pushed namespace, as rcl matches names.
    write(
        tmp_path / "parts/greeter.py",
        """
        from actors import Node

        class Greeter(Node):
            def __init__(self):
                super().__init__("greeter")
        """,
    )
    write(tmp_path / "parts/params.yaml", "/**/greeter:\n  ros__parameters:\n    volume: 11\n")
    write(
        tmp_path / "parts/world.toml",
        """
        [args]
        who = { description = "whom to greet" }

        [runtime]
        clock = "virtual"  # the including file's runtime is the one that counts

        [[nodes]]
        use = "greeter:Greeter"
        name = "greeter"
        params_file = "params.yaml"
        params = { who = "$(var who)" }
        """,
    )
    top = write(
        tmp_path / "top.toml",
        f"""
        [args]
        person = "ada"

        [[include]]
        file = "parts/world.toml"
        args = {{ who = "$(var person)" }}
        namespace = "robot1"

        [[nodes]]
        {TALKER}
        """,
    )
    graph, classes = load_graph(top, [("person", "grace")])
    assert [c.__name__ for c in classes] == ["Greeter", "MinimalPublisher"]
    assert graph.nodes[0].namespace == "/robot1" and graph.nodes[0].params == {"volume": 11, "who": "grace"}
    assert graph.runtime.clock == "wall"


def test_an_included_shipped_graph_is_found_by_name(tmp_path):
    top = write(tmp_path / "top.toml", '[[include]]\nfile = "params"\n')
    _, classes = load_graph(top)
    assert [c.__name__ for c in classes] == ["MinimalParam"]


def test_files_that_include_each_other_are_refused(tmp_path):
    write(tmp_path / "a.toml", f'[[include]]\nfile = "b.toml"\n\n[[nodes]]\n{TALKER}\n')
    write(tmp_path / "b.toml", f'[[include]]\nfile = "a.toml"\n\n[[nodes]]\n{TALKER}\n')
    with pytest.raises(
        GraphFileError, match=r"include: the files include each other: .*a\.toml -> .*b\.toml -> .*a\.toml"
    ):
        load_graph(tmp_path / "a.toml")


def test_a_name_taken_twice_through_an_include_names_both_places(tmp_path):
    write(tmp_path / "part.toml", f'[[nodes]]\n{TALKER}\nname = "same"\n')
    top = write(tmp_path / "top.toml", f'[[include]]\nfile = "part.toml"\n\n[[nodes]]\n{TALKER}\nname = "same"\n')
    with pytest.raises(
        GraphFileError, match=r"top\.toml: nodes\[0\]\.name: a node named /same is already nodes\[0\] of .*part\.toml"
    ):
        load_graph(top)


def actors(*argv, cwd):
    return subprocess.run(
        [sys.executable, "-m", "actors", *argv], cwd=cwd, env=python_env(), capture_output=True, text=True, timeout=120
    )


def test_actors_launch_takes_arguments_and_shows_them_as_ros2_launch_does(tmp_path):
    write(
        tmp_path / "hello.toml",
        """
        [args]
        who = { default = "world", description = "whom the node greets" }
        mode = { description = "how", choices = ["loud", "quiet"] }

        [runtime]
        clock = "virtual"

        [[nodes]]
        use = "nodes.param_talker:MinimalParam"
        params = { my_parameter = "$(var who), $(var mode)" }
        """,
    )
    shown = actors("launch", "hello.toml", "--show-args", cwd=tmp_path)
    assert shown.returncode == 0, shown.stderr
    assert shown.stdout == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'who':\n        whom the node greets\n        (default: 'world')\n\n"
        "    'mode':\n        how\n        Valid choices are: ['loud', 'quiet']\n        (required)\n"
    )
    ran = actors("launch", "hello.toml", "who:=earth", "--duration", "1.5", "mode:=loud", cwd=tmp_path)
    assert ran.returncode == 0, ran.stderr
    assert "Hello earth, loud!" in ran.stdout + ran.stderr
    missing = actors("launch", "hello.toml", "--duration", "1", cwd=tmp_path)
    assert missing.returncode == 2 and missing.stderr.count("\n") == 1, missing.stderr
    assert "argument 'mode' is required: give it as mode:=VALUE" in missing.stderr
    bad = actors("launch", "hello.toml", "mode=loud", "--duration", "1", cwd=tmp_path)
    assert bad.returncode == 2 and "graph arguments are name:=value, got 'mode=loud'" in bad.stderr
