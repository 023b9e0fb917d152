"""The TurtleBot node: a differential-drive robot in the runtime's World, with ROS's topics.

Topics (relative, so a namespace gives ``/robot1/cmd_vel`` and so on):

- subscribes ``cmd_vel`` (geometry_msgs/Twist): linear.x and angular.z, clipped
  to the model's limits and rate-limited by its accelerations (as a real
  TurtleBot's firmware does); a command that is not a finite number is refused
  (:class:`~actors.errors.MessageRefused`: dropped, counted, logged once per
  publisher) and the robot keeps its last valid command;
- publishes ``odom`` (nav_msgs/Odometry, 20 Hz): frame ``odom`` (the start
  pose, as on a real robot), child ``base_footprint``, pose and body twist;
- publishes ``/tf`` (tf2_msgs/TFMessage, with each ``odom``, only while someone
  subscribes): ``odom`` -> ``base_footprint``, the same pose and stamp, as
  TurtleBot3's Gazebo simulation does;
- publishes ``/tf_static`` (tf2_msgs/TFMessage, transient-local depth 1, once):
  ``world`` -> ``odom`` (the start pose), ``base_footprint`` -> ``base_link``
  -> ``base_scan``; frames are prefixed with the robot's namespace
  (``robot1/odom``; see :mod:`world.frames`);
- publishes ``scan`` (sensor_msgs/LaserScan, 10 Hz): 360 beams over 0..2π from
  the heading, counter-clockwise; +inf where nothing is in range, -inf where
  something is closer than ``range_min`` (REP 117);
- publishes ``sim/pose`` (geometry_msgs/PoseStamped, 20 Hz): ground truth in
  frame ``world``;
- publishes ``sim/contact`` (std_msgs/Bool, transient-local depth 1): true when
  the robot touches a wall, an obstacle or another robot, false when it leaves
  it; sent on each change, and a late subscriber gets the current state.

Parameters: ``model`` (``burger`` or ``asl_tb3``), start pose ``x``, ``y``,
``theta``, ``seed``, and noise standard deviations ``noise_position``,
``noise_heading``, ``noise_linear``, ``noise_angular``, ``noise_ranges`` (all 0).
They are read once, at start: each is read-only (``param set`` refuses it).
"""

from __future__ import annotations

import math

from actors import DurabilityPolicy, Node, QoSProfile
from actors.errors import MessageRefused, WorldError
from interfaces.builtin_interfaces.msg import Time as TimeMsg
from interfaces.geometry_msgs.msg import PoseStamped, Quaternion, Transform, TransformStamped, Twist, Vector3
from interfaces.nav_msgs.msg import Odometry
from interfaces.rcl_interfaces.msg import ParameterDescriptor
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import Bool, Header
from interfaces.tf2_msgs.msg import TFMessage

from . import frames
from .noise import Noise
from .sim import world_of

__all__ = ["TurtleBot"]

ODOM_PERIOD = 0.05
SCAN_EVERY = 2  # odometry ticks per scan
SCAN_PERIOD = ODOM_PERIOD * SCAN_EVERY


def yaw_quaternion(yaw: float) -> Quaternion:
    """A rotation of ``yaw`` radians about z."""
    rotation = Quaternion()
    _set_yaw(rotation, yaw)
    return rotation


def _set_yaw(rotation: Quaternion, yaw: float) -> None:
    # Into a reused message's quaternion too (its x and y stay 0).
    rotation.z, rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)


class TurtleBot(Node):
    """Node ``turtlebot``: one simulated robot; needs a world.sim:World started before it."""

    def __init__(self) -> None:
        super().__init__("turtlebot")
        fixed = ParameterDescriptor(read_only=True)
        model = self.declare_parameter("model", "burger", fixed).value
        x = self.declare_parameter("x", 0.0, fixed).value
        y = self.declare_parameter("y", 0.0, fixed).value
        theta = self.declare_parameter("theta", 0.0, fixed).value
        seed = self.declare_parameter("seed", 0, fixed).value
        noise = {k: self.declare_parameter(f"noise_{k}", 0.0, fixed).value for k in Noise.__struct_fields__}
        self.world = world_of(self)
        self.name = self.get_fully_qualified_name()
        # The node is the robot's driver: when it stops or restarts, the body stays in
        # the world (as a Gazebo model does), and a new instance drives it again.
        existing = self.world.sim.robots.get(self.name)
        if existing is not None:
            self.robot = existing
        else:
            try:
                self.robot = self.world.sim.add_robot(
                    self.name, model, x=x, y=y, theta=theta, seed=seed, noise=Noise(**noise)
                )
            except ValueError as exc:
                raise WorldError(f"{self.name}: {exc}") from None
        self._start = (x, y, theta)
        self._noisy_odometry = self.robot.noise.odometry  # a property: asked once, not every tick
        self._start_cos_sin = (math.cos(theta), math.sin(theta))
        lidar = self.robot.model.lidar
        # One message of each kind, refilled and published again each tick: publish() takes a
        # snapshot, so reusing them is safe, and building a fresh Odometry tree each time
        # (nested structs, two 36-float covariances) cost as much as the physics step.
        prefix = frames.frame_prefix(self.get_namespace())
        odom, base = prefix + frames.ODOM, prefix + frames.BASE_FOOTPRINT
        self._odom = Odometry(header=Header(frame_id=odom), child_frame_id=base)
        self._tf = TFMessage(transforms=[TransformStamped(header=Header(frame_id=odom), child_frame_id=base)])
        self._ground = PoseStamped(header=Header(frame_id=frames.WORLD))
        self._scan = LaserScan(
            header=Header(frame_id=prefix + frames.BASE_SCAN),
            angle_min=0.0,
            angle_max=2 * math.pi * (lidar.beams - 1) / lidar.beams,
            angle_increment=2 * math.pi / lidar.beams,
            scan_time=SCAN_PERIOD,
            range_min=float(lidar.range_min),  # a model's limits may be ints
            range_max=float(lidar.range_max),
        )
        self.odom_pub = self.create_publisher(Odometry, "odom", 10)
        self.scan_pub = self.create_publisher(LaserScan, "scan", 10)
        self.pose_pub = self.create_publisher(PoseStamped, "sim/pose", 10)
        # What this node fills is valid by construction: stamps from the clock, frame names,
        # poses from the body's floats and math, the twist as floats (publish_odometry converts
        # it: a model's limits may be ints, and so the clipped command), covariances left at
        # their zeros, the scan's constants made floats above, the World's float64 ranges
        # within range_max or infinite (finish_ranges).
        self.odom_pub.trust()
        self.pose_pub.trust()
        self.scan_pub.trust()
        # tf2's broadcasters' topics and QoS: /tf keeps 100, /tf_static is latched.
        self.tf_pub = self.create_publisher(TFMessage, "/tf", 100)
        self.tf_static_pub = self.create_publisher(
            TFMessage, "/tf_static", QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        )
        self.tf_static_pub.publish(self._static_transforms(prefix))
        self.contact_pub = self.create_publisher(
            Bool, "sim/contact", QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        )
        self._touching: bool | None = None
        # Commands come from outside (the command line, other nodes): name who sends a bad one.
        self.create_subscription(Twist, "cmd_vel", self.on_cmd_vel, 10).track_senders()
        # One timer for both: the scan's ticks fell on every other odometry tick anyway, and
        # each tick of a timer costs the runtime a wake-up of the node.
        self._ticks = 0
        self.create_timer(ODOM_PERIOD, self.tick)

    def tick(self) -> None:
        """Publish odometry (20 Hz) and, on every other tick, the scan (10 Hz) if anyone reads it, with one stamp."""
        stamp = self.get_clock().now().to_msg()
        self.publish_odometry(stamp)
        self._ticks += 1
        if self._ticks % SCAN_EVERY == 0:
            # Casting the lidar costs more than the rest of a tick: with nobody to read the scan
            # (no subscription, recorder, bridge or live view) it is not cast, as simulators skip
            # sensors without connections.  The noise moves on, so a reader that joins later gets
            # the scans it would have got from the start.
            if self.scan_pub.get_subscription_count() or self.world.draws_scans:
                self.publish_scan(stamp)
            else:
                self.world.skip_scan(self.name)

    def on_cmd_vel(self, msg: Twist) -> None:
        """Command the robot: linear.x (m/s) and angular.z (rad/s); MessageRefused if they are not finite.

        A topic carries only what its type allows (publish checks every field),
        so both are floats; NaN and infinities are what a float may still hold.
        """
        v, w = msg.linear.x, msg.angular.z
        if not (math.isfinite(v) and math.isfinite(w)):
            raise MessageRefused("linear.x and angular.z must be finite")
        self.robot.command(v, w)

    def publish_odometry(self, stamp: TimeMsg) -> None:
        """Publish odom, the ground-truth pose, and the contact state if it changed, stamped ``stamp``."""
        robot = self.robot
        odometry = robot.odometry()
        x, y, theta, v, w = odometry
        x0, y0, theta0 = self._start
        # Odometry starts at the start pose: express the pose in that frame.
        c, s = self._start_cos_sin
        dx, dy = x - x0, y - y0
        msg = self._odom
        msg.header.stamp = stamp
        pose = msg.pose.pose
        position, orientation = pose.position, pose.orientation
        position.x, position.y = c * dx + s * dy, -s * dx + c * dy
        _set_yaw(orientation, math.remainder(theta - theta0, math.tau))
        twist = msg.twist.twist
        twist.linear.x, twist.angular.z = float(v), float(w)  # trusted (see __init__): made floats here
        self.odom_pub.publish(msg)
        if self.tf_pub.get_subscription_count():  # nobody listens: no transform to fill
            tf = self._tf.transforms[0]
            tf.header.stamp = stamp
            tf.transform.translation.x, tf.transform.translation.y = position.x, position.y
            rotation = tf.transform.rotation
            rotation.z, rotation.w = orientation.z, orientation.w
            self.tf_pub.publish(self._tf)

        # Without odometry noise the odometry is the truth, read from the body once.
        truth = robot.pose if self._noisy_odometry else odometry
        ground = self._ground
        ground.header.stamp = stamp
        pose = ground.pose
        pose.position.x, pose.position.y = truth.x, truth.y
        _set_yaw(pose.orientation, truth.theta)
        self.pose_pub.publish(ground)

        touching = robot.in_contact
        if touching != self._touching:
            self._touching = touching
            self.contact_pub.publish(Bool(data=touching))

    def _static_transforms(self, prefix: str) -> TFMessage:
        """The robot's fixed frames: world -> odom at the start pose, and the body's frames above the floor."""
        stamp = self.get_clock().now().to_msg()
        x0, y0, theta0 = self._start

        def fixed(parent: str, child: str, x: float = 0.0, y: float = 0.0, z: float = 0.0, yaw: float = 0.0):
            return TransformStamped(
                header=Header(stamp=stamp, frame_id=parent),
                child_frame_id=child,
                transform=Transform(translation=Vector3(x=x, y=y, z=z), rotation=yaw_quaternion(yaw)),
            )

        return TFMessage(
            transforms=[
                fixed(frames.WORLD, prefix + frames.ODOM, x0, y0, yaw=theta0),
                fixed(prefix + frames.BASE_FOOTPRINT, prefix + frames.BASE_LINK, z=frames.BASE_LINK_Z),
                fixed(prefix + frames.BASE_LINK, prefix + frames.BASE_SCAN, z=frames.SCAN_Z),
            ]
        )

    def publish_scan(self, stamp: TimeMsg) -> None:
        """Publish the lidar scan, stamped ``stamp``."""
        scan = self._scan
        scan.header.stamp = stamp
        # The World's array as it is: publish() lists a float array's values in one C call.
        scan.ranges = self.world.scan(self.name)
        self.scan_pub.publish(scan)
