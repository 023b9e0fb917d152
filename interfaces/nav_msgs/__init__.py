"""The nav_msgs interface package: ``interfaces.nav_msgs.msg`` and ``.srv``."""
