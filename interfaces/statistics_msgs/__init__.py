"""The statistics_msgs interface package: ``interfaces.statistics_msgs.msg``, ``.srv`` and ``.action``."""
