"""The approach controller, driven by a scripted robot: a point that ramps its speed at 1 m/s^2 toward the
command (like the simulated Waffle), a wall at a known distance, sweeps at 5 Hz and odometry at 30 Hz."""
import pytest

from week4_services.approach import SAFETY_TRAVEL_M, TIME_LIMIT_S, ApproachController, Outcome
from week4_services.requests import approach

ODOM_DT = 1.0 / 30
SWEEP_EVERY = 6   # 5 Hz


def run(wall_distance, distance, velocity, max_steps=10000):
    """Simulate an approach; returns (outcome, final distance to the wall, steps)."""
    controller = ApproachController(approach(distance, velocity))
    travelled = speed = 0.0
    command = 0.0
    for step in range(max_steps):
        if step % SWEEP_EVERY == 0:
            seen = wall_distance - travelled
            controller.on_sweep(seen if wall_distance != float("inf") else None)
        command, outcome = controller.on_odometry(travelled, speed)
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


def test_already_closer_than_requested_does_not_move():
    outcome, final, _ = run(0.3, 0.5, 0.1)
    assert outcome is Outcome.ALREADY_THERE
    assert final == pytest.approx(0.3)


def test_nothing_ahead_stops_at_the_safety_limit():
    controller = ApproachController(approach(0.4, 0.2))
    controller.on_sweep(None)
    travelled, speed = 0.0, 0.0
    while True:
        command, outcome = controller.on_odometry(travelled, speed)
        speed += max(-ODOM_DT, min(ODOM_DT, command - speed))
        travelled += speed * ODOM_DT
        if outcome is Outcome.NOTHING_AHEAD and speed == 0.0:
            break
    assert SAFETY_TRAVEL_M - 0.05 <= travelled <= SAFETY_TRAVEL_M + 0.01


def test_no_motion_before_the_first_sweep():
    controller = ApproachController(approach(0.4, 0.1))
    assert controller.on_odometry(0.0, 0.0).velocity == 0.0


def test_a_valid_crawl_ends_at_the_time_limit():
    controller = ApproachController(approach(0.4, 1e-6))
    controller.on_sweep(1.3)
    controller.on_clock(TIME_LIMIT_S - 0.1)
    assert controller.on_odometry(0.0, 1e-6) == (1e-6, Outcome.DRIVING)
    controller.on_clock(TIME_LIMIT_S)
    assert controller.on_odometry(0.0, 1e-6) == (0.0, Outcome.TIME_LIMIT)
    controller.on_sweep(1.3)
    assert controller.on_odometry(0.0, 0.0).outcome is Outcome.TIME_LIMIT
