"""Topic rates as `rostopic hz` gives them: over the last two seconds, None when nothing arrived lately."""
import pytest

from lab_web.rates import TopicRates


def test_rate_over_the_window():
    rates = TopicRates()
    for i in range(101):
        rates.count("/odom", 10.0 + i / 30.0)      # 30 Hz for 3.3 s
    assert rates.rate_hz("/odom", 10.0 + 100 / 30.0) == pytest.approx(30.0, abs=0.1)


def test_no_rate_without_recent_messages():
    rates = TopicRates()
    assert rates.rate_hz("/scan", 5.0) is None
    rates.count("/scan", 1.0)
    rates.count("/scan", 1.2)
    assert rates.rate_hz("/scan", 1.2) == 5.0
    assert rates.rate_hz("/scan", 4.0) is None
    rates.forget("/scan")
    assert rates.rate_hz("/scan", 1.2) is None
