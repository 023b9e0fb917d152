"""The Zenoh transport: rmw_zenoh's protocol, so actors graphs and ROS 2 nodes are peers (``actors[zenoh]``)."""

from actors.transport.zenoh.transport import ZenohTransport

__all__ = ["ZenohTransport"]
