"""move_base's state machine with time injected: planning, controlling, recoveries, the abort texts."""
import numpy as np
import pytest

from lab_nav.planning.goal import (
    INVALID_QUATERNION_ABORT,
    NAN_QUATERNION,
    TILTED_QUATERNION,
    ZERO_QUATERNION,
    quaternion_problem,
)
from lab_nav.planning.move_base_logic import CLEARING, CONTROLLING, PLANNING, MoveBaseLogic, MoveBaseParams
from lab_nav.planning.recovery import RotateRecovery, default_recoveries


def test_goal_quaternions_are_checked_with_the_original_texts():
    assert quaternion_problem(0, 0, 0, 1) is None
    assert quaternion_problem(0, 0, np.sin(1), np.cos(1)) is None
    assert quaternion_problem(0, 0, 0, 2) is None   # any length: move_base normalises
    assert quaternion_problem(0, 0, 0, 0) == ZERO_QUATERNION
    assert quaternion_problem(0, 0, float("nan"), 1) == NAN_QUATERNION
    assert quaternion_problem(0.5, 0, 0, 0.86) == TILTED_QUATERNION
    assert INVALID_QUATERNION_ABORT == "Aborting on goal because it was sent with an invalid quaternion"


def _run_until_abort(logic, plan_found, command_valid, position=lambda t: (0.0, 0.0)):
    """Drive the machine at 10 Hz; recoveries take 2 s each. Returns (time, outcome, recoveries run)."""
    logic.start(0.0, position(0.0))
    t, ran = 0.0, []
    while t < 200.0:
        t = round(t + 0.1, 3)
        if logic.state == CLEARING:
            outcome = logic.next_recovery()
            if outcome.kind == "aborted":
                return t, outcome, ran
            ran.append(outcome.recovery.name)
            t += 2.0
            logic.end_recovery(t, position(t))
            continue
        if logic.planner_due(t):
            logic.on_plan(t, plan_found)
        if logic.state == CONTROLLING:
            outcome = logic.on_control(t, position(t), command_valid=command_valid)
    raise AssertionError("never aborted")


def test_no_plan_aborts_after_the_patience_and_every_recovery():
    t, outcome, ran = _run_until_abort(MoveBaseLogic(), plan_found=False, command_valid=True)
    assert outcome.text == "Failed to find a valid plan. Even after executing recovery behaviors."
    assert outcome.log.startswith("Aborting because a valid plan could not be found")
    assert ran == ["conservative_reset", "rotate_recovery", "aggressive_reset", "rotate_recovery"]
    assert 5 * 5.0 + 4 * 2.0 <= t <= 5 * 5.2 + 4 * 2.0 + 1.0


def test_no_valid_control_aborts_after_the_controller_patience():
    logic = MoveBaseLogic(MoveBaseParams(oscillation_timeout=0.0))
    t, outcome, ran = _run_until_abort(logic, plan_found=True, command_valid=False)
    assert outcome.text == "Failed to find a valid control. Even after executing recovery behaviors."
    assert len(ran) == 4 and t >= 15.0


def test_a_robot_that_does_not_get_anywhere_is_oscillating():
    t, outcome, _ = _run_until_abort(MoveBaseLogic(), plan_found=True, command_valid=True)
    assert outcome.text == "Robot is oscillating. Even after executing recovery behaviors."
    assert t >= 5 * 10.0


def test_progress_keeps_the_goal_alive_and_reaching_it_succeeds():
    logic = MoveBaseLogic()
    logic.start(0.0, (0.0, 0.0))
    logic.on_plan(0.0, True)
    for step in range(1, 300):
        outcome = logic.on_control(step * 0.1, (step * 0.02, 0.0))
        assert outcome.kind == "drive" and logic.state == CONTROLLING
    assert logic.on_control(30.0, (6.0, 0.0), reached=True).text == "Goal reached."


def test_a_failed_control_cycle_goes_back_to_planning_first():
    logic = MoveBaseLogic()
    logic.start(0.0, (0.0, 0.0))
    logic.on_plan(0.0, True)
    assert logic.on_control(0.1, (0.0, 0.0), command_valid=False).kind == "stop"
    assert logic.state == PLANNING


def test_recoveries_can_be_disabled_and_rotations_left_out():
    logic = MoveBaseLogic(MoveBaseParams(recovery_behavior_enabled=False))
    _, outcome, ran = _run_until_abort(logic, plan_found=False, command_valid=True)
    assert ran == [] and outcome.kind == "aborted"
    assert [r.name for r in default_recoveries(clearing_rotation_allowed=False)] == ["conservative_reset",
                                                                                     "aggressive_reset"]
    assert default_recoveries()[2].clear_message() == \
        "Clearing both costmaps outside a square (1.84m) large centered on the robot."


def test_the_planner_runs_at_its_frequency():
    logic = MoveBaseLogic()
    assert not logic.planner_due(0.0)
    logic.start(0.0, (0, 0))
    assert logic.planner_due(0.0)
    logic.on_plan(0.0, True)
    assert not logic.planner_due(0.1) and logic.planner_due(0.2)


def test_rotate_recovery_turns_a_full_circle_counter_clockwise():
    rotate = RotateRecovery(start_yaw=1.0)
    yaw, turned, dt = 1.0, 0.0, 0.05
    while (w := rotate.command(yaw)) is not None:
        assert 0.4 <= w <= 1.0
        yaw += w * dt
        turned += w * dt
        assert turned < 7.0
    assert turned == pytest.approx(2 * np.pi, abs=0.1)
