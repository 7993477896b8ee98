"""week6_vision.line_following: the proportional law's sign, size and clamp, and the follower's three states."""
import pytest

from week6_vision.line_following import LineFollowing, proportional_steering


def test_a_line_right_of_the_target_turns_right_in_proportion():
    assert proportional_steering(120.0, 80.0, 160, gain=1.5) == pytest.approx(-1.5 * 40 / 80)
    assert proportional_steering(40.0, 80.0, 160, gain=1.5) == pytest.approx(1.5 * 40 / 80)
    assert proportional_steering(80.0, 80.0, 160) == 0.0


def test_steering_is_clamped():
    assert proportional_steering(0.0, 80.0, 160, gain=5.0, max_angular=1.0) == 1.0
    assert proportional_steering(160.0, 80.0, 160, gain=5.0, max_angular=1.0) == -1.0


def test_the_gain_means_the_same_at_every_width():
    assert proportional_steering(1440.0, 960.0, 1920) == pytest.approx(proportional_steering(120.0, 80.0, 160))


def test_searches_before_the_line_is_seen_follows_it_then_drives_on_over_its_end_and_stops():
    follower = LineFollowing(linear=0.1, search_angular=0.3, coast_m=0.37)
    assert follower.command(None, 80.0, 160, 0.0) == (0.0, 0.3, "searching")
    following = follower.command(90.0, 80.0, 160, 1.0)
    assert following.status == "following" and following.linear == 0.1 and following.angular < 0
    assert follower.command(None, 80.0, 160, 2.0) == (0.1, 0.0, "finishing")
    assert follower.command(None, 80.0, 160, 5.6) == (0.1, 0.0, "finishing")
    assert follower.command(None, 80.0, 160, 5.8) == (0.0, 0.0, "end of the line")


def test_a_line_back_in_view_while_finishing_is_followed_again():
    follower = LineFollowing(linear=0.1, coast_m=0.37)
    follower.command(80.0, 80.0, 160, 0.0)
    assert follower.command(None, 80.0, 160, 1.0).status == "finishing"
    assert follower.command(80.0, 80.0, 160, 2.0).status == "following"
    assert follower.command(None, 80.0, 160, 3.0).status == "finishing"
    assert follower.command(None, 80.0, 160, 6.0).status == "finishing"   # the coast starts again from 3.0


def test_a_mark_across_the_line_is_crossed_straight():
    follower = LineFollowing(linear=0.1)
    assert follower.command(150.0, 80.0, 160, 0.0, span=0.9) == (0.1, 0.0, "crossing a mark")
    assert follower.command(150.0, 80.0, 160, 0.1, span=0.3).status == "following"
