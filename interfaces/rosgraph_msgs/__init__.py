"""The rosgraph_msgs interface package: ``interfaces.rosgraph_msgs.msg``, ``.srv`` and ``.action``."""
