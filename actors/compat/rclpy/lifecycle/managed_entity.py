"""``rclpy.lifecycle.managed_entity``: what a lifecycle node calls on each transition, besides itself."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from actors.ros.lifecycle import CallbackResult as TransitionCallbackReturn

__all__ = ["ManagedEntity", "SimpleManagedEntity"]


class ManagedEntity:
    """An entity a lifecycle node drives through its transitions: every callback succeeds unless overridden."""

    def on_configure(self, state: Any) -> TransitionCallbackReturn:
        """Called on the way to inactive from unconfigured."""
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state: Any) -> TransitionCallbackReturn:
        """Called on the way back to unconfigured."""
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state: Any) -> TransitionCallbackReturn:
        """Called on the way to finalized."""
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: Any) -> TransitionCallbackReturn:
        """Called on the way to active."""
        return TransitionCallbackReturn.SUCCESS

    def on_deactivate(self, state: Any) -> TransitionCallbackReturn:
        """Called on the way back to inactive from active."""
        return TransitionCallbackReturn.SUCCESS

    def on_error(self, state: Any) -> TransitionCallbackReturn:
        """Called in errorprocessing: success goes back to unconfigured, anything else to finalized."""
        return TransitionCallbackReturn.SUCCESS


class SimpleManagedEntity(ManagedEntity):
    """An entity that is enabled while its node is active, and nothing more."""

    def __init__(self) -> None:
        self._enabled = False

    def on_activate(self, state: Any) -> TransitionCallbackReturn:
        """Enable the entity."""
        self._enabled = True
        return TransitionCallbackReturn.SUCCESS

    def on_deactivate(self, state: Any) -> TransitionCallbackReturn:
        """Disable the entity."""
        self._enabled = False
        return TransitionCallbackReturn.SUCCESS

    @property
    def is_activated(self) -> bool:
        """Whether the entity is enabled (its node is active)."""
        return self._enabled

    @staticmethod
    def when_enabled(
        wrapped: Callable[..., None] | None = None, *, when_not_enabled: Callable[[], None] | None = None
    ) -> Any:
        """Decorate a method so that it does nothing (or calls ``when_not_enabled``) while disabled."""

        def decorate(method: Callable[..., None]) -> Callable[..., None]:
            @functools.wraps(method)
            def only_when_enabled(self: SimpleManagedEntity, *args: Any, **kwargs: Any) -> None:
                if self._enabled:
                    method(self, *args, **kwargs)
                elif when_not_enabled is not None:
                    when_not_enabled()

            return only_when_enabled

        return decorate if wrapped is None else decorate(wrapped)
