"""``actors param describe|delete|load`` against a graph served in this process."""

from __future__ import annotations

import contextlib
from collections.abc import AsyncIterator
from pathlib import Path

import anyio
import pytest
import yaml

from actors import Node, Runtime
from actors.cli import main
from actors.ops.control import ControlEndpoint
from interfaces.rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor


class Tuned(Node):
    """Parameters of every kind ``param describe`` prints."""

    def __init__(self) -> None:
        super().__init__("tuned")
        speed = ParameterDescriptor(
            description="forward speed, m/s",
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0, step=0.1)],
        )
        self.declare_parameter("speed", 0.5, speed)
        self.declare_parameter("mode", "idle", ParameterDescriptor(read_only=True))
        laps = ParameterDescriptor(
            integer_range=[IntegerRange(from_value=1, to_value=9)],
            additional_constraints="odd numbers look best",
        )
        self.declare_parameter("laps", 3, laps)
        self.declare_parameter("pid.kp", 1.0)
        self.declare_parameter("scratch", 7, ParameterDescriptor(dynamic_typing=True))
        self.declare_parameter("gains", [0.5, 1.5])
        self.declare_parameter("ids", [1, 2])


@pytest.fixture
def endpoints(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))


@contextlib.asynccontextmanager
async def tuned() -> AsyncIterator[Runtime]:
    """The graph, served to the command line (in the test's own task: a task group's rule)."""
    async with Runtime(name="cli_param", attach=[ControlEndpoint()]) as rt:
        rt.spawn(Tuned)
        yield rt


async def actors(capsys, *argv: str) -> tuple[int, str, str]:
    """``actors ARGS`` in a thread (the command line blocks), beside the graph on this loop."""
    code = await anyio.to_thread.run_sync(main, list(argv))
    out, err = capsys.readouterr()
    return code, out, err


async def test_describe_prints_type_description_and_constraints(endpoints, capsys):
    async with tuned():
        code, out, err = await actors(capsys, "param", "describe", "/tuned", "speed", "mode", "laps")
        assert (code, err) == (0, "")
        assert out == (
            "Parameter name: speed\n"
            "  Type: double\n"
            "  Description: forward speed, m/s\n"
            "  Constraints:\n"
            "    Min value: 0.0\n"
            "    Max value: 1.0\n"
            "    Step: 0.1\n"
            "Parameter name: mode\n"
            "  Type: string\n"
            "  Constraints:\n"
            "    Read only: true\n"
            "Parameter name: laps\n"
            "  Type: integer\n"
            "  Constraints:\n"
            "    Min value: 1\n"
            "    Max value: 9\n"
            "    Additional constraints: odd numbers look best\n"
        )
        assert await actors(capsys, "param", "describe", "tuned", "nothing") == (
            2,
            "",
            "actors: parameter 'nothing' is not declared on /tuned\n",
        )


async def test_delete_undeclares_a_dynamically_typed_parameter_and_refuses_a_static_one(endpoints, capsys):
    async with tuned() as rt:
        assert await actors(capsys, "param", "delete", "/tuned", "scratch") == (
            0,
            "Deleted parameter successfully\n",
            "",
        )
        assert not rt.node("tuned").has_parameter("scratch")
        assert await actors(capsys, "param", "delete", "/tuned", "speed") == (
            1,
            "",
            "Deleting parameter failed: Static parameter cannot be undeclared\n",
        )
        assert rt.node("tuned").get_parameter("speed").value == 0.5


async def test_load_sets_what_the_file_gives_the_node_each_on_its_own(endpoints, capsys, tmp_path):
    async with tuned() as rt:
        params = tmp_path / "tuned.yaml"
        params.write_text(
            yaml.safe_dump(
                {
                    "/**": {"ros__parameters": {"speed": 0.2}},
                    "/tuned": {"ros__parameters": {"laps": 5, "pid": {"kp": 2.5}, "mode": "race"}},
                    "/other": {"ros__parameters": {"laps": 1}},
                }
            )
        )
        code, out, err = await actors(capsys, "param", "load", "/tuned", str(params))
        assert code == 1  # mode is read-only
        assert out == (
            "Set parameter speed successful\nSet parameter laps successful\nSet parameter pid.kp successful\n"
        )
        assert err == "Set parameter mode failed: parameter 'mode' is read-only\n"
        node = rt.node("tuned")
        assert [node.get_parameter(n).value for n in ("speed", "laps", "pid.kp", "mode")] == [
            0.2,
            5,
            2.5,
            "idle",
        ]


async def test_load_without_the_wildcard_and_a_file_with_nothing_for_the_node(endpoints, capsys, tmp_path):
    async with tuned():
        params = tmp_path / "all.yaml"
        params.write_text("/**:\n  ros__parameters:\n    speed: 0.3\n")
        code, out, err = await actors(capsys, "param", "load", "/tuned", str(params), "--no-use-wildcard")
        assert (code, out, err) == (2, "", f"actors: {params} has no parameters for /tuned\n")
        assert (await actors(capsys, "param", "load", "/tuned", str(params)))[:2] == (
            0,
            "Set parameter speed successful\n",
        )


async def test_a_file_that_is_not_a_parameters_file_is_one_line_and_exit_2(endpoints, capsys, tmp_path):
    async with tuned():
        bad = tmp_path / "bad.yaml"
        bad.write_text("/tuned:\n  speed: 0.3\n")  # no ros__parameters
        code, out, err = await actors(capsys, "param", "load", "/tuned", str(bad))
        assert (code, out) == (2, "")
        assert err.startswith(f"actors: {bad}") and len(err.splitlines()) == 1
        missing = Path(tmp_path / "missing.yaml")
        code, _, err = await actors(capsys, "param", "load", "/tuned", str(missing))
        assert code == 2 and err.startswith(f"actors: {missing}")


async def test_array_parameters_are_set_and_dumped_as_lists(endpoints, capsys):
    # The request and the reply carry a ParameterValue, whose array fields hold array.array.
    async with tuned():
        for name, value in (("gains", "[1.0, 2.5]"), ("ids", "[3, 4]")):
            code, out, err = await actors(capsys, "param", "set", "/tuned", name, value)
            assert (code, out.strip(), err) == (0, "Set parameter successful", "")
        code, out, err = await actors(capsys, "param", "dump", "/tuned")
    assert code == 0 and err == ""
    parameters = yaml.safe_load(out)["/tuned"]["ros__parameters"]
    assert (parameters["gains"], parameters["ids"]) == ([1.0, 2.5], [3, 4])
