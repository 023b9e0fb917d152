"""``launch.conditions``: whether an action runs, from text that says true or false."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import Condition, LaunchContext, caller_location, normalize_to_list_of_substitutions
from actors.compat.launch.substitutions import _truth

__all__ = ["IfCondition", "UnlessCondition", "LaunchConfigurationEquals", "LaunchConfigurationNotEquals"]


class IfCondition(Condition):
    """Runs the action when the expression is ``true`` or ``1`` (``false``/``0``: not; anything else: an error)."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__()
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        self.where = caller_location()

    def evaluate(self, context: LaunchContext) -> bool:
        return _truth(context, self.expression, self.where)


class UnlessCondition(IfCondition):
    """Runs the action when the expression is ``false`` or ``0``."""

    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)


class LaunchConfigurationEquals(Condition):
    """Runs the action when a launch configuration has this value (None: it is not set)."""

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        super().__init__()
        self.name = launch_configuration_name
        self.expected = None if expected_value is None else normalize_to_list_of_substitutions(expected_value)

    def evaluate(self, context: LaunchContext) -> bool:
        from actors.compat.launch.entities import perform_substitutions

        value = context.launch_configurations.get(self.name)
        expected = None if self.expected is None else perform_substitutions(context, self.expected)
        return value == expected


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """Runs the action when a launch configuration does not have this value."""

    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)
