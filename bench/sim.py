"""Real-time factor of the simulated world, through the nodes and for the bare core.

``python -m bench.sim [--quick]``.  Physics at 100 Hz, odometry at 20 Hz and a
360-beam scan at 10 Hz per robot.  "nodes" runs World + TurtleBot +
ConstantControl nodes on the virtual clock, publishing every message; "core"
drives the same robots through world.simulation alone (the floor: no runtime,
no messages).  The factor is simulated seconds per wall-clock second.
Target: the nodes at >= 0.6x the core's factor with 1 and 20 robots; 100 robots measured.
"""

from __future__ import annotations

import math
import time

import anyio

from actors import Runtime, VirtualTimeLoop
from bench.harness import Result, side_by_side, standalone
from nodes.constant_control import ConstantControl
from world.robot import TurtleBot
from world.sim import World
from world.simulation import Simulation

__all__ = ["run", "nodes_factor", "core_factor"]

PHYSICS_HZ = 100
SCAN_EVERY = 10  # steps: 10 Hz
ODOMETRY_EVERY = 5  # steps: 20 Hz
ROBOTS = (1, 20, 100)


def _grid(robots: int) -> list[tuple[float, float, float, float]]:
    """Start poses and turn rates: a grid over the arena's middle, each robot on its own arc."""
    side = math.ceil(math.sqrt(robots))
    return [
        (-3.0 + 6.0 * (i % side + 0.5) / side, -3.0 + 6.0 * (i // side + 0.5) / side, i * 0.7, 0.2 * ((i % 5) - 2))
        for i in range(robots)
    ]


def nodes_factor(robots: int, seconds: float) -> float:
    """Simulated seconds per wall second for the World, TurtleBot and ConstantControl nodes."""

    async def main() -> float:
        async with Runtime(name="bench_sim") as rt:
            rt.spawn(World, params={"world": "empty", "dt": 1.0 / PHYSICS_HZ})
            for i, (x, y, theta, omega) in enumerate(_grid(robots)):
                ns = f"tb{i}"
                rt.spawn(TurtleBot, namespace=ns, params={"x": x, "y": y, "theta": theta})
                rt.spawn(ConstantControl, namespace=ns, params={"v": 0.2, "omega": omega})
            start = time.perf_counter()
            await anyio.sleep(seconds)
            return seconds / (time.perf_counter() - start)

    return anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop})


def core_factor(robots: int, seconds: float) -> float:
    """The same robots, odometry and batched scans through the simulation core alone."""
    sim = Simulation.from_file("empty", dt=1.0 / PHYSICS_HZ)
    for i, (x, y, theta, omega) in enumerate(_grid(robots)):
        sim.add_robot(f"tb{i}", "burger", x=x, y=y, theta=theta).command(0.2, omega)
    robots_now = list(sim.robots.values())
    start = time.perf_counter()
    for k in range(round(seconds * PHYSICS_HZ)):
        sim.step()
        if k % ODOMETRY_EVERY == 0:
            for robot in robots_now:
                robot.odometry()
        if k % SCAN_EVERY == 0:
            sim.scan_all()
    return seconds / (time.perf_counter() - start)


def run(quick: bool = False) -> list[Result]:
    """Real-time factors for 1, 20 and 100 robots, nodes beside the bare core, in one run."""
    seconds = 10.0 if quick else 30.0
    results = []
    for robots in ROBOTS:
        scenario = f"g. sim RTF, {robots} robot{'s' if robots > 1 else ''}"
        samples = side_by_side(
            {"nodes": lambda: nodes_factor(robots, seconds), "core": lambda: core_factor(robots, seconds)}, 5
        )
        results.append(Result(scenario, "nodes", "× real time", samples["nodes"], baselines={"core": "core (floor)"}))
        results.append(Result(scenario, "core (floor)", "× real time", samples["core"]))
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "10 simulated seconds per run instead of 30")
