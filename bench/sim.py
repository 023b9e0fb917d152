"""Real-time factor of the pure simulation core (no nodes, no messages): ``python -m bench.sim``.

Physics runs at 100 Hz, every robot is scanned at 10 Hz and its odometry read
at 20 Hz, as the TurtleBot nodes will. The real-time factor is simulated
seconds per wall-clock second, the median over the repetitions. For scale: the
node version is to reach >= 200x with 1 robot and >= 10x with 20.
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

from world.simulation import Simulation

__all__ = ["main", "real_time_factor"]

PHYSICS_HZ = 100
SCAN_EVERY = 10  # steps: 10 Hz
ODOMETRY_EVERY = 5  # steps: 20 Hz


def real_time_factor(robots: int, seconds: float, *, batched: bool, world: str = "empty") -> float:
    """Run ``robots`` robots on arcs for ``seconds`` simulated seconds; return sim s per wall s.

    ``batched`` scans all robots with one ``scan_all()``, otherwise with one ``scan()`` each.
    """
    sim = Simulation.from_file(world, dt=1.0 / PHYSICS_HZ)
    side = math.ceil(math.sqrt(robots))
    for i in range(robots):
        # A grid over the middle of the arena, each robot on its own arc, meeting walls and robots.
        x = -3.0 + 6.0 * (i % side + 0.5) / side
        y = -3.0 + 6.0 * (i // side + 0.5) / side
        robot = sim.add_robot(f"tb{i}", "burger", x=x, y=y, theta=i * 0.7)
        robot.command(0.2, 0.4 * ((i % 5) - 2) / 2)
    names = list(sim.robots)
    steps = round(seconds * PHYSICS_HZ)
    start = time.perf_counter()
    for k in range(steps):
        sim.step()
        if k % ODOMETRY_EVERY == 0:
            for name in names:
                sim.robots[name].odometry()
        if k % SCAN_EVERY == 0:
            if batched:
                sim.scan_all()
            else:
                for name in names:
                    sim.scan(name)
    return seconds / (time.perf_counter() - start)


def main(argv: list[str] | None = None) -> None:
    """Print a table of real-time factors for 1 and 20 robots."""
    parser = argparse.ArgumentParser(
        prog="python -m bench.sim", description=__doc__.splitlines()[0]
    )
    parser.add_argument(
        "--seconds", type=float, default=30.0, help="simulated seconds per run (default 30)"
    )
    parser.add_argument(
        "--repeat", type=int, default=5, help="runs per case; the median is shown (default 5)"
    )
    args = parser.parse_args(argv)
    rates = f"scans {PHYSICS_HZ // SCAN_EVERY} Hz, odometry {PHYSICS_HZ // ODOMETRY_EVERY} Hz"
    print(
        f"physics {PHYSICS_HZ} Hz, {rates}, {args.seconds:g} s simulated, median of {args.repeat}"
    )
    print(f"{'robots':>6}  {'scans':<16}  {'real-time factor':>16}  {'min':>8}  {'max':>8}")
    for robots in (1, 20):
        for batched, how in ((False, "scan() each"), (True, "scan_all()")):
            factors = [
                real_time_factor(robots, args.seconds, batched=batched) for _ in range(args.repeat)
            ]
            low, median, high = min(factors), statistics.median(factors), max(factors)
            print(f"{robots:>6}  {how:<16}  {median:>15.0f}x  {low:>7.0f}x  {high:>7.0f}x")


if __name__ == "__main__":
    main()
