"""slam_gmapping's map -> odom ticks: one per period of sim time, on the period's multiples, the ticks a late
wake-up slept past included, afresh after a long stall or the clock jumping back."""
import pytest

from gmapping.transform_ticks import MAX_CATCH_UP_S, TransformTicks

PERIOD_S = 0.05


def test_waking_on_each_tick_hands_out_that_tick_once():
    ticks = TransformTicks(PERIOD_S)
    assert ticks.due(10.0) == [pytest.approx(10.0)]
    assert ticks.due(10.0) == []
    assert ticks.due(10.04) == []
    assert ticks.due(10.05) == [pytest.approx(10.05)]
    assert ticks.next_s(10.05) == pytest.approx(10.1)


def test_a_clock_reading_a_float_hair_below_a_tick_is_on_it():
    ticks = TransformTicks(PERIOD_S)
    ticks.due(0.1)
    assert ticks.due(0.1 + 0.05) == [pytest.approx(0.15)]   # 0.15000000000000002 / 0.05 = 3.0000000000000004
    assert ticks.due(0.3 - 1e-12) == [pytest.approx(0.2), pytest.approx(0.25), pytest.approx(0.3)]


def test_a_late_wake_up_sends_every_tick_it_slept_past_so_a_second_has_twenty():
    ticks = TransformTicks(PERIOD_S)
    handed_out = ticks.due(5.0)
    for now in (5.01, 5.23, 5.24, 5.61, 5.72, 6.0):
        handed_out += ticks.due(now)
    assert handed_out == pytest.approx([5.0 + PERIOD_S * k for k in range(21)])


def test_a_stall_longer_than_the_catch_up_or_a_clock_jumping_back_starts_afresh_from_now():
    ticks = TransformTicks(PERIOD_S)
    ticks.due(5.0)
    assert ticks.due(5.0 + MAX_CATCH_UP_S + 0.2) == [pytest.approx(6.2)]
    assert ticks.due(0.42) == [pytest.approx(0.4)]
    assert ticks.due(0.5) == [pytest.approx(0.45), pytest.approx(0.5)]


def test_the_period_must_be_positive():
    with pytest.raises(ValueError, match="period_s must be > 0"):
        TransformTicks(0.0)
