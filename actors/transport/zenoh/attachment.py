"""The attachment rmw_zenoh puts on every sample, query and reply, and the entity GIDs in it.

33 bytes, in Zenoh's serialization format (``zenoh::ext::Serializer``): the
sequence number and the source timestamp (nanoseconds since the Unix epoch)
as little-endian int64, then the 16-byte GID as a sequence (its length 16 as
one LEB128 byte, then the bytes).  A publisher counts its samples from 1; a
client numbers its requests from 1, and a server's reply carries the
request's sequence number and client GID back, so the client can match it.

An entity's GID is the XXH3-128 hash of its liveliness token (low 64 bits
first, each little-endian), as rmw_zenoh computes it: the same entity has the
same GID in every process's graph.
"""

from __future__ import annotations

import struct

__all__ = ["SIZE", "GID_SIZE", "pack", "unpack", "gid_of"]

GID_SIZE = 16
SIZE = 8 + 8 + 1 + GID_SIZE
_LAYOUT = struct.Struct(f"<qqB{GID_SIZE}s")


def pack(sequence: int, stamp_ns: int, gid: bytes) -> bytes:
    """The attachment of one sample, query or reply."""
    return _LAYOUT.pack(sequence, stamp_ns, GID_SIZE, gid)


def unpack(data: bytes) -> tuple[int, int, bytes]:
    """``(sequence, stamp_ns, gid)`` from an attachment; ValueError saying what is wrong."""
    if len(data) != SIZE:
        raise ValueError(f"attachment of {len(data)} bytes, expected {SIZE}")
    sequence, stamp, length, gid = _LAYOUT.unpack(data)
    if length != GID_SIZE:
        raise ValueError(f"attachment with a GID of {length} bytes, expected {GID_SIZE}")
    return sequence, stamp, gid


def gid_of(token: str) -> bytes:
    """The GID rmw_zenoh gives the entity holding liveliness token ``token``."""
    import xxhash  # installed with the zenoh extra

    return xxhash.xxh3_128_intdigest(token.encode()).to_bytes(16, "little")
