"""The SLAM tests' and benchmarks' scripted drives: a route per world and the steering law that follows it.

Steering turns in place towards the next waypoint, then drives at DRIVE_MPS while correcting the heading.
"""
import math

DRIVE_MPS = 0.22
TURN_GAIN = 2.5
MAX_TURN_RADPS = 1.2
ALIGNED_RAD = 0.15
REACHED_M = 0.06

# world name -> (the world launch file's spawn pose (x, y, yaw), waypoints): around the pillars of
# turtlebot3_world; around the table of the house's first room.
ROUTES = {
    "turtlebot3_world": ((-2.0, -0.5, 0.0),
                         ((-1.65, -0.5), (-1.65, -1.6), (1.65, -1.6), (1.65, 1.6), (-1.65, 1.6), (-1.65, -0.4))),
    "turtlebot3_house": ((-3.0, 1.0, 0.0),
                         ((-1.0, 1.0), (-1.0, 4.2), (-4.2, 4.2), (-4.2, 1.0), (-3.0, 1.0))),
}


def steer(pose, waypoint):
    """(linear m/s, angular rad/s) from `pose` (x, y, yaw) towards `waypoint` (x, y); None once it is reached."""
    x, y, yaw = pose
    distance = math.hypot(waypoint[0] - x, waypoint[1] - y)
    if distance < REACHED_M:
        return None
    error = math.remainder(math.atan2(waypoint[1] - y, waypoint[0] - x) - yaw, 2.0 * math.pi)
    linear = min(DRIVE_MPS, distance) if abs(error) < ALIGNED_RAD else 0.0
    return linear, max(-MAX_TURN_RADPS, min(MAX_TURN_RADPS, TURN_GAIN * error))
