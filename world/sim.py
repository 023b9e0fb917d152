"""The World node: steps the pymunk simulation on the runtime clock and hosts the robots.

One World per runtime; TurtleBot nodes started after it find it with
:func:`world_of`.  Parameters:

- ``world``: a world file path, or the name of a shipped world (``empty``, ``signs``);
- ``dt``: the physics step in seconds (0.01; from 0.0001 to 0.1);
- ``image``: a PNG to draw the run into when the node stops (arena, obstacles,
  robots, trajectories); ``gif``: an animated GIF of the run.  Both need the
  ``viz`` extra (Pillow).

They are read once, at start: each is read-only (``param set`` refuses it).
The World logs a line when a robot starts touching something and when it
is free again.  Beside a live view (``--foxglove``) it draws itself as a 3D
scene on ``/scene`` (:mod:`world.scene`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING
from weakref import WeakKeyDictionary

import numpy as np

from actors import Node
from actors.errors import WorldError
from interfaces.rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor

from .drive import Contact, Pose
from .record import Recorder
from .scene import SCENE_TOPIC, scene_hosts, scene_update
from .simulation import Scans, Simulation

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["World", "world_of"]

_WORLDS: WeakKeyDictionary[Runtime, World] = WeakKeyDictionary()

#: How often (s) the World looks for robots that started or stopped touching something.
CONTACT_PERIOD = 0.1


def world_of(node: Node) -> World:
    """The World node of ``node``'s runtime; WorldError if there is none."""
    world = _WORLDS.get(node._core.runtime)
    if world is None:
        raise WorldError(
            f"{node.get_fully_qualified_name()} needs a world: start a world.sim:World node before it in the same graph"
        )
    return world


class World(Node):
    """Node ``world``: the simulation, stepped every ``dt`` seconds of runtime clock."""

    def __init__(self) -> None:
        super().__init__("world")
        fixed = ParameterDescriptor(read_only=True)
        source = self.declare_parameter("world", "empty", fixed).value
        # Above 0.1 s robots would cross the contact look-ahead in one step; below 0.1 ms is a typo.
        step_range = FloatingPointRange(from_value=0.0001, to_value=0.1)
        dt = self.declare_parameter(
            "dt", 0.01, ParameterDescriptor(read_only=True, floating_point_range=[step_range])
        ).value
        self._image = self.declare_parameter("image", "", fixed).value
        self._gif = self.declare_parameter("gif", "", fixed).value
        runtime = self._core.runtime
        other = _WORLDS.get(runtime)
        if other is not None and other is not self and not other._core.destroyed:
            raise WorldError(f"a runtime has one World; {other.get_fully_qualified_name()} is already running")
        self.sim = Simulation.from_file(source, dt=dt)
        self.recorder: Recorder | None = None
        if self._image or self._gif:
            from .render import pillow

            try:
                pillow()  # no Pillow: say so now, not after the whole run
            except ImportError as exc:
                raise WorldError(f"{self.get_fully_qualified_name()}: image/gif: {exc}") from None
            self.recorder = Recorder(self.sim, every=10, frame_every=10 if self._gif else None)
        self._scans = Scans()
        self._scanned_at = -1
        _WORLDS[runtime] = self
        self._scene_hosts = scene_hosts(runtime)
        for host in self._scene_hosts:
            host.add_scene(SCENE_TOPIC, lambda now_ns: scene_update(self, now_ns))
        self._touching: dict[str, tuple[Contact, ...]] = {}
        # The physics step itself when nothing records the run: one Python call less on every step.
        self.timer = self.create_timer(dt, self.step if self.recorder is not None else self.sim.step)
        self.create_timer(CONTACT_PERIOD, self.report_contacts)

    def step(self) -> None:
        """Advance the physics one step (the timer's callback)."""
        self.sim.step()
        if self.recorder is not None:
            self.recorder.update()

    def report_contacts(self) -> None:
        """Log each robot that started touching something, or is free again, since the last look."""
        for name, robot in self.sim.robots.items():
            contacts = robot.contacts
            if contacts == self._touching.get(name, ()):
                continue
            self._touching[name] = contacts
            if contacts:
                things = ", ".join(_describe(c) for c in contacts)
                x, y, _ = robot.pose
                self.get_logger().info(f"{name} touches {things} at ({x:.2f}, {y:.2f})")
            else:
                self.get_logger().info(f"{name} is free again")

    def scan(self, robot: str) -> np.ndarray:
        """``robot``'s 360 ranges now; all robots are scanned in one batch per physics step."""
        if self._scanned_at != self.sim.steps:
            self._scans = self.sim.scan_all()
            self._scanned_at = self.sim.steps
        return self._scans[robot]

    def skip_scan(self, robot: str) -> None:
        """Take no scan of ``robot`` this tick; its range noise moves on as a scan's would."""
        body = self.sim.robots[robot]
        body.noise_source.skip_ranges(body.model.lidar.beams)

    @property
    def draws_scans(self) -> bool:
        """Whether a live view draws the robots' scans, so that they are taken with nobody on /scan."""
        return bool(self._scene_hosts)

    def latest_scans(self) -> dict[str, tuple[Pose, np.ndarray]]:
        """The last batch of scans by robot, each with the pose it was taken from (empty before the first)."""
        poses = self._scans.poses()
        return {name: (poses[name], ranges) for name, ranges in self._scans.items()}

    def on_shutdown(self) -> None:
        """Draw the run into the files named by ``image`` and ``gif``."""
        if self.recorder is None:
            return
        from .render import save_gif, save_png

        if self._image:
            self.get_logger().info(f"wrote {save_png(self.recorder, self._image)}")
        if self._gif:
            self.get_logger().info(f"wrote {save_gif(self.recorder, self._gif)}")

    def destroy_node(self) -> None:
        runtime = self._core.runtime
        if _WORLDS.get(runtime) is self:
            del _WORLDS[runtime]
            for host in self._scene_hosts:
                host.remove_scene(SCENE_TOPIC)
        super().destroy_node()


def _describe(contact: Contact) -> str:
    return f"{contact.kind} {contact.name}" if contact.name else f"a {contact.kind}"
