"""Message, service and their generated Python types: ``interfaces.<pkg>.msg`` and ``.srv``."""
