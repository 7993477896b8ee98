"""The approach controller, driven by a scripted robot: a point that ramps its speed at 1 m/s^2 toward the
command (like the simulated Waffle), a wall at a known distance, sweeps at 5 Hz and odometry at 30 Hz, each
stamped with its measurement time."""
import pytest

from week4_services.approach import SAFETY_TRAVEL_M, TIME_LIMIT_S, ApproachController, Outcome
from week4_services.requests import approach

ODOM_DT = 1.0 / 30
SWEEP_EVERY = 6   # 5 Hz


def run(wall_distance, distance, velocity, sweep_delay_steps=0, max_steps=10000):
    """Simulate an approach; returns (outcome, final distance to the wall, steps). Each sweep reaches the
    controller `sweep_delay_steps` odometry updates after it was measured, as when its callback runs late."""
    controller = ApproachController(approach(distance, velocity))
    travelled = speed = 0.0
    measured = {}
    for step in range(max_steps):
        stamp = step * ODOM_DT
        if step % SWEEP_EVERY == 0:
            measured[step] = (wall_distance - travelled if wall_distance != float("inf") else None, stamp)
        controller.on_odometry(travelled, speed, stamp)
        if step - sweep_delay_steps in measured:
            controller.on_sweep(*measured.pop(step - sweep_delay_steps))
        command, outcome = controller.step()
        delta = max(-ODOM_DT, min(ODOM_DT, command - speed))
        speed += delta
        travelled += speed * ODOM_DT
        if outcome is not Outcome.DRIVING and speed == 0.0:
            return outcome, wall_distance - travelled, step
    raise AssertionError("approach never ended")


@pytest.mark.parametrize("velocity, tolerance", [(0.1, 0.01), (0.26, 0.02)])
def test_stops_at_the_requested_distance(velocity, tolerance):
    outcome, final, _ = run(1.5, 0.4, velocity)
    assert outcome is Outcome.ARRIVED
    assert final == pytest.approx(0.4, abs=tolerance)


@pytest.mark.parametrize("velocity", [0.1, 0.26])
def test_a_sweep_handled_late_still_stops_at_the_requested_distance(velocity):
    """Three odometry updates (0.1 s) between a sweep's measurement and its handling: dead reckoning goes by the
    sweep's stamp, so the stop is where an on-time sweep puts it."""
    _, on_time, _ = run(1.5, 0.4, velocity)
    outcome, late, _ = run(1.5, 0.4, velocity, sweep_delay_steps=3)
    assert outcome is Outcome.ARRIVED
    assert late == pytest.approx(on_time, abs=0.002)


def test_already_closer_than_requested_does_not_move():
    outcome, final, _ = run(0.3, 0.5, 0.1)
    assert outcome is Outcome.ALREADY_THERE
    assert final == pytest.approx(0.3)


def test_nothing_ahead_stops_at_the_safety_limit():
    controller = ApproachController(approach(0.4, 0.2))
    controller.on_sweep(None, 0.0)
    travelled, speed = 0.0, 0.0
    while True:
        controller.on_odometry(travelled, speed, 0.0)
        command, outcome = controller.step()
        speed += max(-ODOM_DT, min(ODOM_DT, command - speed))
        travelled += speed * ODOM_DT
        if outcome is Outcome.NOTHING_AHEAD and speed == 0.0:
            break
    assert SAFETY_TRAVEL_M - 0.05 <= travelled <= SAFETY_TRAVEL_M + 0.01


def test_no_motion_before_the_first_sweep():
    controller = ApproachController(approach(0.4, 0.1))
    controller.on_odometry(0.0, 0.0, 0.0)
    assert controller.step().velocity == 0.0


def test_a_valid_crawl_ends_at_the_time_limit():
    controller = ApproachController(approach(0.4, 1e-6))
    controller.on_sweep(1.3, 0.0)
    controller.on_odometry(0.0, 1e-6, TIME_LIMIT_S - 0.1)
    controller.on_clock(TIME_LIMIT_S - 0.1)
    assert controller.step() == (1e-6, Outcome.DRIVING)
    controller.on_clock(TIME_LIMIT_S)
    assert controller.step() == (0.0, Outcome.TIME_LIMIT)
    controller.on_sweep(1.3, TIME_LIMIT_S)
    assert controller.step().outcome is Outcome.TIME_LIMIT
