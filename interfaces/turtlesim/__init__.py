"""The turtlesim interface package: ``interfaces.turtlesim.msg``, ``.srv`` and ``.action``."""
