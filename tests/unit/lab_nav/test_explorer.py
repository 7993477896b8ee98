"""explore_lite's planning steps (goal choice, progress timeout, blacklist, stop) and its partial map updates."""
import numpy as np

from lab_nav.exploration.costmap_codes import apply_update
from lab_nav.exploration.explorer import KEEP, SEND, STOP, Explorer
from lab_nav.exploration.frontier_search import Frontier


def frontier(x, min_distance, cost):
    return Frontier(initial=(x, 0.0), size=10, min_distance=min_distance, centroid=(x, 0.0), cost=cost)


NEAR, FAR = frontier(1.0, 1.0, 0.5), frontier(4.0, 4.0, 2.0)


def test_the_cheapest_frontier_is_sent_once_and_then_kept():
    explorer = Explorer(progress_timeout_s=30.0)
    step = explorer.step([NEAR, FAR], 0.05, now_s=10.0)
    assert (step.action, step.target, step.frontier) == (SEND, (1.0, 0.0), NEAR)
    assert explorer.step([NEAR, FAR], 0.05, now_s=13.0).action == KEEP


def test_no_progress_for_the_timeout_blacklists_the_target_and_moves_on():
    explorer = Explorer(progress_timeout_s=30.0)
    explorer.step([NEAR, FAR], 0.05, now_s=10.0)
    assert explorer.step([NEAR, FAR], 0.05, now_s=40.0).action == KEEP        # exactly 30 s: not yet
    step = explorer.step([NEAR, FAR], 0.05, now_s=40.5)
    assert (step.action, step.target, step.blacklisted) == (SEND, (4.0, 0.0), ((1.0, 0.0),))
    assert explorer.blacklist == [(1.0, 0.0)]


def test_a_frontier_that_comes_nearer_counts_as_progress():
    explorer = Explorer(progress_timeout_s=30.0)
    explorer.step([NEAR], 0.05, now_s=0.0)
    closer = frontier(1.0, 0.5, 0.2)
    assert explorer.step([closer], 0.05, now_s=25.0).action == KEEP
    assert explorer.step([closer], 0.05, now_s=50.0).action == KEEP          # 25 s since the progress
    assert explorer.step([closer], 0.05, now_s=55.5).action == STOP          # 30.5 s: blacklisted, none left


def test_an_aborted_goal_is_blacklisted_and_no_frontier_left_stops():
    explorer = Explorer(progress_timeout_s=30.0)
    explorer.step([NEAR, FAR], 0.05, now_s=0.0)
    assert explorer.goal_ended((1.0, 0.0), aborted=True)
    assert explorer.step([NEAR, FAR], 0.05, now_s=1.0).target == (4.0, 0.0)
    assert not explorer.goal_ended((4.0, 0.0), aborted=False)
    assert explorer.step([], 0.05, now_s=2.0).action == STOP
    explorer.goal_ended((4.0, 0.0), aborted=True)
    assert explorer.step([NEAR, FAR], 0.05, now_s=3.0).action == STOP


def test_a_partial_update_is_written_in_place_and_clipped_like_the_original():
    codes = np.zeros((3, 4), np.uint8)
    assert apply_update(codes, 1, 1, 2, 2, [100, -1, 0, 99]) is None
    assert codes.tolist() == [[0, 0, 0, 0], [0, 254, 255, 0], [0, 0, 253, 0]]
    warning = apply_update(codes, 3, 2, 2, 2, [100, 100, 100, 100])
    assert warning.startswith("received update doesn't fully fit into existing map")
    assert codes[2, 3] == 254
    assert apply_update(codes, -1, 0, 1, 1, [0]) == "negative coordinates, invalid update. x: -1, y: 0"
    assert apply_update(codes, 0, 0, 2, 2, [0]) == "invalid update: 2 x 2 cells but 1 values"
