"""The shape_msgs interface package: ``interfaces.shape_msgs.msg``, ``.srv`` and ``.action``."""
