"""What the robot did during one graded call, from ground-truth odometry samples (plain Python, no ROS).

A `Sample` is one ground-truth state of tb3_sim's robot (its private channel, lab_grader.checks.ground_truth; no
noise): sim time (s), pose (x, y in m, yaw in rad, world = odom frame) and body-frame velocities (v forward in m/s,
w counter-clockwise in rad/s).

`summarize(samples, since_s)` turns a recording into a `MotionSummary`, measured in the robot's *initial* frame,
the pose at the moment the request was sent (the last sample at or before `since_s`):
- forward_m: signed displacement along the initial heading (negative: it reversed);
- lateral_m: signed displacement across it (positive: to the robot's left);
- turn_deg: signed accumulated heading change (counter-clockwise positive; a 400 degree spin reads 400, not 40);
- displacement_m: straight-line distance from start to end; excursion_m: the farthest it ever got from the start;
- start_s / stop_s: sim time of the first sample that moves and of the first still sample after the last moving
  one (a sample moves when |v| > STILL_LINEAR_MPS or |w| > STILL_ANGULAR_RADPS); duration_s = stop_s - start_s,
  0 when it never moved, and up to the last sample when it never stopped (stop_s None, still_at_end False);
- still_at_end: the last sample is still (the recorder ends it `settle_s` after the reply).
Times in the evidence (started_after_s, stopped_after_s) count from `since_s`, the moment the request was sent.

Resolution: tb3_sim reports the state at 30 Hz, so start and stop are known to 1/30 s; a TurtleBot3's drive ramps
at about 1 m/s^2, so a 0.1 m/s motion reads ~0.1 s longer than its command.
"""
import math
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple

STILL_LINEAR_MPS = 0.01
STILL_ANGULAR_RADPS = 0.01
MAX_TRAJECTORY_POINTS = 400


class Sample(NamedTuple):
    t: float     # sim time, s
    x: float     # m
    y: float     # m
    yaw: float   # rad, CCW from +x
    v: float     # forward speed in the body frame, m/s
    w: float     # yaw rate, rad/s (CCW positive)


class MotionSummary(NamedTuple):
    since_s: float
    start_s: Optional[float]
    stop_s: Optional[float]
    duration_s: float
    forward_m: float
    lateral_m: float
    turn_deg: float
    displacement_m: float
    excursion_m: float
    still_at_end: bool
    end_v: float
    end_w: float

    @property
    def moved(self):
        return self.start_s is not None

    @property
    def mean_speed_mps(self):
        """forward_m / duration_s (m/s, negative when reversing): the speed it drove at, the drive's ramps
        included (0.1 m/s over 0.8 m reads ~0.099); 0 when it never moved."""
        return self.forward_m / self.duration_s if self.duration_s > 0 else 0.0

    def as_evidence(self):
        """The JSON form of the result file's evidence.motion (rounded to 0.1 mm, 0.01 deg and 1 ms)."""
        return {
            "duration_s": round(self.duration_s, 3),
            "forward_m": round(self.forward_m, 4),
            "lateral_m": round(self.lateral_m, 4),
            "turn_deg": round(self.turn_deg, 2),
            "still_at_end": self.still_at_end,
            "displacement_m": round(self.displacement_m, 4),
            "excursion_m": round(self.excursion_m, 4),
            "started_after_s": None if self.start_s is None else round(self.start_s - self.since_s, 3),
            "stopped_after_s": None if self.stop_s is None else round(self.stop_s - self.since_s, 3),
            "end_v": round(self.end_v, 4),
            "end_w": round(self.end_w, 4),
            "mean_speed_mps": round(self.mean_speed_mps, 4),
        }


class Observation(NamedTuple):
    """The raw record of one graded call: the request sent, the reply (fields as a dict) or the error text, when
    (sim s) the request went out and the reply came back, every /odom sample from before the call until `settle_s`
    after the reply (None when the suite has no robot), and the distance to the nearest object ahead once still (m;
    the LiDAR's view without its noise, from the simulator's private channel; None when nothing was in range, or
    when not measured: see `front_measured`). `server_error` is True when the error is
    the server's own answer (its callback raised), not a timeout or a broken connection. `interference` lists what
    the submission did to the measurement meanwhile, in words (lab_grader.checks.interference; empty: nothing)."""

    request: Dict[str, Any]
    reply: Optional[Dict[str, Any]]
    error: Optional[str]
    sent_s: float
    replied_s: Optional[float]
    samples: Optional[Tuple[Sample, ...]]
    front_distance_m: Optional[float] = None
    front_measured: bool = False
    server_error: bool = False
    interference: Tuple[str, ...] = ()


class MotionError(ValueError):
    """No samples to summarize (the odometry never arrived)."""


def wrap_angle(radians):
    """`radians` wrapped into (-pi, pi]."""
    return math.atan2(math.sin(radians), math.cos(radians))


def is_still(sample, still_linear=STILL_LINEAR_MPS, still_angular=STILL_ANGULAR_RADPS):
    return abs(sample.v) <= still_linear and abs(sample.w) <= still_angular


def origin_index(samples, since_s):
    """Index of the last sample at or before `since_s` (the pose when the request went out), else 0."""
    index = 0
    for i, sample in enumerate(samples):
        if sample.t <= since_s:
            index = i
        else:
            break
    return index


def summarize(samples: Sequence[Sample], since_s: float, still_linear: float = STILL_LINEAR_MPS,
              still_angular: float = STILL_ANGULAR_RADPS) -> MotionSummary:
    """The motion in `samples` (sorted by time) from the pose at `since_s` on; see the module docstring."""
    if not samples:
        raise MotionError("no odometry was recorded")
    timeline = list(samples[origin_index(samples, since_s):])
    origin, end = timeline[0], timeline[-1]
    cos0, sin0 = math.cos(origin.yaw), math.sin(origin.yaw)

    def offset(sample):
        dx, dy = sample.x - origin.x, sample.y - origin.y
        return dx * cos0 + dy * sin0, -dx * sin0 + dy * cos0

    forward, lateral = offset(end)
    turn = sum(wrap_angle(b.yaw - a.yaw) for a, b in zip(timeline, timeline[1:]))
    excursion = max(math.hypot(*offset(sample)) for sample in timeline)

    moving = [i for i, sample in enumerate(timeline) if not is_still(sample, still_linear, still_angular)]
    start_s = stop_s = None
    duration = 0.0
    if moving:
        start_s = timeline[moving[0]].t
        after_last = moving[-1] + 1
        if after_last < len(timeline):
            stop_s = timeline[after_last].t
            duration = stop_s - start_s
        else:
            duration = end.t - start_s
    return MotionSummary(
        since_s=since_s, start_s=start_s, stop_s=stop_s, duration_s=duration, forward_m=forward, lateral_m=lateral,
        turn_deg=math.degrees(turn), displacement_m=math.hypot(forward, lateral), excursion_m=excursion,
        still_at_end=is_still(end, still_linear, still_angular), end_v=end.v, end_w=end.w)


def thin(samples: Sequence[Sample], since_s: float, max_points: int = MAX_TRAJECTORY_POINTS) -> List[List[float]]:
    """[[t, x, y, yaw], ...] with t in sim seconds since `since_s`, at most `max_points` evenly spread samples
    (always the first and the last), rounded to 1 ms, 0.1 mm and 1e-4 rad. Deterministic."""
    if max_points < 2:
        raise ValueError("max_points must be at least 2")
    count = len(samples)
    if count <= max_points:
        chosen = range(count)
    else:
        chosen = sorted({round(i * (count - 1) / (max_points - 1)) for i in range(max_points)})
    return [[round(samples[i].t - since_s, 3), round(samples[i].x, 4), round(samples[i].y, 4),
             round(samples[i].yaw, 4)] for i in chosen]
