"""The stereo_msgs interface package: ``interfaces.stereo_msgs.msg``, ``.srv`` and ``.action``."""
