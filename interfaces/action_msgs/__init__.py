"""The action_msgs interface package: ``interfaces.action_msgs.msg``, ``.srv`` and ``.action``."""
