"""``ament_index_python.constants``: where the resource index is, and the variable listing install prefixes."""

from actors.launch.packages import INDEX

__all__ = ["RESOURCE_INDEX_SUBFOLDER", "AMENT_PREFIX_PATH_ENV_VAR"]

RESOURCE_INDEX_SUBFOLDER = str(INDEX)
AMENT_PREFIX_PATH_ENV_VAR = "AMENT_PREFIX_PATH"
