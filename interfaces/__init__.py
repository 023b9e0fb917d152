"""ROS 2 interface packages as Python types: ``interfaces.<pkg>.msg``, ``.srv`` and ``.action``.

The shipped packages are generated modules in this folder.  A package found in a
workspace or a ROS install is typed on its first import by
:mod:`actors.messages.discovery`, which the finder below loads only then: the
shipped packages import without it.
"""

import importlib.abc
import importlib.machinery
import sys
from collections.abc import Sequence
from types import ModuleType


class _Discovered(importlib.abc.MetaPathFinder):
    """After Python's own finders: what this folder lacks, discovery may find."""

    def find_spec(
        self, fullname: str, path: Sequence[str] | None = None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        if not fullname.startswith(f"{__name__}."):
            return None
        from actors.messages.discovery import find_spec

        return find_spec(fullname, path, target)


if not any(type(finder).__name__ == "_Discovered" for finder in sys.meta_path):
    sys.meta_path.append(_Discovered())
