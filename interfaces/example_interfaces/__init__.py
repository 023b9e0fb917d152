"""The example_interfaces interface package: ``interfaces.example_interfaces.msg`` and ``.srv``."""
