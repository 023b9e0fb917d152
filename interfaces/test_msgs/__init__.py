"""The test_msgs interface package: ``interfaces.test_msgs.msg``, ``.srv`` and ``.action``."""
