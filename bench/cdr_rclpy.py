"""rclpy's side of scenario i (CDR), in a child process that imports nothing of actors, nor msgspec.

``python -m bench.cdr_rclpy FILE``: FILE holds JSON, ``{"reps": 7, "samples":
{name: {"type": "pkg/msg/Name", "cdr": hex, "loops": n}}}``, the CDR of each
sample as actors encodes it.  The child decodes each with rclpy's
``deserialize_message``, then times ``serialize_message`` and
``deserialize_message`` of it, and prints one JSON line: per sample the µs per
call of each (``encode``, ``decode``) and the bytes rclpy serialised
(``cdr``, hex), for the parent to check they hold the same values.

Why a module of its own: with msgspec imported first (any actors module),
rclpy's ``deserialize_message`` of a large Image was many times slower in
the same process (the allocator's state, not rclpy's work), so rclpy is
measured as a program that uses only rclpy runs.
"""

from __future__ import annotations

import importlib
import json
import sys
from typing import Any

from bench.harness import micros_per_call, repeat

__all__ = ["measure"]


def measure(spec: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """Each sample's rclpy timings and re-serialised bytes (see the module docstring)."""
    from rclpy.serialization import deserialize_message, serialize_message

    out: dict[str, dict[str, Any]] = {}
    for name, sample in spec["samples"].items():
        pkg, kind, type_name = sample["type"].split("/")
        cls = getattr(importlib.import_module(f"{pkg}.{kind}"), type_name)
        theirs = deserialize_message(bytes.fromhex(sample["cdr"]), cls)
        data = serialize_message(theirs)
        loops, reps = sample["loops"], spec["reps"]
        out[name] = {
            "encode": repeat(lambda: micros_per_call(lambda: serialize_message(theirs), loops), reps),
            "decode": repeat(lambda: micros_per_call(lambda: deserialize_message(data, cls), loops), reps),
            "cdr": data.hex(),
        }
    return out


if __name__ == "__main__":
    with open(sys.argv[1], encoding="utf-8") as file:
        print(json.dumps(measure(json.load(file))))
