"""The diagnostic_msgs interface package: ``interfaces.diagnostic_msgs.msg``, ``.srv`` and ``.action``."""
