"""explore_lite's frontier search and goal choice on small hand-made maps."""
import numpy as np
import pytest

from lab_nav.exploration.blacklist import next_frontier, on_blacklist
from lab_nav.exploration.costmap_codes import costmap_codes
from lab_nav.exploration.frontier_search import NO_CLEAR_CELL, OUT_OF_BOUNDS, FrontierSearch
from lab_nav.maps.geometry import MapGeometry

F, U, W = 0, -1, 100   # free, unknown, wall as /map carries them


def search(rows_top_first, x, y, resolution=1.0, potential_scale=3.0, gain_scale=1.0, min_frontier_size=0.5):
    """Frontiers of a map drawn as text is read (top row first, as the map looks from above)."""
    occupancy = np.array(rows_top_first, dtype=np.int8)[::-1]
    geometry = MapGeometry(resolution=resolution, width=occupancy.shape[1], height=occupancy.shape[0],
                           origin_x=0.0, origin_y=0.0)
    return FrontierSearch(costmap_codes(occupancy), geometry, potential_scale, gain_scale,
                          min_frontier_size).search_from(x, y)


def test_map_values_become_costmap_codes():
    assert costmap_codes([-1, 0, 1, 50, 98, 99, 100]).tolist() == [255, 0, 1, 127, 252, 253, 254]


def test_a_frontier_is_the_unknown_cells_next_to_free_space_with_the_originals_centroid_and_cost():
    result = search([[F, F, F, U, U, U],
                     [F, F, F, U, U, U],
                     [F, F, F, U, U, U]], 0.5, 1.5)
    assert result.message is None
    (frontier,) = result.frontiers
    assert frontier.initial == (3.5, 1.5)               # the seed: first met by the breadth-first search
    assert frontier.points == [(3.5, 0.5), (3.5, 2.5)]  # row - 1 before row + 1; the seed is not among them
    assert frontier.size == 3
    assert frontier.centroid == pytest.approx((7.0 / 3, 1.0))   # sum of the points / size, as the original
    assert frontier.min_distance == pytest.approx(10 ** 0.5)
    assert frontier.middle == (3.5, 0.5)   # the first of the two nearest
    assert frontier.cost == pytest.approx(3.0 * 10 ** 0.5 - 3.0)


def test_frontier_cells_touching_diagonally_form_one_frontier():
    result = search([[U, U, F],
                     [U, F, F],
                     [F, F, F]], 0.5, 0.5)
    (frontier,) = result.frontiers
    assert frontier.size == 2
    assert {frontier.initial, *frontier.points} == {(0.5, 1.5), (1.5, 2.5)}


def test_frontiers_behind_a_wall_are_not_reached():
    result = search([[F, F, W, F, U],
                     [F, F, W, F, U]], 0.5, 0.5)
    assert result.frontiers == []


def test_small_frontiers_are_dropped_and_the_rest_come_cheapest_first():
    corridor = [[U, F, F, F, F, F, F, U],
                [U, F, F, F, F, F, F, U],
                [W, F, F, F, F, F, F, U]]
    near, far = search(corridor, 1.5, 1.5).frontiers
    assert (near.initial[0], near.size, far.initial[0], far.size) == (0.5, 2, 7.5, 3)
    assert near.cost < far.cost
    bigger_first = search(corridor, 1.5, 1.5, potential_scale=0.001, gain_scale=1.0).frontiers
    assert [frontier.size for frontier in bigger_first] == [3, 2]
    assert [frontier.size for frontier in search(corridor, 1.5, 1.5, min_frontier_size=2.5).frontiers] == [3]
    assert search(corridor, 0.75, 0.75, resolution=0.5, min_frontier_size=1.25).frontiers[0].size == 3


def test_the_search_starts_from_the_nearest_free_cell_when_the_robot_stands_on_a_wall():
    result = search([[W, F, U]], 0.5, 0.5)
    assert result.message is None
    assert [frontier.initial for frontier in result.frontiers] == [(2.5, 0.5)]


def test_a_robot_outside_the_map_or_a_map_without_free_space_gives_no_frontier_and_the_originals_message():
    assert search([[F, U]], 5.0, 0.5).message == OUT_OF_BOUNDS
    assert search([[F, U]], -0.1, 0.5).message == OUT_OF_BOUNDS
    no_free = search([[U, U], [W, U]], 0.5, 0.5)
    assert (no_free.frontiers, no_free.message) == ([], NO_CLEAR_CELL)


def test_goals_within_5_cells_of_a_blacklisted_point_are_skipped():
    assert on_blacklist((1.0, 1.0), [(1.24, 0.76)], 0.05)
    assert not on_blacklist((1.0, 1.0), [(1.25, 1.0)], 0.05)
    result = search([[U, F, F, F, F, F, F, U],
                     [U, F, F, F, F, F, F, U]], 1.5, 0.5)
    near, far = result.frontiers
    assert next_frontier(result.frontiers, [], 1.0) is near
    assert near.centroid == (0.25, 0.75) and far.centroid == (3.75, 0.75)   # the seed is left out of the sum
    assert next_frontier(result.frontiers, [near.centroid], 0.5) is far    # 5 cells = 2.5 m
    assert next_frontier(result.frontiers, [(0.0, 0.0), (20.0, 0.0)], 1.0) is None
    assert next_frontier(result.frontiers, [(0.0, 0.0)], 0.05) is near
