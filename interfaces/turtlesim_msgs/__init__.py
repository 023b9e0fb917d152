"""The turtlesim_msgs interface package: ``interfaces.turtlesim_msgs.msg``, ``.srv`` and ``.action``."""
