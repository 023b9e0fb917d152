"""Write the golden files from real ROS 2 (Kilted): rclpy's CDR bytes and ROS's RIHS01 type hashes.

Run from the repository root where the ROS 2 wheels are installed
(``pip install -e '.[bench-ros]'`` plus the message packages listed in
``ROS_PACKAGES`` below, e.g. ``pip install ros-sensor-msgs ...``):

    ROS_LOG_DIR=/tmp/ros-log RMW_IMPLEMENTATION=rmw_fastrtps_cpp python tests/goldens/make_goldens.py

It writes ``cdr.json`` (per shipped message type: seeded random values and
the default, each with the hex bytes rclpy's ``serialize_message`` made of
it) and ``hashes.json`` (every shipped type and every type its description
references, with ROS's hash).  Hashes come from the installed packages'
own type description files (``share/<pkg>/<kind>/<Name>.json``); for the
shipped packages that have no wheel (example_interfaces,
tutorial_interfaces) ROS's own generator hashes our ``.msg``/``.srv``/
``.action`` sources (rosidl_adapter to IDL, then
rosidl_generator_type_description).  The tests read both files without
ROS installed.
"""

from __future__ import annotations

import json
import sys
import sysconfig
import tempfile
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent.parent), str(HERE.parent)]

from actors import codec  # noqa: E402
from actors.messages.idl import shipped_root  # noqa: E402
from goldens.ros import rclpy_class, same_wire, to_rclpy  # noqa: E402
from goldens.values import RandomPick, message, shipped_messages, shipped_types  # noqa: E402

SEEDS = (1, 2, 3)
ROS_PACKAGES = (
    "ros-rclpy ros-std-msgs ros-std-srvs ros-geometry-msgs ros-sensor-msgs ros-nav-msgs ros-rcl-interfaces "
    "ros-builtin-interfaces ros-service-msgs ros-action-msgs ros-unique-identifier-msgs "
    "ros-type-description-interfaces ros-rosidl-adapter ros-rosidl-generator-type-description"
)
SHARE = Path(sysconfig.get_paths()["data"]) / "share"  # where the ROS wheels put share/<pkg>


def cdr_goldens() -> tuple[list[dict], list[str]]:
    """The CDR entries of every shipped message rclpy has, and the types it lacks."""
    from rclpy.serialization import serialize_message

    entries, missing = [], []
    for name in shipped_messages():
        cls = codec.get_type(name)
        try:
            rclpy_class(name)
        except ImportError:
            missing.append(name)
            continue
        values = [cls(), *(message(cls, RandomPick(zlib.crc32(f"{name} {seed}".encode()))) for seed in SEEDS)]
        for value in values:
            data = serialize_message(to_rclpy(value))
            problem = same_wire(value, data)
            if problem:
                print(f"warning: {name}: {problem}", file=sys.stderr)
            entries.append({"type": name, "value": codec.to_builtins(value), "cdr": data.hex()})
    return entries, missing


def installed_hashes(kind_name: str) -> dict[str, str] | None:
    """The hashes in the installed type description file of ``pkg/kind/Name``, or None."""
    path = SHARE / f"{kind_name}.json"
    if not path.exists():
        return None
    return {entry["type_name"]: entry["hash_string"] for entry in json.loads(path.read_text())["type_hashes"]}


def generated_hashes(package: str) -> dict[str, str]:
    """Hashes ROS's own generator computes from our sources of ``package``."""
    from rosidl_adapter import convert_to_idl
    from rosidl_generator_type_description import generate_type_hash

    source = shipped_root() / package
    with tempfile.TemporaryDirectory() as tmp:
        idl_dir, out_dir = Path(tmp) / "idl", Path(tmp) / "out"
        tuples = []
        for path in sorted(source.glob("*/*.*")):
            if path.suffix in (".msg", ".srv", ".action"):
                relative = path.relative_to(source)
                convert_to_idl(source, package, relative, idl_dir / package)
                tuples.append(f"{idl_dir / package}:{relative.with_suffix('.idl')}")
        includes = [f"{pkg.name}:{pkg}" for pkg in SHARE.iterdir() if pkg.is_dir()]
        arguments = Path(tmp) / "arguments.json"
        arguments.write_text(
            json.dumps(
                {"package_name": package, "output_dir": str(out_dir), "idl_tuples": tuples, "include_paths": includes}
            )
        )
        hashes = {}
        for written in generate_type_hash(str(arguments)):
            hashes.update(
                {e["type_name"]: e["hash_string"] for e in json.loads(Path(written).read_text())["type_hashes"]}
            )
    return hashes


def hash_goldens() -> dict[str, str]:
    """ROS's hash of every shipped type and of every type their descriptions reference."""
    hashes: dict[str, str] = {}
    generated: set[str] = set()
    for name in shipped_types():
        found = installed_hashes(name)
        if found is None:
            package = name.split("/")[0]
            if package not in generated:
                generated.add(package)
                hashes.update(generated_hashes(package))
            if name not in hashes:
                raise SystemExit(f"no hash found for {name}")
        else:
            hashes.update(found)
    return dict(sorted(hashes.items()))


def main() -> None:
    """Write cdr.json and hashes.json beside this script."""
    try:
        import rclpy  # noqa: F401
    except ImportError:
        raise SystemExit(f"rclpy is not installed: pip install {ROS_PACKAGES}") from None
    from importlib.metadata import version

    entries, missing = cdr_goldens()
    made_with = {"rclpy": version("ros-rclpy"), "rmw": "rmw_fastrtps_cpp " + version("ros-rmw-fastrtps-cpp")}
    (HERE / "cdr.json").write_text(
        json.dumps({"made_with": made_with, "no_rclpy_type": missing, "messages": entries}, indent=1) + "\n"
    )
    hashes = hash_goldens()
    (HERE / "hashes.json").write_text(json.dumps({"made_with": made_with, "hashes": hashes}, indent=1) + "\n")
    print(f"wrote {len(entries)} CDR goldens ({len(missing)} types rclpy lacks) and {len(hashes)} hashes")


if __name__ == "__main__":
    main()
