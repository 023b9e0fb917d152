"""Launch files: 100 nodes started from a ROS 2 launch file, against the same graph as a TOML file.

Run: ``python -m bench.launch [--quick]``.  Each sample is a fresh process,
timed from its start until the hundredth talker's first message is on its
output (the talkers tick after 0.5 s of virtual time, which takes no wall
time): interpreter, imports, reading the file, starting 100 nodes.  The
launch file (``.launch.py`` and ``.launch.xml``, each node a ``Node`` of the
shipped ``actors_tutorials`` package) and the TOML graph (``use =
"nodes.talker:MinimalPublisher"``) describe the same 100 nodes; the row
"launch file less TOML" is what reading and translating the launch file
adds.  ``python -c`` printing the line is the floor.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from bench.harness import Result, side_by_side, standalone, time_to_line

__all__ = ["run", "write_files", "NODES"]

NODES = 100
SCENARIO = f"n. launch, {NODES} nodes"
MARKER = f"[talker{NODES - 1}]: Publishing"


def write_files(folder: Path, count: int = NODES) -> dict[str, Path]:
    """The same ``count`` talkers as a .launch.py, a .launch.xml and a TOML graph file, in ``folder``."""
    nodes = "\n".join(
        f"        Node(package='actors_tutorials', executable='talker', name='talker{i}')," for i in range(count)
    )
    python = folder / "talkers.launch.py"
    python.write_text(
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
        f"def generate_launch_description():\n    return LaunchDescription([\n{nodes}\n    ])\n"
    )
    xml = folder / "talkers.launch.xml"
    xml.write_text(
        "<launch>\n"
        + "".join(f'  <node pkg="actors_tutorials" exec="talker" name="talker{i}"/>\n' for i in range(count))
        + "</launch>\n"
    )
    toml = folder / "talkers.toml"
    toml.write_text(
        "".join(f'[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\nname = "talker{i}"\n\n' for i in range(count))
    )
    return {"launch file (.launch.py)": python, "launch file (.launch.xml)": xml, "TOML graph": toml}


def run(quick: bool = False) -> list[Result]:
    """Seconds to the hundredth node's first message: launch files and the TOML graph, side by side."""
    reps = 3 if quick else 7
    virtual = ["--clock", "virtual", "--duration", "5"]
    with tempfile.TemporaryDirectory() as tmp:
        files = write_files(Path(tmp))
        commands = {
            name: ["-m", "actors", "launch", *virtual, str(path)] if "launch" in name else
            ["-m", "actors.run", str(path), *virtual]
            for name, path in files.items()
        }  # fmt: skip
        commands["python -c (floor)"] = ["-c", f"print('{MARKER}')"]
        samples = side_by_side(
            {name: (lambda args=args: time_to_line(args, MARKER, stderr_too=True)) for name, args in commands.items()},
            reps,
            warmup=False,
        )
    toml = samples["TOML graph"]
    results = [Result(SCENARIO, name, "s", values, False) for name, values in samples.items()]
    for name in ("launch file (.launch.py)", "launch file (.launch.xml)"):
        # Paired by turn: each launch sample less the TOML sample taken just after it.
        extra = [a - b for a, b in zip(samples[name], toml)]
        results.append(Result(SCENARIO, f"{name} less TOML", "s", extra, False))
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "3 runs instead of 7")
