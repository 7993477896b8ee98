"""The decisions of turtlebot3_drive, turtlebot3_gazebo's obstacle-avoidance demo (noetic-devel), without ROS.

The demo looks at three LiDAR beams and the robot's heading, and wanders: it drives straight ahead while the way
is clear and turns on the spot by a fixed escape angle when something is close. The ROS node (drive_node) calls
`ObstacleAvoider.step` once per control tick (CONTROL_RATE_HZ of ROS time) with the latest ranges and heading,
and publishes the command it returns, if any.

Beams (`ranges_from_scan`): indices 0 (ahead), 30 (left) and 330 (right) of the /scan ranges. On the LDS-01 as
Gazebo and tb3_sim publish it (360 beams, angle_increment 6.28319 / 359 rad, CCW from +x of base_scan) they point
at 0, +30.1 and -29.4 degrees. The LiDAR sits 6.4 cm behind the rotation centre, so "0.7 m ahead" is measured
from there. An infinite reading (Gazebo and tb3_sim give +inf where nothing is hit within range_max 3.5 m)
counts as range_max; NaN is kept and, as in the original, fails every comparison.

States and ticks (`step`):
- GET_DIRECTION publishes nothing and picks the next state: ahead < 0.7 m -> RIGHT_TURN (always right);
  ahead > 0.7 m and left < 0.6 m -> RIGHT_TURN; ahead > 0.7 m and right < 0.6 m -> LEFT_TURN; ahead > 0.7 m and
  both sides >= 0.6 m -> DRIVE_FORWARD. A reading of exactly 0.7 m ahead, or NaN ahead, stays in GET_DIRECTION.
  Starting a turn remembers the heading.
- DRIVE_FORWARD publishes (0.3 m/s, 0) and goes back to GET_DIRECTION: while the way is clear, ticks alternate
  between deciding and publishing.
- RIGHT_TURN / LEFT_TURN publish (0, -1.5 rad/s) / (0, +1.5 rad/s) each tick until the heading has changed by the
  escape angle (30 degrees) from where the turn started; that tick publishes nothing and goes to GET_DIRECTION
  (the robot keeps the last command, so it goes on turning until the next decision publishes).
The speeds are the original's: 0.3 m/s and 1.5 rad/s, above the Waffle's 0.26 m/s and 1.82 rad/s vendor
limit for the linear one; Gazebo's drive plugin does not clamp them and neither does tb3_sim by default.

Deliberate differences from the original:
- The heading change of a turn is measured as the wrapped angle between the two headings. The original
  subtracts the raw yaw values, so a turn that crosses +-pi ends early (the next decision then starts another
  one if the way is still blocked).
- The node asks for a decision only once it has a scan and a heading. The original starts deciding on zeroed
  ranges, so its first decision is always a right turn.
"""

import enum
import math
from typing import NamedTuple

CENTER_BEAM_INDEX = 0
LEFT_BEAM_INDEX = 30
RIGHT_BEAM_INDEX = 330

FORWARD_CLEARANCE_M = 0.7
"""A reading ahead below this starts a (right) turn."""
SIDE_CLEARANCE_M = 0.6
"""A reading on the left (right) below this, with the way ahead clear, starts a right (left) turn."""
ESCAPE_ANGLE_RAD = math.radians(30.0)
"""A turn ends once the heading has changed by this much."""

LINEAR_VELOCITY_MPS = 0.3
ANGULAR_VELOCITY_RADPS = 1.5

CONTROL_RATE_HZ = 125.0
"""Decisions per second of ROS time (simulated time under /use_sim_time)."""


class DriveError(ValueError):
    """An input the demo cannot use; the text says what was wrong and what is expected."""


class Ranges(NamedTuple):
    """The three readings the demo uses, in metres from the LiDAR (range_max where nothing was hit)."""

    center: float
    left: float
    right: float


class Command(NamedTuple):
    """A velocity command: linear.x in m/s and angular.z in rad/s (positive = CCW = left)."""

    linear: float
    angular: float


class State(enum.Enum):
    """The demo's states, numbered as in the original."""

    GET_DIRECTION = 0
    DRIVE_FORWARD = 1
    RIGHT_TURN = 2
    LEFT_TURN = 3


FORWARD = Command(LINEAR_VELOCITY_MPS, 0.0)
TURN_RIGHT = Command(0.0, -ANGULAR_VELOCITY_RADPS)
TURN_LEFT = Command(0.0, ANGULAR_VELOCITY_RADPS)
STOP = Command(0.0, 0.0)


def ranges_from_scan(ranges, range_max):
    """The Ranges of a LaserScan's `ranges` (a sequence of metres) with its `range_max`; +-inf becomes range_max.

    Raises DriveError if the scan has too few beams to read index RIGHT_BEAM_INDEX.
    """
    if len(ranges) <= RIGHT_BEAM_INDEX:
        raise DriveError(f"the scan has {len(ranges)} ranges, but turtlebot3_drive reads beams {CENTER_BEAM_INDEX}, "
                         f"{LEFT_BEAM_INDEX} and {RIGHT_BEAM_INDEX}, so it needs at least {RIGHT_BEAM_INDEX + 1} "
                         "(the LDS-01 gives 360)")
    return Ranges(*(float(range_max) if math.isinf(ranges[i]) else float(ranges[i])
                    for i in (CENTER_BEAM_INDEX, LEFT_BEAM_INDEX, RIGHT_BEAM_INDEX)))


def heading_from_quaternion(x, y, z, w):
    """Yaw in rad, in (-pi, pi], of the orientation quaternion (x, y, z, w) (CCW from +x of its frame)."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def angle_between(a, b):
    """The absolute angle in rad, in [0, pi], between headings `a` and `b` (rad)."""
    return abs(math.remainder(a - b, 2.0 * math.pi))


class ObstacleAvoider:
    """The demo's state machine: one `step` per control tick."""

    def __init__(self):
        self.state = State.GET_DIRECTION
        self.turn_start_heading = 0.0

    def step(self, ranges, heading):
        """Decide one tick from the latest `ranges` (Ranges) and `heading` (rad).

        Returns the Command to publish, or None when this tick publishes nothing.
        """
        if self.state is State.GET_DIRECTION:
            self._choose_direction(ranges, heading)
            return None
        if self.state is State.DRIVE_FORWARD:
            self.state = State.GET_DIRECTION
            return FORWARD
        if angle_between(heading, self.turn_start_heading) >= ESCAPE_ANGLE_RAD:
            self.state = State.GET_DIRECTION
            return None
        return TURN_RIGHT if self.state is State.RIGHT_TURN else TURN_LEFT

    def _choose_direction(self, ranges, heading):
        # Strict comparisons on purpose: a reading of exactly the clearance, or NaN, decides nothing.
        if ranges.center < FORWARD_CLEARANCE_M:
            self._start_turn(State.RIGHT_TURN, heading)
        elif ranges.center > FORWARD_CLEARANCE_M:
            if ranges.left < SIDE_CLEARANCE_M:
                self._start_turn(State.RIGHT_TURN, heading)
            elif ranges.right < SIDE_CLEARANCE_M:
                self._start_turn(State.LEFT_TURN, heading)
            else:
                self.state = State.DRIVE_FORWARD

    def _start_turn(self, state, heading):
        self.state = state
        self.turn_start_heading = heading

