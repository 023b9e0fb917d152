"""The geometry_msgs interface package: ``interfaces.geometry_msgs.msg`` and ``.srv``."""
