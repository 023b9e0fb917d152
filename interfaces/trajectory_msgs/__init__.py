"""The trajectory_msgs interface package: ``interfaces.trajectory_msgs.msg``, ``.srv`` and ``.action``."""
