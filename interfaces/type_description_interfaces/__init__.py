"""The type_description_interfaces interface package: ``interfaces.type_description_interfaces.msg``, ``.srv`` and ``.action``."""
