"""Differential-drive robots: the TurtleBot models, their limits, and the driven pymunk body.

How a robot moves. Each step the command (v, w) is clipped to the model's
limits and rate-limited by its accelerations. The robot is a DYNAMIC pymunk
circle (a kinematic body would pass through static walls), and before every
space step its velocity is set to the chord of the exact unicycle arc over that
step: heading at mid-step, length ``2 v / w sin(w dt / 2)``. Pymunk integrates
positions with that velocity, so free motion follows the arc to rounding error,
with no lag and no drift.

How it stops. A slightly larger sensor circle (``LOOKAHEAD`` metres wider)
reports, during each step, the gap to everything that is near. Before the next
step the motion is scaled down so that it closes no more than that gap, half
of it toward another robot, which does the same. So a robot comes to rest
touching a wall, box or robot instead of sinking in and being pushed back out,
and it cannot push another robot. The motion is only ever scaled, never turned:
wheels do not slip sideways, so a robot that meets a wall at an angle stalls
there, as a real one does, until it turns away or backs off. Zero elasticity
and friction mean no bounce and no spin, and the heading rate is always the
commanded one. Contacts stay exact while no step moves two things more than
``LOOKAHEAD`` closer (0.05 s steps for robots meeting head-on at 0.5 m/s);
beyond that pymunk's solver still separates the shapes, more slowly.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import msgspec
import pymunk

from .lidar import LidarSpec
from .noise import Noise, NoiseSource

__all__ = [
    "LOOKAHEAD",
    "MODELS",
    "TOUCHING",
    "Contact",
    "Odometry",
    "Pose",
    "Robot",
    "RobotModel",
    "Twist",
]

#: How far (m) beyond its body a robot senses things, to stop exactly where it touches them.
LOOKAHEAD = 0.05
#: A gap (m) at most this small counts as contact.
TOUCHING = 0.001


class RobotModel(msgspec.Struct, frozen=True, kw_only=True):
    """A robot's shape and limits; the limits are absolute values.

    ``radius`` (m), ``max_linear`` (m/s), ``max_angular`` (rad/s),
    ``linear_accel`` (m/s^2) and ``angular_accel`` (rad/s^2), where ``None``
    means no limit, ``mass`` (kg), and the ``lidar`` it carries.
    """

    name: str
    radius: float = 0.105
    max_linear: float
    max_angular: float
    linear_accel: float | None = None
    angular_accel: float | None = None
    mass: float = 1.0
    lidar: LidarSpec = LidarSpec()

    def limit(self, v: float, w: float, last_v: float, last_w: float, dt: float) -> tuple[float, float]:
        """The twist to drive this step: (v, w) clipped to the limits.

        Then rate-limited: at most ``accel * dt`` away from the last step's ``(last_v, last_w)``.
        """
        v = min(max(v, -self.max_linear), self.max_linear)
        w = min(max(w, -self.max_angular), self.max_angular)
        if self.linear_accel is not None:
            step = self.linear_accel * dt
            v = min(max(v, last_v - step), last_v + step)
        if self.angular_accel is not None:
            step = self.angular_accel * dt
            w = min(max(w, last_w - step), last_w + step)
        return v, w


#: The robots ``Simulation.add_robot`` knows by name.
MODELS: dict[str, RobotModel] = {
    "burger": RobotModel(name="burger", max_linear=0.22, max_angular=2.84),
    "asl_tb3": RobotModel(name="asl_tb3", max_linear=0.5, max_angular=1.0, linear_accel=1.0, angular_accel=2.0),
}


class Pose(NamedTuple):
    """Where a robot is: ``x``, ``y`` (m), ``theta`` (rad in [-pi, pi], 0 along +x, CCW)."""

    x: float
    y: float
    theta: float


class Twist(NamedTuple):
    """Motion in the robot's own frame: ``v`` forward (m/s), ``w`` turning (rad/s, CCW)."""

    v: float
    w: float


class Odometry(NamedTuple):
    """A pose (m, m, rad) and body-frame twist (m/s, rad/s) as the robot's odometry reports them."""

    x: float
    y: float
    theta: float
    v: float
    w: float


class Contact(NamedTuple):
    """Something a robot touches: ``kind`` "wall", "obstacle" or "robot"; ``name`` if any."""

    kind: str
    name: str | None


class _Near(NamedTuple):
    nx: float  # unit normal from the robot toward the thing
    ny: float
    gap: float  # m between the surfaces; negative when they overlap
    room: float  # m the robot may still close this step
    what: Contact


class Robot:
    """A differential-drive robot in a Simulation; made by ``Simulation.add_robot``, not directly.

    ``command(v, w)`` sets the twist it tries to drive until the next command.
    ``pose``, ``twist`` and ``contacts`` are the truth after the last step;
    ``odometry()`` is what its sensors report, with noise when some is set.
    """

    def __init__(self, name: str, model: RobotModel, pose: Pose, *, seed: int, noise: Noise) -> None:
        self.name = name
        self.model = model
        self.noise = noise
        self.noise_source = NoiseSource(noise, seed)
        self.body = pymunk.Body(model.mass, pymunk.moment_for_circle(model.mass, 0.0, model.radius))
        self.body.position = (pose.x, pose.y)
        self.body.angle = pose.theta
        self.shape = pymunk.Circle(self.body, model.radius)
        self.shape.elasticity = 0.0
        self.shape.friction = 0.0
        self.sensor = pymunk.Circle(self.body, model.radius + LOOKAHEAD)
        self.sensor.sensor = True
        self._command = (0.0, 0.0)
        self._wheels = (0.0, 0.0)  # the limited twist driven in the last step
        self._twist = Twist(0.0, 0.0)
        self._near: list[_Near] = []

    def command(self, v: float, w: float) -> None:
        """Drive at ``v`` m/s turning at ``w`` rad/s, within limits, from the next step on.

        Raises ValueError for a value that is not a finite number, and keeps the last command.
        """
        v, w = float(v), float(w)
        if not (math.isfinite(v) and math.isfinite(w)):
            raise ValueError(f"robot {self.name!r}: command must be finite, got v={v}, w={w}")
        self._command = (v, w)

    @property
    def commanded(self) -> Twist:
        """The last command, before limits."""
        return Twist(*self._command)

    @property
    def pose(self) -> Pose:
        """The true pose after the last step."""
        x, y = self.body.position
        return Pose(x, y, math.remainder(self.body.angle, math.tau))

    @property
    def twist(self) -> Twist:
        """The true twist of the last step: the limited command, less what contacts blocked."""
        return self._twist

    @property
    def contacts(self) -> tuple[Contact, ...]:
        """What the robot touches now (surfaces within ``TOUCHING`` m), in a stable order."""
        return tuple(near.what for near in self._near if near.gap <= TOUCHING)

    @property
    def in_contact(self) -> bool:
        """Whether the robot touches anything now."""
        for near in self._near:  # noqa: SIM110 - a loop, not any(): no generator to make on every odometry tick
            if near.gap <= TOUCHING:
                return True
        return False

    def odometry(self) -> Odometry:
        """The pose and twist as odometry reports them: the truth plus the robot's noise."""
        (x, y), theta = self.body.position, self.body.angle
        x, y, theta, v, w = self.noise_source.odometry(x, y, theta, *self._twist)
        return Odometry(x, y, math.remainder(theta, math.tau), v, w)

    def _drive(self, dt: float) -> None:
        """Set the body's velocity for the coming step of ``dt`` s (called by the Simulation)."""
        v, w = self._wheels = self.model.limit(*self._command, *self._wheels, dt)
        half = 0.5 * w * dt
        heading = self.body.angle + half
        # Chord of the arc over the step, per second: v * sin(half) / half.
        sinc = math.sin(half) / half if half else 1.0
        ux, uy = v * sinc * math.cos(heading), v * sinc * math.sin(heading)
        # Wheels do not slip sideways: scale the motion down, never turn it, so that it
        # closes no more than the room left toward each near thing.
        scale = 1.0
        for near in self._near:
            approach = (ux * near.nx + uy * near.ny) * dt
            if approach > near.room:
                scale = min(scale, near.room / approach)
        ux, uy = ux * scale, uy * scale
        self._near = []
        self.body.velocity = (ux, uy)
        self.body.angular_velocity = w
        self._twist = Twist(v * scale, w)

    def _sense(self, arbiter: pymunk.Arbiter, what: Contact) -> None:
        """Note a thing near the sensor circle during a step (called by the collision callback)."""
        points = arbiter.contact_point_set
        nx, ny = points.normal
        gap = points.points[0].distance + LOOKAHEAD
        # Another robot cuts its own approach too, so each closes half the gap.
        room = max(gap, 0.0) * (0.5 if what.kind == "robot" else 1.0)
        self._near.append(_Near(nx, ny, gap, room, what))
