"""Codec speed: encode and decode a Twist and a 360-beam LaserScan with msgpack and with JSON.

Run: ``python -m bench.codec [--quick]``.  Each sample times a loop of
messages; the table shows the median of the samples in µs per message, the
matching messages per second, and the ratio to pickle (the baseline: what
copying a message between processes costs without a codec; higher is better).
"""

from __future__ import annotations

import argparse
import math
import pickle
from collections.abc import Callable
from typing import Any

from actors import codec
from bench.harness import Result, micros_per_call, repeat, table
from interfaces.geometry_msgs.msg import Twist, Vector3
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import Header

FORMATS: dict[str, tuple[Callable[[Any], bytes], Callable[[bytes, type], Any]]] = {
    "pickle": (pickle.dumps, lambda data, _type: pickle.loads(data)),
    "msgpack": (codec.encode, codec.decode),
    "json": (codec.encode_json, codec.decode_json),
}


def samples() -> dict[str, Any]:
    """The messages measured, by name."""
    beams = 360
    scan = LaserScan(
        header=Header(frame_id="base_scan"),
        angle_min=-math.pi,
        angle_max=math.pi,
        angle_increment=2 * math.pi / beams,
        range_min=0.12,
        range_max=3.5,
        ranges=[1.0 + math.sin(i / 10) for i in range(beams)],
        intensities=[100.0 + i for i in range(beams)],
    )
    return {"Twist": Twist(linear=Vector3(x=0.2), angular=Vector3(z=0.5)), "LaserScan[360]": scan}


def measure(loops: int, repetitions: int) -> list[Result]:
    """Encode and decode every sample in every format."""
    results = []
    for name, msg in samples().items():
        for fmt, (encode, decode) in FORMATS.items():
            data = encode(msg)
            assert decode(data, type(msg)) == msg
            cases = {"encode": lambda: encode(msg), "decode": lambda: decode(data, type(msg))}
            for verb, fn in cases.items():
                times = repeat(lambda: micros_per_call(fn, loops), repetitions)
                result = Result(name, f"{fmt} {verb}", "µs/msg", times, higher_better=False)
                result.note = f"{1e6 / result.median:,.0f} msg/s, {len(data)} B"
                if fmt != "pickle":
                    result.baselines = {"pickle": f"pickle {verb}"}
                results.append(result)
    return results


def main() -> None:
    """Print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer loops, for a smoke run")
    args = parser.parse_args()
    loops, repetitions = (200, 5) if args.quick else (5000, 7)
    print(table(measure(loops, repetitions)))


if __name__ == "__main__":
    main()
