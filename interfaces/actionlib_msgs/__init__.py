"""The actionlib_msgs interface package: ``interfaces.actionlib_msgs.msg``, ``.srv`` and ``.action``."""
