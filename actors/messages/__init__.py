"""Messages: the ``.msg``/``.srv``/``.action`` parser and generator, field layouts, copies, CDR, type hashes.

:mod:`actors.codec` is the front of this layer; :mod:`actors.messages.idl` (the
parser) and :mod:`actors.messages.generate` (the code generator) are public too.
"""

__all__: list[str] = []
