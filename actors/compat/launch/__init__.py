"""``launch`` under the overlay: ROS 2 launch files' Python API, translated onto actors' runtime.

Launch files import ``launch``, ``launch.actions``, ``launch.substitutions``,
``launch.conditions``, ``launch.launch_description_sources``, ``launch.events``
and ``launch.event_handlers`` (and ``launch_ros``) as on ROS; what they describe
runs in one actors runtime (:mod:`actors.compat.launch.service`).
"""

from actors.compat.launch import (
    actions,
    conditions,
    event_handlers,
    events,
    launch_description_sources,
    substitutions,
)
from actors.compat.launch.entities import (
    Action,
    Condition,
    Event,
    EventHandler,
    LaunchContext,
    LaunchDescription,
    LaunchDescriptionEntity,
    SomeSubstitutionsType,
    Substitution,
)

__all__ = [
    "actions",
    "conditions",
    "event_handlers",
    "events",
    "launch_description_sources",
    "substitutions",
    "Action",
    "Condition",
    "Event",
    "EventHandler",
    "LaunchContext",
    "LaunchDescription",
    "LaunchDescriptionEntity",
    "SomeSubstitutionsType",
    "Substitution",
]
