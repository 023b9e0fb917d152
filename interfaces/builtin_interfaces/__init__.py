"""The builtin_interfaces interface package: ``interfaces.builtin_interfaces.msg`` and ``.srv``."""
