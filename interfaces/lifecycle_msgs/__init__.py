"""The lifecycle_msgs interface package: ``interfaces.lifecycle_msgs.msg``, ``.srv`` and ``.action``."""
