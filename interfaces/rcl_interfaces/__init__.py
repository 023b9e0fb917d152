"""The rcl_interfaces interface package: ``interfaces.rcl_interfaces.msg`` and ``.srv``."""
