"""The unique_identifier_msgs interface package: ``interfaces.unique_identifier_msgs.msg``, ``.srv`` and ``.action``."""
