"""The colour search's decisions, as a pure state machine over camera frames: turn on the spot until a pillar of
the colour being looked for is in view, turn it to the middle of the image (proportional control), stop there
facing it for `pause_s`, then look for the next colour; stop for good after the last.

`update(offset, now_s)` takes the pillar's horizontal offset from the image's middle as a fraction of the
half-width (-1 at the left edge, +1 at the right, None when that colour is not in view) and the time (s; rospy
time in the node) and returns a `Step`: the angular velocity to command and, when something happened, an event.
A colour not in view within one full turn plus a quarter (`give_up_s` = 1.25 x 2 pi / turn_speed) is given up
with a "not found" event. The step that ends the last colour's pause (or gives it up) has done=True.

Named apart from the node nodes/colour_search.py: with two colour_search.py files in the package (and every .py
file executable, as the course has students make them) `rosrun week6_vision colour_search.py` would ask which.
"""
import math
from typing import NamedTuple, Optional

DEFAULT_TURN_RADPS = 0.4
DEFAULT_GAIN = 0.5            # rad/s per half-width of offset
DEFAULT_TOLERANCE = 0.02      # 1 % of the image's width: 0.8 degrees of the Waffle's 77-degree view
DEFAULT_PAUSE_S = 2.0


class Step(NamedTuple):
    angular: float
    event: Optional[str] = None   # "facing <colour>" or "<colour> not found"
    done: bool = False            # the last colour has been dealt with: the search is over


class ColourSearch:
    def __init__(self, colours, turn_speed=DEFAULT_TURN_RADPS, gain=DEFAULT_GAIN, tolerance=DEFAULT_TOLERANCE,
                 pause_s=DEFAULT_PAUSE_S):
        self.colours = list(colours)
        self.turn_speed, self.gain, self.tolerance, self.pause_s = turn_speed, gain, tolerance, pause_s
        self.give_up_s = 1.25 * 2.0 * math.pi / turn_speed
        self.index = 0
        self.started_s = None      # when the search for the current colour began
        self.paused_until_s = None

    @property
    def target(self):
        """The colour being looked for, or None when the search is over."""
        return self.colours[self.index] if self.index < len(self.colours) else None

    def _next_colour(self, now_s, event):
        self.index += 1
        self.started_s, self.paused_until_s = now_s, None
        return Step(0.0, event, done=self.target is None)

    def update(self, offset, now_s):
        if self.target is None:
            return Step(0.0)
        if self.started_s is None:
            self.started_s = now_s
        if self.paused_until_s is not None:
            if now_s < self.paused_until_s:
                return Step(0.0)
            return self._next_colour(now_s, None)
        if offset is None:
            if now_s - self.started_s > self.give_up_s:
                return self._next_colour(now_s, f"{self.target} not found")
            return Step(self.turn_speed)
        if abs(offset) <= self.tolerance:
            self.paused_until_s = now_s + self.pause_s
            return Step(0.0, f"facing {self.target}")
        angular = max(-self.turn_speed, min(self.turn_speed, -self.gain * offset))
        return Step(angular)
