"""The sensor_msgs interface package: ``interfaces.sensor_msgs.msg`` and ``.srv``."""
