"""Teleop from a page: published at a fixed rate while the page keeps commanding, zero exactly once when the
commands stop (release, timeout, page gone, shutdown), and nothing at all while nobody drives."""
from lab_web.teleop import COMMAND_TIMEOUT_S, TeleopGate


def test_nothing_is_published_while_no_page_drives():
    assert TeleopGate().tick(0.0) == []


def test_a_held_command_repeats_until_it_times_out_then_zero_once():
    gate = TeleopGate()
    gate.command("page-1", "robot", 0.2, 0.5, now_s=10.0)
    assert gate.tick(10.1) == [("robot", 0.2, 0.5)]
    assert gate.tick(10.2) == [("robot", 0.2, 0.5)]
    assert gate.tick(10.0 + COMMAND_TIMEOUT_S) == [("robot", 0.0, 0.0)]
    assert gate.tick(11.0) == []


def test_a_release_is_one_zero():
    gate = TeleopGate()
    gate.command("page-1", "turtle1", 2.0, 0.0, now_s=1.0)
    gate.command("page-1", "turtle1", 0.0, 0.0, now_s=1.05)
    assert gate.tick(1.1) == [("turtle1", 0.0, 0.0)]
    assert gate.tick(1.2) == []


def test_a_page_that_goes_away_stops_only_what_it_drove():
    gate = TeleopGate()
    gate.command("page-1", "robot", 0.1, 0.0, now_s=1.0)
    gate.command("page-2", "turtle1", 1.0, 0.0, now_s=1.0)
    gate.disconnect("page-1", now_s=1.05)
    assert sorted(gate.tick(1.1)) == [("robot", 0.0, 0.0), ("turtle1", 1.0, 0.0)]


def test_shutdown_zeroes_every_target():
    gate = TeleopGate()
    gate.command("page-1", "robot", 0.1, 0.0, now_s=1.0)
    gate.command("page-2", "turtle1", 1.0, 0.0, now_s=1.0)
    gate.stop_all(now_s=1.01)
    assert sorted(gate.tick(1.02)) == [("robot", 0.0, 0.0), ("turtle1", 0.0, 0.0)]
