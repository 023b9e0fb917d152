"""The Zenoh session a graph opens: its defaults, the ``[transport]`` keys, the environment.

By default a graph is a Zenoh *peer* that reaches nothing beyond this
machine: it listens on ``tcp/127.0.0.1:7447`` and on a free loopback port,
and connects to ``tcp/127.0.0.1:7447``, with multicast scouting off.  The
first graph (or ``zenohd``, or ROS 2's ``rmw_zenohd`` router) to take port
7447 is where the others meet; each also listens on a port of its own, so
that, told of each other by gossip, the peers connect directly and keep
talking when the first one stops.  Peers connect with no wait at start:
discovery goes on in the background.

Settings, later ones winning:

1. a Zenoh config file: ``[transport] config = "zenoh.json5"``, else
   ``$ZENOH_SESSION_CONFIG_URI`` (rmw_zenoh's variable); with a file, the
   defaults above are not applied, only what the graph sets;
2. ``[transport]`` ``mode``, ``connect`` and ``listen``;
3. ``$ZENOH_CONFIG_OVERRIDE``: ``key=value`` pairs separated by ``;``, each
   value JSON5, as rmw_zenoh reads it (``mode="client";connect/endpoints=["tcp/10.0.0.2:7447"]``).

The domain is ``[transport] domain_id``, else ``$ROS_DOMAIN_ID``, else 0.
``zenoh`` itself (the ``eclipse-zenoh`` package) is imported only here, when
a transport starts.
"""

from __future__ import annotations

import json
import os
from types import ModuleType
from typing import Any

from actors.errors import TransportError
from actors.launch.graph_file import TransportSection

__all__ = ["INSTALL_HINT", "RENDEZVOUS", "load_zenoh", "domain_id", "session_config"]

INSTALL_HINT = "the zenoh transport needs eclipse-zenoh: pip install 'actors[zenoh]'"
RENDEZVOUS = "tcp/127.0.0.1:7447"
"""Where local graphs (and a local Zenoh router) meet by default."""


def load_zenoh() -> ModuleType:
    """The ``zenoh`` module; TransportError with the install hint when it is missing."""
    try:
        import xxhash  # noqa: F401 - GIDs (attachment.gid_of)
        import zenoh
        import zenoh.ext
    except ImportError:
        raise TransportError(INSTALL_HINT) from None
    return zenoh


def domain_id(section: TransportSection) -> int:
    """The ROS domain: the section's, else ``$ROS_DOMAIN_ID``, else 0; TransportError if malformed."""
    if section.domain_id is not None:
        return section.domain_id
    text = os.environ.get("ROS_DOMAIN_ID", "").strip()
    if not text:
        return 0
    if not text.isdigit() or int(text) > 232:
        raise TransportError(f"ROS_DOMAIN_ID must be a number from 0 to 232, got {text!r}")
    return int(text)


def _defaults(mode: str) -> dict[str, Any]:
    settings: dict[str, Any] = {
        "scouting/multicast/enabled": False,
        "scouting/delay": 0,
        "connect/endpoints": [RENDEZVOUS],
        "connect/timeout_ms": 0,
        "connect/exit_on_failure": False,
    }
    if mode == "peer":
        settings["listen/endpoints"] = [RENDEZVOUS, "tcp/127.0.0.1:0"]
        settings["listen/exit_on_failure"] = False
    return settings


def _insert(config: Any, key: str, json5: str, where: str) -> None:
    try:
        config.insert_json5(key, json5)
    except Exception as exc:  # zenoh raises its own ZError for an unknown key or a bad value
        raise TransportError(f"{where}: cannot set {key} = {json5}: {exc}") from None


def session_config(section: TransportSection) -> Any:
    """The ``zenoh.Config`` of a session for ``section`` (see the module docstring).

    Raises TransportError naming the file, key or variable that is wrong, or
    when zenoh is not installed.
    """
    zenoh = load_zenoh()
    path = section.config or os.environ.get("ZENOH_SESSION_CONFIG_URI", "")
    if path:
        try:
            config = zenoh.Config.from_file(path)
        except Exception as exc:
            raise TransportError(f"zenoh config {path}: {exc}") from None
        settings: dict[str, Any] = {}
    else:
        config = zenoh.Config()
        settings = _defaults(section.mode)
    settings["mode"] = section.mode
    if section.connect is not None:
        settings["connect/endpoints"] = section.connect
    if section.listen is not None:
        settings["listen/endpoints"] = section.listen
    for key, value in settings.items():
        _insert(config, key, json.dumps(value), "[transport]")
    for pair in filter(None, (p.strip() for p in os.environ.get("ZENOH_CONFIG_OVERRIDE", "").split(";"))):
        key, sep, value = pair.partition("=")
        if not sep or not key.strip() or not value.strip():
            raise TransportError(f"ZENOH_CONFIG_OVERRIDE: expected key=value, got {pair!r}")
        _insert(config, key.strip(), value.strip(), "ZENOH_CONFIG_OVERRIDE")
    return config
