"""Write ``echo.json``: what ``ros2 topic echo`` prints for a few messages, with each of its format options.

ros2 topic echo prints through rosidl_runtime_py's ``message_to_yaml`` and
``message_to_csv``, which have no wheel; give a checkout of ros2/rosidl_runtime_py
(its top folder) as the argument, in the environment where the ROS 2 wheels
are installed (see ``make_goldens.py``):

    python tests/goldens/make_echo_goldens.py /path/to/rosidl_runtime_py

Each entry holds the message (as our builtins), the options, and the text
ros2 prints for it (its YAML with the ``---`` line, or its CSV line).  The
values are exact in float32, so rclpy's float32 arrays hold what we hold.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent.parent), str(HERE.parent)]

from actors import codec  # noqa: E402
from goldens.ros import to_rclpy  # noqa: E402

DEFAULT = 128  # ros2 topic echo's --truncate-length

MESSAGES = {
    "scan": (
        "sensor_msgs/msg/LaserScan",
        {"header": {"frame_id": "base_scan"}, "angle_max": 6.25, "ranges": [i / 4 for i in range(200)]},
    ),
    "long string": ("std_msgs/msg/String", {"data": "abc" * 60}),
    "bool": ("std_msgs/msg/Bool", {"data": True}),
    "poses": (
        "geometry_msgs/msg/PoseArray",
        {
            "header": {"frame_id": "map"},
            "poses": [{"position": {"x": float(i)}, "orientation": {"w": 1.0}} for i in range(3)],
        },
    ),
    "image": (
        "sensor_msgs/msg/Image",
        {"height": 1, "width": 150, "encoding": "mono8", "step": 150, "data": list(range(150))},
    ),
}

# (name, options): the options as our formatter names them; csv picks message_to_csv.
OPTIONS = [
    ("default", {"truncate_length": DEFAULT}),
    ("-l 2", {"truncate_length": 2}),
    ("-f", {}),
    ("--flow-style", {"truncate_length": DEFAULT, "flow_style": True}),
    ("--flow-style -l 2", {"truncate_length": 2, "flow_style": True}),
    ("--no-arr --no-str", {"truncate_length": DEFAULT, "no_arr": True, "no_str": True}),
    ("--csv", {"truncate_length": DEFAULT, "csv": True}),
    ("--csv -l 2", {"truncate_length": 2, "csv": True}),
    ("--csv --no-arr", {"truncate_length": DEFAULT, "csv": True, "no_arr": True}),
]


def main(checkout: str) -> None:
    sys.path.insert(0, checkout)
    from rosidl_runtime_py import message_to_csv, message_to_yaml

    entries = []
    for name, (ros_type, value) in MESSAGES.items():
        ours = codec.convert(value, codec.get_type(ros_type))
        theirs = to_rclpy(ours)
        for label, options in OPTIONS:
            opts = dict(options)
            if opts.pop("csv", False):
                printed = message_to_csv(theirs, **opts) + "\n"
            else:
                printed = message_to_yaml(theirs, **opts) + "---\n"
            entries.append(
                {
                    "message": name,
                    "flags": label,
                    "type": ros_type,
                    "value": codec.to_builtins(ours),
                    "options": options,
                    "printed": printed,
                }
            )
    (HERE / "echo.json").write_text(json.dumps(entries, indent=1) + "\n")
    print(f"wrote {len(entries)} entries to {HERE / 'echo.json'}")


if __name__ == "__main__":
    main(sys.argv[1])
