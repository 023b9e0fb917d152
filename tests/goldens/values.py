"""Random message values for any shipped type, from a seeded Random or from hypothesis, and the shipped types.

One walk over a type's layout (:func:`message`) builds a value; what it asks
for at each leaf comes from a ``Pick``: :class:`RandomPick` (seeded, for the
golden files) or :class:`DrawPick` (hypothesis's ``data.draw``).  Values stay
inside what every side can carry exactly: floats are finite, float32 values
are exactly representable in float32, strings hold no NUL (a C string ends
there) and no lone surrogate.
"""

from __future__ import annotations

import random
import struct
from typing import Any, Protocol

from actors import codec
from actors.messages._fields import MessageLayout, layout
from actors.messages.idl import FLOATS, INTEGER_RANGES, OCTETS, STRINGS, FieldType, shipped_root

__all__ = ["Pick", "RandomPick", "DrawPick", "message", "shipped_types", "shipped_messages", "float32"]

MAX_ITEMS = 4  # items in an unbounded sequence: enough for alignment, small goldens
ALPHABET = "abcXYZ019 _-/:é✓😀"  # ASCII, 2-, 3- and 4-byte UTF-8


def float32(value: float) -> float:
    """``value`` rounded to the nearest float32, as a Python float."""
    return struct.unpack("<f", struct.pack("<f", value))[0]


class Pick(Protocol):
    """Where the leaves of a random value come from."""

    def integer(self, low: int, high: int) -> int: ...
    def real(self, bits: int) -> float: ...
    def text(self, most: int) -> str: ...
    def count(self, most: int) -> int: ...
    def octets(self, count: int) -> bytes: ...


class RandomPick:
    """Leaves from a seeded ``random.Random``: reproducible golden values."""

    def __init__(self, seed: int) -> None:
        self.rng = random.Random(seed)

    def integer(self, low: int, high: int) -> int:
        # The extremes half the time: they are where encodings break.
        return self.rng.choice((low, high, 0)) if self.rng.random() < 0.3 else self.rng.randint(low, high)

    def real(self, bits: int) -> float:
        value = (
            self.rng.choice((0.0, -0.0, 1.5, -2.25, 1e300, -1e-300))
            if self.rng.random() < 0.2
            else (self.rng.uniform(-1e6, 1e6))
        )
        return float32(max(-3e38, min(3e38, value))) if bits == 32 else value

    def text(self, most: int) -> str:
        return "".join(self.rng.choice(ALPHABET) for _ in range(self.rng.randint(0, most)))

    def count(self, most: int) -> int:
        return self.rng.randint(0, most)

    def octets(self, count: int) -> bytes:
        return bytes(self.rng.randrange(256) for _ in range(count))


class DrawPick:
    """Leaves drawn by hypothesis (``st.data()``): shrinkable random values.

    A type with more leaves than hypothesis can draw in one example (test_msgs'
    MultiNested has thousands) gets its first ``BUDGET`` leaves drawn and the
    rest from a :class:`RandomPick` seeded by one more draw: every example is
    still hypothesis's to choose and replay, only the tail does not shrink.
    """

    BUDGET = 300

    def __init__(self, data: Any) -> None:
        from hypothesis import strategies as st

        self.data, self.st = data, st
        self.drawn = 0
        self.rest: RandomPick | None = None

    def _tail(self) -> RandomPick | None:
        if self.rest is None and self.drawn >= self.BUDGET:
            self.rest = RandomPick(self.data.draw(self.st.integers(0, 2**32)))
        self.drawn += 1
        return self.rest

    def integer(self, low: int, high: int) -> int:
        tail = self._tail()
        return tail.integer(low, high) if tail else self.data.draw(self.st.integers(low, high))

    def real(self, bits: int) -> float:
        tail = self._tail()
        if tail:
            return tail.real(bits)
        return self.data.draw(self.st.floats(allow_nan=False, allow_infinity=False, width=bits))

    def text(self, most: int) -> str:
        tail = self._tail()
        if tail:
            return tail.text(most)
        alphabet = self.st.characters(blacklist_categories=("Cs",), blacklist_characters="\x00")
        return self.data.draw(self.st.text(alphabet, max_size=most))

    def count(self, most: int) -> int:
        tail = self._tail()
        return tail.count(most) if tail else self.data.draw(self.st.integers(0, most))

    def octets(self, count: int) -> bytes:
        tail = self._tail()
        return tail.octets(count) if tail else self.data.draw(self.st.binary(min_size=count, max_size=count))


def message(cls: type, pick: Pick) -> Any:
    """A ``cls`` message whose every field comes from ``pick``."""
    lay = layout(cls)
    if lay.placeholder:
        return cls()
    return cls(**{field.name: _field(field.type, field.nested, pick) for field in lay.fields})


def _field(type_: FieldType, nested: MessageLayout | None, pick: Pick) -> Any:
    if type_.array is None:
        return _item(type_, nested, pick)
    if type_.array == "fixed":
        count = type_.size
    else:
        count = pick.count(type_.size if type_.array == "bounded" else MAX_ITEMS)
    if type_.base in OCTETS:
        return pick.octets(count)
    return [_item(type_, nested, pick) for _ in range(count)]


def _item(type_: FieldType, nested: MessageLayout | None, pick: Pick) -> Any:
    if nested is not None:
        return message(nested.cls, pick)
    if type_.base == "bool":
        return bool(pick.integer(0, 1))
    if type_.base in FLOATS:
        return pick.real(32 if type_.base == "float32" else 64)
    if type_.base in STRINGS:
        return pick.text(type_.string_bound if type_.string_bound is not None else 12)
    return pick.integer(*INTEGER_RANGES[type_.base])


def shipped_types() -> list[str]:
    """Every message, service and action type of the shipped root (not of roots tests register)."""
    root = shipped_root()
    return sorted(
        f"{p.parent.parent.name}/{p.parent.name}/{p.stem}"
        for p in root.glob("*/*/*.*")
        if p.suffix.lstrip(".") == p.parent.name
    )


def shipped_messages() -> list[str]:
    """Every shipped message type with a CDR form: messages, services' parts, actions' wire types."""
    names = []
    for name in shipped_types():
        cls = codec.get_type(name)
        if "/srv/" in name:
            names += [cls.Request.__ros_type__, cls.Response.__ros_type__]
        elif "/action/" in name:
            impl = cls.Impl
            names += [cls.Goal.__ros_type__, cls.Result.__ros_type__, cls.Feedback.__ros_type__]
            for service in (impl.SendGoalService, impl.GetResultService):
                names += [service.Request.__ros_type__, service.Response.__ros_type__]
            names.append(impl.FeedbackMessage.__ros_type__)
        else:
            names.append(name)
    return names
