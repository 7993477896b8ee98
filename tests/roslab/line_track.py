"""tuos_simulations' line_following track from the original's numbers (the seven cubic Béziers of its pink line's
centre, the FINISH box), and one run of a line follower along it: what the line-follower test and benchmark
measure (lap time, the robot's distance to the line's centre, where it stopped)."""
import statistics
from typing import NamedTuple

import numpy as np

from roslab.robot_view import pose_of
from roslab.waiting import wait_until

TRACK_BEZIERS = [   # start, control 1, control 2, end (m); the line starts at the launch file's START pose
    ((2.3797, -2.5004), (2.3797, -2.5004), (-1.0369, -2.9464), (-1.9639, -2.5206)),
    ((-1.9639, -2.5206), (-2.8909, -2.0947), (-3.0883, -1.7718), (-3.1155, -1.1670)),
    ((-3.1155, -1.1670), (-3.1426, -0.5622), (-2.9017, -0.0899), (-2.0447, 0.3483)),
    ((-2.0447, 0.3483), (-1.1877, 0.7864), (1.0529, -0.0693), (1.8747, 0.3079)),
    ((1.8747, 0.3079), (2.6964, 0.6850), (2.8410, 0.9429), (2.8444, 1.4594)),
    ((2.8444, 1.4594), (2.8478, 1.9759), (2.6759, 2.2908), (1.8343, 2.6918)),
    ((1.8343, 2.6918), (0.9926, 3.0928), (-2.1659, 2.7120), (-2.1659, 2.7120)),
]
TRACK_END = (-2.1659, 2.7120)
FINISH_BOX = [(-3.357, 3.174), (-2.065, 3.289), (-1.927, 2.141), (-3.219, 2.026)]
END_OF_LINE_LOG = "Line follower: end of the line."   # what week6_vision's line_follower.py logs when it stops


def track_points(samples_per_curve=400):
    """Points along the line's centre, under 1 cm apart."""
    t = np.linspace(0.0, 1.0, samples_per_curve)[:, None]
    curves = [(1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * c1 + 3 * (1 - t) * t ** 2 * c2 + t ** 3 * p1
              for p0, c1, c2, p1 in (np.array(b) for b in TRACK_BEZIERS)]
    return np.vstack(curves)


def distance_to_track(points):
    """Distance (m) from each (x, y) row of `points` to the line's centre."""
    track = track_points()
    return np.sqrt(((points[:, None, :] - track[None, :, :]) ** 2).sum(axis=2)).min(axis=1)


def in_finish_box(point):
    corners = FINISH_BOX
    signs = [(bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax)
             for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1])]
    return all(s > 0 for s in signs) or all(s < 0 for s in signs)


class Lap(NamedTuple):
    lap_s: float                 # sim seconds from the robot's first move to the follower's "end of the line"
    mean_distance_m: float       # the robot's mean distance to the line's centre while it moved
    max_distance_m: float
    end: tuple                   # (x, y) where it stopped


def follow_the_line(master, probe, timeout_s=300):
    """Start week6_vision's line_follower.py on `master` (line_following.launch running, `probe` subscribed to
    /odom and /rosout_agg) and measure its lap until it logs the end of the line."""
    probe.take("/odom")
    probe.take("/rosout_agg")
    master.rosrun("week6_vision", "line_follower.py")
    odometry, end_log = [], []

    def at_the_end():
        odometry.extend(entry["msg"] for entry in probe.take("/odom"))
        end_log.extend(e["msg"] for e in probe.take("/rosout_agg") if e["msg"]["msg"] == END_OF_LINE_LOG)
        return end_log
    wait_until(at_the_end, timeout_s, "the line follower to reach the end of the line")
    first_move = next(m for m in odometry if abs(m["twist"]["twist"]["linear"]["x"]) > 1e-3)
    lap_s = end_log[0]["header"]["stamp"] - first_move["header"]["stamp"]
    path = np.array([pose_of(m)[:2] for m in odometry])
    moving = path[np.r_[True, np.hypot(*np.diff(path, axis=0).T) > 1e-4]]
    distances = distance_to_track(moving)
    return Lap(lap_s, float(statistics.mean(distances)), float(distances.max()), tuple(path[-1]))
