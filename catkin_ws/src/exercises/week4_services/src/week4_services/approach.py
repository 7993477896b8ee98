"""The approach controller: drive straight ahead and stop `distance` metres from the closest object ahead.

Between LiDAR sweeps (5 Hz) the distance is dead-reckoned from odometry (30 Hz): the last measured distance
minus how far the robot has travelled since that sweep was measured. "Since" goes by the messages' stamps, not
by when they were handled: the travel at the sweep's stamp is the odometry's travel corrected by speed times the
stamps' difference. (A server that pairs a sweep with whatever odometry it last saw is off by the travel between
the two whenever its /odom and /scan callbacks run skewed, as on a loaded machine: up to centimetres at 3x.)
The stop is commanded early by the braking distance v^2 / (2 * DECELERATION_MPS2), because a TurtleBot3 does not
stop instantly (the Gazebo drive ramps the wheel speed at about 1 m/s^2). Safety limit: when nothing is seen ahead,
the robot drives at most SAFETY_TRAVEL_M (the LiDAR's 3.5 m range: anything it could have driven into would have
been seen by then) and stops. Time limit: an approach ends after TIME_LIMIT_S of driving whatever it has reached,
so that a valid but tiny velocity (1e-6 m/s passes the (0, 0.26] check) or a robot pushing against something the
LiDAR cannot see never holds the server for ever (found by fuzzing).
Pure logic: the caller feeds odometry, sweeps and the elapsed time, then publishes the velocity `step` returns.
"""
import enum
from typing import NamedTuple, Optional

from tb3_client.motion import MAX_MOTION_S

DECELERATION_MPS2 = 1.0
SAFETY_TRAVEL_M = 3.5
TIME_LIMIT_S = MAX_MOTION_S


class Outcome(enum.Enum):
    DRIVING = "driving"
    ARRIVED = "arrived"
    ALREADY_THERE = "already_there"
    NOTHING_AHEAD = "nothing_ahead"
    TIME_LIMIT = "time_limit"


class Step(NamedTuple):
    """What to do now: drive at `velocity` m/s (0 = stop); `outcome` is DRIVING until the approach ends."""

    velocity: float
    outcome: Outcome


class ApproachController:
    """One approach. Feed it every odometry update (`on_odometry`), every LiDAR sweep (`on_sweep`) and the time
    since the start (`on_clock`), then publish the velocity of `step()`. Stamps are rospy time in seconds."""

    def __init__(self, plan):
        self.plan = plan
        self._measured: Optional[float] = None
        self._travelled_at_sweep = 0.0
        self._travelled = 0.0
        self._speed = 0.0
        self._odom_stamp_s: Optional[float] = None
        self._sweeps = 0
        self.outcome = Outcome.DRIVING

    def on_odometry(self, travelled_m: float, speed_mps: float, stamp_s: float):
        """Distance driven since the start (m) and forward speed (m/s), as odometry stamped `stamp_s` says."""
        self._travelled, self._speed, self._odom_stamp_s = travelled_m, speed_mps, stamp_s

    def on_sweep(self, closest_distance: Optional[float], stamp_s: float):
        """A new sweep measured at `stamp_s`: the closest object ahead in metres, or None when nothing is seen
        ahead."""
        self._sweeps += 1
        self._measured = closest_distance
        self._travelled_at_sweep = self.travelled_at(stamp_s)
        if self._sweeps == 1 and closest_distance is not None and closest_distance <= self.plan.distance:
            self.outcome = Outcome.ALREADY_THERE

    def travelled_at(self, stamp_s: float) -> float:
        """The travel at `stamp_s`: the latest odometry's, moved on (or back) at its speed to that stamp."""
        if self._odom_stamp_s is None:
            return self._travelled
        return self._travelled + self._speed * (stamp_s - self._odom_stamp_s)

    def on_clock(self, elapsed_s: float):
        """Seconds (rospy time) since the approach started: past TIME_LIMIT_S the approach ends."""
        if self.outcome is Outcome.DRIVING and elapsed_s >= TIME_LIMIT_S:
            self.outcome = Outcome.TIME_LIMIT

    def step(self) -> Step:
        """The command to publish now, given everything fed so far."""
        if self.outcome is not Outcome.DRIVING or self._sweeps == 0:
            return Step(0.0, self.outcome)
        braking = max(self._speed, 0.0) ** 2 / (2.0 * DECELERATION_MPS2)
        estimate = self.estimated_distance()
        if estimate is not None and estimate - braking <= self.plan.distance:
            self.outcome = Outcome.ARRIVED
        elif estimate is None and self._travelled + braking >= SAFETY_TRAVEL_M:
            self.outcome = Outcome.NOTHING_AHEAD
        velocity = self.plan.velocity if self.outcome is Outcome.DRIVING else 0.0
        return Step(velocity, self.outcome)

    def estimated_distance(self) -> Optional[float]:
        """The closest object ahead at the latest odometry's stamp: the last sweep's distance minus the travel
        since that sweep was measured, or None."""
        if self._measured is None:
            return None
        return self._measured - (self._travelled - self._travelled_at_sweep)
