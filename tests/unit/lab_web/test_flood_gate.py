"""The server's flood limit: bursts of 100 frames, then 50 per second, and one warning per second at most."""
from lab_web.server import FLOOD_BURST, FLOOD_RATE_PER_S, FloodGate


def test_a_burst_passes_then_the_rate_limit_holds():
    gate = FloodGate(now_s=0.0)
    assert all(gate.allow(0.0) for _ in range(FLOOD_BURST))
    assert not gate.allow(0.0)
    assert sum(gate.allow(1.0) for _ in range(200)) == FLOOD_RATE_PER_S   # refilled for one second


def test_warnings_come_once_per_second():
    gate = FloodGate(now_s=0.0)
    assert [gate.should_warn(t) for t in (0.0, 0.5, 0.99, 1.0, 1.5, 2.1)] == [True, False, False, True, False, True]
