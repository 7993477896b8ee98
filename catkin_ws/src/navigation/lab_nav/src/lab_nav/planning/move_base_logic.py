"""move_base's goal state machine (planning, controlling, clearing) as a pure class; time is passed in.

A goal starts in PLANNING. A plan moves it to CONTROLLING; no plan for planner_patience (or more than
max_planning_retries failures, when that is >= 0) moves it to CLEARING. In CONTROLLING each control cycle either
reaches the goal (SUCCEEDED, "Goal reached."), drives, or finds no valid command: that returns to PLANNING, or to
CLEARING once controller_patience has passed since the last valid command. Moving less than
oscillation_distance for oscillation_timeout (when > 0) also leads to CLEARING. CLEARING runs the next recovery
and goes back to PLANNING with fresh timers; with none left (or recoveries disabled) the goal is ABORTED with
the text of what triggered the recoveries. A new plan resets the recovery sequence when a planning failure
started it, moving oscillation_distance resets it when oscillation did, as in the original.
"""
from dataclasses import dataclass

import numpy as np

from .recovery import default_recoveries

PLANNING, CONTROLLING, CLEARING = "PLANNING", "CONTROLLING", "CLEARING"
PLANNING_R, CONTROLLING_R, OSCILLATION_R = "PLANNING_R", "CONTROLLING_R", "OSCILLATION_R"

GOAL_REACHED = "Goal reached."
ABORT_TEXTS = {
    PLANNING_R: "Failed to find a valid plan. Even after executing recovery behaviors.",
    CONTROLLING_R: "Failed to find a valid control. Even after executing recovery behaviors.",
    OSCILLATION_R: "Robot is oscillating. Even after executing recovery behaviors.",
}
ABORT_LOGS = {
    PLANNING_R: "Aborting because a valid plan could not be found. Even after executing all recovery behaviors",
    CONTROLLING_R: ("Aborting because a valid control could not be found. Even after executing all recovery "
                    "behaviors"),
    OSCILLATION_R: ("Aborting because the robot appears to be oscillating over and over. Even after executing "
                    "all recovery behaviors"),
}


@dataclass(frozen=True)
class MoveBaseParams:
    """move_base_params.yaml's values for turtlebot3 as defaults (s, Hz, m)."""

    planner_frequency: float = 5.0
    controller_frequency: float = 10.0
    planner_patience: float = 5.0
    controller_patience: float = 15.0
    max_planning_retries: int = -1
    oscillation_timeout: float = 10.0
    oscillation_distance: float = 0.2
    recovery_behavior_enabled: bool = True
    clearing_rotation_allowed: bool = True
    conservative_reset_dist: float = 3.0


@dataclass(frozen=True)
class Outcome:
    """What a control cycle decided: `drive` (send the controller's command), `stop` (a zero Twist),
    `succeeded`, `aborted` (with text and log) or `recover` (start recovery `recovery`)."""

    kind: str
    text: str = ""
    log: str = ""
    recovery: object = None
    index: int = -1


class MoveBaseLogic:
    """One move_base's goal handling; the node calls start, on_plan, on_control and end_recovery."""

    def __init__(self, params=MoveBaseParams(), recoveries=None):
        self.params = params
        self.recoveries = recoveries if recoveries is not None else default_recoveries(
            params.conservative_reset_dist, params.clearing_rotation_allowed)
        self.state = None
        self.trigger = None
        self.recovery_index = 0
        self._last_plan_time = None

    @property
    def active(self):
        return self.state is not None

    def start(self, now, position):
        """A new goal (also one that preempts the active one): back to planning with fresh timers."""
        self.state = PLANNING
        self.trigger = None
        self.recovery_index = 0
        self._reset_timers(now, position)
        self._last_plan_time = None

    def finish(self):
        """The goal ended (succeeded, aborted, preempted): nothing is active."""
        self.state = None

    def _reset_timers(self, now, position=None):
        self._last_valid_plan = now
        self._last_valid_control = now
        self._last_oscillation_reset = now
        self._planning_retries = 0
        if position is not None:
            self._oscillation_position = np.asarray(position, dtype=float)

    # --- planning -----------------------------------------------------------------------------------------
    def planner_due(self, now):
        """The planner runs at planner_frequency while a goal is planning or being followed."""
        if self.state not in (PLANNING, CONTROLLING):
            return False
        if self.params.planner_frequency <= 0.0:
            return self.state == PLANNING
        return self._last_plan_time is None or now - self._last_plan_time >= 1.0 / self.params.planner_frequency - 1e-9

    def on_plan(self, now, found):
        """A planning attempt's result; returns an Outcome `stop` when planning has failed for too long."""
        self._last_plan_time = now
        if found:
            self._last_valid_plan = now
            self._planning_retries = 0
            if self.trigger == PLANNING_R:
                self.recovery_index = 0
            if self.state == PLANNING:
                self.state = CONTROLLING
            return None
        self._planning_retries += 1
        retries = self.params.max_planning_retries
        if self.state == PLANNING and (now > self._last_valid_plan + self.params.planner_patience or
                                       (retries >= 0 and self._planning_retries > retries)):
            self._enter_clearing(PLANNING_R)
            return Outcome("stop")
        return None

    # --- control ------------------------------------------------------------------------------------------
    def on_control(self, now, position, reached=False, command_valid=True):
        """One control cycle while CONTROLLING, with the local planner's verdict; returns an Outcome."""
        self._watch_oscillation(now, position)
        if reached:
            return Outcome("succeeded", GOAL_REACHED)
        p = self.params
        if p.oscillation_timeout > 0.0 and now > self._last_oscillation_reset + p.oscillation_timeout:
            self._enter_clearing(OSCILLATION_R)
            return Outcome("stop")
        if command_valid:
            self._last_valid_control = now
            return Outcome("drive")
        if now > self._last_valid_control + p.controller_patience:
            self._enter_clearing(CONTROLLING_R)
        else:
            self.state = PLANNING
            self._last_valid_plan = now
            self._planning_retries = 0
        return Outcome("stop")

    def _watch_oscillation(self, now, position):
        position = np.asarray(position, dtype=float)
        if np.linalg.norm(position - self._oscillation_position) >= self.params.oscillation_distance:
            self._last_oscillation_reset = now
            self._oscillation_position = position
            if self.trigger == OSCILLATION_R:
                self.recovery_index = 0

    def _enter_clearing(self, trigger):
        self.state = CLEARING
        self.trigger = trigger

    # --- recovery -----------------------------------------------------------------------------------------
    def next_recovery(self):
        """In CLEARING: Outcome `recover` with the next recovery, or `aborted` when none is left."""
        if self.params.recovery_behavior_enabled and self.recovery_index < len(self.recoveries):
            return Outcome("recover", recovery=self.recoveries[self.recovery_index], index=self.recovery_index)
        return Outcome("aborted", ABORT_TEXTS[self.trigger], ABORT_LOGS[self.trigger])

    def end_recovery(self, now, position):
        """The recovery started by next_recovery has finished: plan again with fresh timers."""
        self.recovery_index += 1
        self._reset_timers(now, position)
        self.state = PLANNING
