"""Transports: how a graph's topics and services reach other processes (the seam, and Zenoh)."""

from actors.transport.seam import (
    GraphSource,
    Hub,
    Inlet,
    Outlet,
    RemoteEndpoint,
    RemoteNode,
    RemoteService,
    Transport,
    is_proxy,
    submit,
)

__all__ = [
    "GraphSource",
    "Hub",
    "Inlet",
    "Outlet",
    "RemoteEndpoint",
    "RemoteNode",
    "RemoteService",
    "Transport",
    "is_proxy",
    "submit",
]
