"""Record, replay and look: ROS 2 bags (MCAP) of a graph's topics, and a live Foxglove view.

The recorder is an attachment, ``Runtime(attach=[Recorder("run.mcap")])``; it
needs the ``record`` extra (``pip install 'actors[record]'``: the mcap library
and zstandard).
"""

from actors.recording.recorder import Recorder

__all__ = ["Recorder"]
