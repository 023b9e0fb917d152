"""Which frames of a traceback or a stack are the user's own, and not the machinery's."""

from __future__ import annotations

from types import FrameType, TracebackType

__all__ = ["is_users", "users_traceback"]

# Frames from these top-level packages are the machinery, not the user's code: actors itself,
# the shipped interface modules, the libraries it runs on, and the standard library's parts
# that start threads, modules and event loops.
_MACHINERY = frozenset(
    {
        "actors",
        "interfaces",
        "anyio",
        "asyncio",
        "runpy",
        "contextlib",
        "sniffio",
        "importlib",
        "selectors",
        "threading",
        "concurrent",
        "uvloop",
    }
)


def is_users(frame: FrameType) -> bool:
    """Whether ``frame`` runs the user's code (a script, a node module, a test), not the machinery's."""
    spec = frame.f_globals.get("__spec__")  # __name__ is "__main__" under python -m
    module = str(getattr(spec, "name", None) or frame.f_globals.get("__name__", ""))
    return module.partition(".")[0] not in _MACHINERY and not module.startswith("<frozen")


def users_traceback(tb: TracebackType | None) -> TracebackType | None:
    """``tb`` with only the user's frames, in order; None when it has none of them."""
    kept = [entry for entry in _entries(tb) if is_users(entry.tb_frame)]
    result: TracebackType | None = None
    for entry in reversed(kept):
        result = TracebackType(result, entry.tb_frame, entry.tb_lasti, entry.tb_lineno)
    return result


def _entries(tb: TracebackType | None) -> list[TracebackType]:
    entries = []
    while tb is not None:
        entries.append(tb)
        tb = tb.tb_next
    return entries
