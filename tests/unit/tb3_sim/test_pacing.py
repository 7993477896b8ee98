"""Pacer: wall-clock waits that hold a real-time factor without bursts."""
import pytest

from tb3_sim.core.pacing import Pacer


def test_factor_one_waits_until_wall_time_catches_up():
    pacer = Pacer(1.0)
    pacer.restart(0.0, 100.0)
    assert pacer.delay(0.010, 100.002) == pytest.approx(0.008)


def test_factor_five_runs_five_sim_seconds_per_wall_second():
    pacer = Pacer(5.0, max_sleep_s=1.0)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(1.0, 0.05) == pytest.approx(0.15)


def test_zero_factor_never_waits():
    pacer = Pacer(0.0)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(1000.0, 0.0) == 0.0


def test_short_waits_are_skipped_and_carried_over():
    pacer = Pacer(1.0, min_sleep_s=0.001)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(0.0005, 0.0) == 0.0
    assert pacer.delay(0.0105, 0.0) == pytest.approx(0.0105)


def test_late_loop_reanchors_instead_of_bursting():
    pacer = Pacer(1.0, max_lag_s=0.05)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(0.005, 1.0) == 0.0
    assert pacer.delay(0.010, 1.0) == pytest.approx(0.005)


def test_small_lag_is_absorbed():
    pacer = Pacer(1.0, max_lag_s=0.05)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(0.005, 0.03) == 0.0
    assert pacer.delay(0.040, 0.03) == pytest.approx(0.010)


def test_sim_time_going_back_reanchors():
    pacer = Pacer(1.0)
    pacer.restart(10.0, 0.0)
    assert pacer.delay(0.005, 0.0) == 0.0
    assert pacer.delay(0.010, 0.0) == pytest.approx(0.005)


@pytest.mark.parametrize("factor", [-1.0, float("nan")])
def test_bad_factor_is_refused(factor):
    with pytest.raises(ValueError, match="real_time_factor"):
        Pacer(factor)


def test_a_long_wait_is_given_in_short_sleeps_until_it_is_over():
    """A slow pacing never sleeps longer than max_sleep_s at once, so the loop re-checks for Ctrl-C meanwhile."""
    pacer = Pacer(0.01, max_sleep_s=0.1)
    pacer.restart(0.0, 0.0)
    assert pacer.delay(0.01, 0.0) == pytest.approx(0.1)
    assert pacer.delay(0.01, 0.95) == pytest.approx(0.05)
    assert pacer.delay(0.01, 1.0) == 0.0
