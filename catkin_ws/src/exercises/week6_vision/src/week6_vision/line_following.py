"""The line follower's decisions, as pure functions of what the camera shows: a proportional steering law and what
to do when the line is not in view.

Steering: angular = -gain * (line column - target column) / (width / 2), clamped to +-max_angular; a line right of
the target (a larger column) turns the robot right (negative z). The course's kp = -0.001 rad/s per pixel at
1920 px is a gain of 0.96 here; the default 1.5 holds the Waffle within about 2 cm of the line on the
line_following track's tightest bends (radius about 0.45 m) at 0.1 m/s.
No line in view: before the line was ever seen the robot turns on the spot to look for it (anticlockwise, at
search_angular). Once it has followed the line, losing it means the end of the line has passed under the stretch
of floor the camera watches: the robot drives straight on for `coast_m` (the distance from its centre to that
stretch) so that it stops over the line's end, not short of it; if the line comes back meanwhile, it follows on.
A mark across the line (the track's START and FINISH bars) makes the mask span more than MAX_LINE_SPAN of the
image's width, and its centroid says nothing about where the line runs: the robot drives straight over it.
"""
from typing import NamedTuple

DEFAULT_LINEAR_MPS = 0.1
DEFAULT_GAIN = 1.5
DEFAULT_MAX_ANGULAR_RADPS = 1.0
DEFAULT_SEARCH_ANGULAR_RADPS = 0.3
MAX_LINE_SPAN = 0.6      # of the image's width: the 0.15 m line spans at most about 30 % 0.3 m ahead
DEFAULT_COAST_M = 0.37   # the Waffle's camera is 0.07 m ahead of its centre; the follower watches 0.3 m ahead of it


class Command(NamedTuple):
    linear: float
    angular: float
    status: str   # "searching", "following", "crossing a mark", "finishing" (coasting over the line's end) or
                  # "end of the line"


def proportional_steering(line_x, target_x, width, gain=DEFAULT_GAIN, max_angular=DEFAULT_MAX_ANGULAR_RADPS):
    """The angular velocity (rad/s) that turns the line's column `line_x` toward `target_x` in an image `width`
    pixels wide."""
    angular = -gain * (line_x - target_x) / (width / 2.0)
    return max(-max_angular, min(max_angular, angular))


class LineFollowing:
    """What to command for each camera frame: `command(line_x, target_x, width, now_s, span)`, with line_x None
    when no line is in view, now_s the frame's time (s) and span the fraction of the width the mask covers."""

    def __init__(self, linear=DEFAULT_LINEAR_MPS, gain=DEFAULT_GAIN, max_angular=DEFAULT_MAX_ANGULAR_RADPS,
                 search_angular=DEFAULT_SEARCH_ANGULAR_RADPS, coast_m=DEFAULT_COAST_M):
        self.linear, self.gain, self.max_angular = linear, gain, max_angular
        self.search_angular, self.coast_s = search_angular, coast_m / linear if linear > 0 else 0.0
        self.seen_line = False
        self.lost_at_s = None

    def command(self, line_x, target_x, width, now_s, span=0.0):
        if line_x is None:
            if not self.seen_line:
                return Command(0.0, self.search_angular, "searching")
            if self.lost_at_s is None:
                self.lost_at_s = now_s
            if now_s - self.lost_at_s < self.coast_s:
                return Command(self.linear, 0.0, "finishing")
            return Command(0.0, 0.0, "end of the line")
        self.seen_line, self.lost_at_s = True, None
        if span > MAX_LINE_SPAN:
            return Command(self.linear, 0.0, "crossing a mark")
        return Command(self.linear, proportional_steering(line_x, target_x, width, self.gain, self.max_angular),
                       "following")
