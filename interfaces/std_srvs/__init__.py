"""The std_srvs interface package: ``interfaces.std_srvs.msg`` and ``.srv``."""
