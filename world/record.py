"""Recording a run in bounded memory: each robot's trajectory, and snapshots for an animation."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import MappingProxyType
from typing import TYPE_CHECKING, Generic, NamedTuple, TypeVar

from .drive import Pose

if TYPE_CHECKING:
    from .simulation import Simulation

__all__ = ["Frame", "Recorder", "Sample"]

T = TypeVar("T")


class Sample(NamedTuple):
    """A robot's pose at simulated time ``t`` (s)."""

    t: float
    x: float
    y: float
    theta: float


class Frame(NamedTuple):
    """Every robot's pose at simulated time ``t`` (s): one picture of an animation."""

    t: float
    poses: Mapping[str, Pose]


class _Thinned(Generic[T]):
    """Keeps every ``stride``-th item offered, at most ``limit`` of them.

    When full it drops every other item kept and doubles the stride, so a long
    run keeps its whole span at a coarser spacing instead of only its end.
    """

    def __init__(self, limit: int) -> None:
        self.items: list[T] = []
        self.limit = limit
        self.stride = 1
        self._offered = 0

    def offer(self, item: T) -> None:
        if self._offered % self.stride == 0:
            self.items.append(item)
            if len(self.items) > self.limit:
                del self.items[1::2]
                self.stride *= 2
        self._offered += 1


class Recorder:
    """Watches a Simulation: call ``update()`` after each ``sim.step()``.

    Every ``every`` steps it appends each robot's pose to that robot's
    trajectory, and every ``frame_every`` steps (if given) it keeps a Frame of
    all robots for ``render.save_gif``. Each trajectory keeps at most
    ``max_samples`` samples and the frames at most ``max_frames``: past that,
    every other one is dropped and the spacing doubles. It records once on
    creation, and a robot's trajectory outlives the robot's removal.
    """

    def __init__(
        self,
        sim: Simulation,
        *,
        every: int = 10,
        frame_every: int | None = None,
        max_samples: int = 4096,
        max_frames: int = 300,
    ) -> None:
        if every < 1 or (frame_every is not None and frame_every < 1):
            raise ValueError("every and frame_every count steps and must be >= 1")
        if max_samples < 2 or max_frames < 2:
            raise ValueError("max_samples and max_frames must be >= 2")
        self.sim = sim
        self.every = every
        self.frame_every = frame_every
        self._max_samples = max_samples
        self._trajectories: dict[str, _Thinned[Sample]] = {}
        self._radii: dict[str, float] = {}
        self._frames: _Thinned[Frame] = _Thinned(max_frames)
        self._sampled_at: int | None = None
        self._framed_at: int | None = None
        self.update()

    @property
    def trajectories(self) -> Mapping[str, Sequence[Sample]]:
        """Each robot's recorded poses, oldest first, by robot name."""
        return MappingProxyType({name: series.items for name, series in self._trajectories.items()})

    @property
    def radii(self) -> Mapping[str, float]:
        """The radius (m) of every robot ever recorded."""
        return MappingProxyType(self._radii)

    @property
    def frames(self) -> Sequence[Frame]:
        """The recorded frames, oldest first (empty unless ``frame_every`` was given)."""
        return self._frames.items

    def update(self) -> None:
        """Record what is due at the simulation's current step; cheap when nothing is."""
        steps, t = self.sim.steps, self.sim.time
        sample = self._sampled_at is None or steps - self._sampled_at >= self.every
        frame = self.frame_every is not None and (
            self._framed_at is None or steps - self._framed_at >= self.frame_every
        )
        if not (sample or frame):
            return
        poses = {}
        for name, robot in self.sim.robots.items():
            poses[name] = robot.pose
            self._radii.setdefault(name, robot.model.radius)
        if sample:
            self._sampled_at = steps
            for name, pose in poses.items():
                if name not in self._trajectories:
                    self._trajectories[name] = _Thinned(self._max_samples)
                self._trajectories[name].offer(Sample(t, *pose))
        if frame:
            self._framed_at = steps
            self._frames.offer(Frame(t, poses))
