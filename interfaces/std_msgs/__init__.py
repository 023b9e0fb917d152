"""The std_msgs interface package: ``interfaces.std_msgs.msg`` and ``.srv``."""
