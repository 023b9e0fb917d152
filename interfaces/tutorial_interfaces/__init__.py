"""The tutorial_interfaces interface package: ``interfaces.tutorial_interfaces.msg`` and ``.srv``."""
