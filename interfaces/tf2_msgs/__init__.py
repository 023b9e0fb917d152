"""The tf2_msgs interface package: ``interfaces.tf2_msgs.msg``, ``.srv`` and ``.action``."""
