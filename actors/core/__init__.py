"""The core: one task per node (the actor scheduler), the event loops with virtual time, error wording.

Nothing here knows about ROS: :mod:`actors.core.loops` is public (the loops a graph
runs on), the rest is internal.
"""

__all__: list[str] = []
