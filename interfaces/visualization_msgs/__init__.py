"""The visualization_msgs interface package: ``interfaces.visualization_msgs.msg``, ``.srv`` and ``.action``."""
