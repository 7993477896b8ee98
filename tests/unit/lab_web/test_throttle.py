"""lab_web.panels.nav.Throttle: the costmaps' and the navigation frame's rate limit never loses the last change."""
from lab_web.panels import nav
from lab_web.panels.nav import Throttle


def test_a_change_within_the_period_waits_pending_and_goes_out_after_it(monkeypatch):
    clock = [100.0]
    monkeypatch.setattr(nav, "now_s", lambda: clock[0])
    throttle = Throttle(0.2)
    assert throttle.ready() and not throttle.pending
    clock[0] += 0.05
    assert not throttle.ready() and throttle.pending
    assert throttle.ready(force=True) and not throttle.pending   # a whole new costmap goes out at once
    clock[0] += 0.1
    assert not throttle.ready() and throttle.pending
    clock[0] += 0.15
    assert throttle.ready() and not throttle.pending
