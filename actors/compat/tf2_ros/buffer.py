"""``tf2_ros.buffer``: the Buffer scripts look transforms up in, with waits on the runtime's clock.

A lookup with a ``timeout`` waits until the transform can be had or the
timeout has passed on the runtime's clock (virtual time under a virtual run),
parked like any rclpy wait: whoever adds a transform wakes it.  As in tf2_ros,
the transforms come from whoever calls ``set_transform`` (a
:class:`~actors.compat.tf2_ros.transform_listener.TransformListener`, in the
callbacks its node's executor runs), so a wait inside a callback of a
single-threaded executor sees no new data, as with rclpy.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from actors.compat.rclpy.context import current_session
from actors.compat.rclpy.task import Future
from actors.compat.tf2_ros.buffer_interface import BufferInterface
from actors.ros.tf_buffer import BufferCore
from actors.ros.time import Duration
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.tf2_msgs.srv import FrameGraph

__all__ = ["Buffer"]

_NS = 1_000_000_000


class Buffer(BufferCore, BufferInterface):
    """Frames and transforms (:class:`~actors.ros.tf_buffer.BufferCore`) with tf2_ros's waiting lookups.

    ``cache_time`` (a Duration; 10 s by default) is how long each frame keeps
    its history.  Given a ``node``, the buffer serves ``tf2_frames``
    (tf2_msgs/FrameGraph: every frame as YAML), as tf2_ros's does.
    """

    def __init__(self, cache_time: Duration | None = None, node: Any = None) -> None:
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self._new_data_callbacks: list[Callable[[], None]] = []
        self._callbacks_lock = threading.RLock()
        self._waiters: set[Any] = set()
        if node is not None:
            self.srv = node.create_service(FrameGraph, "tf2_frames", self._frames_service)

    def _frames_service(self, request: Any, response: Any) -> Any:
        response.frame_yaml = self.all_frames_as_yaml()
        return response

    def set_transform(self, transform: TransformStamped, authority: str) -> bool:
        added = super().set_transform(transform, authority)
        self._new_data()
        return added

    def set_transform_static(self, transform: TransformStamped, authority: str) -> bool:
        added = super().set_transform_static(transform, authority)
        self._new_data()
        return added

    def _new_data(self) -> None:
        with self._callbacks_lock:
            for callback in list(self._new_data_callbacks):
                callback()
            waiters = list(self._waiters)
        for waiter in waiters:
            waiter.wake()

    # -- lookups that may wait ---------------------------------------------------------

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Duration | None = None
    ) -> TransformStamped:
        """The transform from ``source_frame`` to ``target_frame`` at ``time`` (a zero Time: the latest).

        Waits up to ``timeout`` for it; then raises tf2's exception if it still cannot be had.
        """
        self.can_transform(target_frame, source_frame, time, timeout)
        return self.lookup_transform_core(target_frame, source_frame, time)

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Duration | None = None,
    ) -> TransformStamped:
        """Time travel: ``source_frame`` at ``source_time`` into ``target_frame`` at ``target_time``.

        ``fixed_frame`` is the frame taken not to move between the two times.
        """
        self.can_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame, timeout)
        return self.lookup_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)

    def can_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: Any,
        timeout: Duration | None = None,
        return_debug_tuple: bool = False,
    ) -> Any:
        """Whether the transform can be had, waiting up to ``timeout``; (bool, reason) if ``return_debug_tuple``."""
        result = self._wait(lambda: self.can_transform_core(target_frame, source_frame, time), timeout)
        return result if return_debug_tuple else result[0]

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Duration | None = None,
        return_debug_tuple: bool = False,
    ) -> Any:
        """As :meth:`can_transform`, for :meth:`lookup_transform_full`."""
        result = self._wait(
            lambda: self.can_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame),
            timeout,
        )
        return result if return_debug_tuple else result[0]

    def _wait(self, check: Callable[[], tuple[bool, str]], timeout: Duration | None) -> tuple[bool, str]:
        seconds = timeout.nanoseconds / _NS if timeout is not None else 0.0
        session = current_session()
        if seconds <= 0 or session is None or check()[0]:
            return check()
        waiter = session.waiter()
        with self._callbacks_lock:
            self._waiters.add(waiter)
        try:
            session.wait_until(lambda: check()[0], seconds, waiter)
        finally:
            with self._callbacks_lock:
                self._waiters.discard(waiter)
        return check()

    # -- lookups that complete a future -------------------------------------------------

    def wait_for_transform_async(self, target_frame: str, source_frame: str, time: Any) -> Future[TransformStamped]:
        """A Future that gets the transform as soon as it can be had."""
        return self._when_possible(
            lambda: self.can_transform_core(target_frame, source_frame, time)[0],
            lambda: self.lookup_transform_core(target_frame, source_frame, time),
        )

    def wait_for_transform_full_async(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> Future[TransformStamped]:
        """A Future that gets the time-travel transform as soon as it can be had."""
        args = (target_frame, target_time, source_frame, source_time, fixed_frame)
        return self._when_possible(
            lambda: self.can_transform_full_core(*args)[0], lambda: self.lookup_transform_full_core(*args)
        )

    def _when_possible(
        self, possible: Callable[[], bool], lookup: Callable[[], TransformStamped]
    ) -> Future[TransformStamped]:
        future: Future[TransformStamped] = Future()
        if possible():
            future.set_result(lookup())
            return future

        def on_new_data() -> None:
            if future.done():
                return
            try:
                if possible():
                    future.set_result(lookup())
            except Exception as exc:
                future.set_exception(exc)

        def forget(_: Future[TransformStamped]) -> None:
            with self._callbacks_lock:
                if on_new_data in self._new_data_callbacks:
                    self._new_data_callbacks.remove(on_new_data)

        with self._callbacks_lock:
            self._new_data_callbacks.append(on_new_data)
        future.add_done_callback(forget)
        return future

    async def lookup_transform_async(self, target_frame: str, source_frame: str, time: Any) -> TransformStamped:
        """Await the transform (in a coroutine callback)."""
        return await self.wait_for_transform_async(target_frame, source_frame, time)  # type: ignore[return-value]

    async def lookup_transform_full_async(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> TransformStamped:
        """Await the time-travel transform (in a coroutine callback)."""
        future = self.wait_for_transform_full_async(target_frame, target_time, source_frame, source_time, fixed_frame)
        return await future  # type: ignore[return-value]
