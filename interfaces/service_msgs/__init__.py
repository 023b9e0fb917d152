"""The service_msgs interface package: ``interfaces.service_msgs.msg``, ``.srv`` and ``.action``."""
