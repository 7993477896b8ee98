"""explore_lite's planning step: which frontier to pursue, when to give up on one, when exploration is over.

Each step (every 1/planner_frequency s, and at once when a goal ends) takes the frontiers sorted by cost and
picks the first whose centroid is not blacklisted. No frontier, or none left, stops exploration. A target that
changes, or a frontier that came nearer (its min_distance fell), counts as progress; no progress for
progress_timeout s blacklists the target and the step is taken again. A new target is sent to move_base; the same
target is left alone. A goal that ends ABORTED is blacklisted. Times are seconds of ROS time, passed in.
"""

from dataclasses import dataclass

from lab_nav.exploration.blacklist import next_frontier

STOP, KEEP, SEND = "stop", "keep", "send"
BLACKLISTED = "Adding current goal to black list"


@dataclass(frozen=True)
class Step:
    """What to do: STOP (cancel all goals, stop the timer), KEEP (the current goal stands) or SEND `target`
    (x, y) as a new goal. `frontier` is the one chosen (None for STOP); `blacklisted` lists targets this step added
    to the blacklist."""

    action: str
    target: tuple = None
    frontier: object = None
    blacklisted: tuple = ()


class Explorer:
    """The blacklist and progress bookkeeping between steps."""

    def __init__(self, progress_timeout_s):
        self.progress_timeout_s = progress_timeout_s
        self.blacklist = []
        self._previous_target = None
        self._previous_distance = 0.0
        self._last_progress_s = 0.0

    def step(self, frontiers, resolution, now_s):
        """The Step for `frontiers` (sorted by cost) on a map of `resolution` m/cell at time `now_s`."""
        added = []
        while True:
            frontier = next_frontier(frontiers, self.blacklist, resolution)
            if frontier is None:
                return Step(STOP, blacklisted=tuple(added))
            target = frontier.centroid
            same_target = target == self._previous_target
            self._previous_target = target
            if not same_target or self._previous_distance > frontier.min_distance:
                self._last_progress_s = now_s
                self._previous_distance = frontier.min_distance
            if now_s - self._last_progress_s > self.progress_timeout_s:
                self.blacklist.append(target)
                added.append(target)
                continue
            action = KEEP if same_target else SEND
            return Step(action, target, frontier, tuple(added))

    def goal_ended(self, target, aborted):
        """Record the end of the goal sent for `target`; an aborted goal's target is blacklisted (returns True)."""
        if aborted:
            self.blacklist.append(target)
        return aborted
