"""The SLAM grid: gmapping's geometry and growth, beam counts, log-odds and the published -1/0/100 values."""
import numpy as np
import pytest

from lab_nav.slam.grid import (
    LOG_ODDS_HIT,
    LOG_ODDS_LIMITS,
    LOG_ODDS_MISS,
    PATCH_CELLS,
    SlamGrid,
    grown_geometry,
    initial_geometry,
)

TB3 = initial_geometry(-10.0, -10.0, 10.0, 10.0, 0.05)


def test_tb3_extent_gives_gmappings_384_cells_at_minus_10():
    assert (TB3.width, TB3.height, TB3.origin_x, TB3.origin_y) == (384, 384, -10.0, -10.0)
    default = initial_geometry(-100.0, -100.0, 100.0, 100.0, 0.05)
    assert (default.width, default.origin_x) == (4000, -100.0)


def test_points_inside_do_not_grow_the_map():
    geometry, shift = grown_geometry(TB3, [-9.9, 9.1], [0.0, 9.19])
    assert geometry is TB3 and shift == (0, 0)


def test_a_point_beyond_the_right_edge_grows_that_side_by_whole_patches_to_10_m_beyond_it():
    geometry, shift = grown_geometry(TB3, [9.5], [0.0])
    # end 9.2 must reach 19.5: 10.3 m = 6.44 patches of 1.6 m -> 7 patches
    assert geometry.width == 384 + 7 * PATCH_CELLS and geometry.height == 384
    assert (geometry.origin_x, geometry.origin_y) == (-10.0, -10.0) and shift == (0, 0)


def test_a_point_below_the_origin_moves_the_origin_by_whole_patches():
    geometry, shift = grown_geometry(TB3, [0.0], [-10.5])
    # origin -10 must reach -20.5: 10.5 m = 6.56 patches -> 7 patches, origin -21.2
    assert geometry.origin_y == pytest.approx(-21.2) and geometry.height == 384 + 7 * PATCH_CELLS
    assert shift == (0, 7 * PATCH_CELLS)


def test_growing_keeps_every_cell_where_it_was_in_the_world():
    grid = SlamGrid(TB3)
    grid.integrate((0.0, 0.0), [[1.0, 0.0]], [True])
    before = grid.occupancy(0.25)
    grid.integrate((0.0, 0.0), [[0.0, -10.5]], [True])
    after = grid.occupancy(0.25)
    col, row = grid.geometry.world_to_cell(1.02, 0.02)
    assert after[row, col] == 100 and (after == 100).sum() == (before == 100).sum() + 1


def test_a_hit_beam_marks_its_end_occupied_and_the_cells_before_it_free():
    grid = SlamGrid(TB3)
    grid.integrate((0.0, 0.0), [[1.0, 0.0]], [True])
    values = grid.occupancy(0.25)
    col, row = TB3.world_to_cell(1.0, 0.0)
    assert values[row, col] == 100
    assert (values[row, TB3.world_to_cell(0.0, 0)[0]:col] == 0).all()
    assert (values == 100).sum() == 1 and (values == 0).sum() == col - TB3.world_to_cell(0.0, 0)[0]
    assert grid.log_odds[row, col] == pytest.approx(LOG_ODDS_HIT)
    assert grid.log_odds[row, col - 5] == pytest.approx(LOG_ODDS_MISS)


def test_a_beam_cut_at_max_urange_marks_free_space_only():
    grid = SlamGrid(TB3)
    grid.integrate((0.0, 0.0), [[3.0, 0.0]], [False])
    values = grid.occupancy(0.25)
    assert (values == 100).sum() == 0 and (values == 0).sum() == 61


def test_log_odds_add_up_per_beam_and_stay_within_limits():
    grid = SlamGrid(TB3)
    col, row = TB3.world_to_cell(1.0, 0.0)
    for _ in range(2):
        grid.integrate((0.0, 0.0), [[1.0, 0.0]], [True])
    assert grid.log_odds[row, col] == pytest.approx(2 * LOG_ODDS_HIT)
    for _ in range(30):
        grid.integrate((0.0, 0.0), [[2.0, 0.0]], [True])
    assert grid.log_odds[row, col] == pytest.approx(LOG_ODDS_LIMITS[0])
    assert not grid.occupied()[row, col]


def test_published_value_is_100_only_above_the_hit_fraction_threshold():
    grid = SlamGrid(TB3)
    col, row = TB3.world_to_cell(1.0, 0.0)
    grid.integrate((0.0, 0.0), [[1.0, 0.0]], [True])
    for _ in range(3):
        grid.integrate((0.0, 0.0), [[2.0, 0.0]], [True])
    assert (grid.hits[row, col], grid.visits[row, col]) == (1, 4)
    assert grid.occupancy(0.25)[row, col] == 0      # 1/4 is not > 0.25
    assert grid.occupancy(0.2)[row, col] == 100
    assert grid.occupancy(0.25)[0, 0] == -1


def test_many_beams_through_one_cell_count_one_visit_each():
    grid = SlamGrid(TB3)
    ends = [[2.0, 0.05 + dy] for dy in np.linspace(-0.01, 0.01, 5)]
    grid.integrate((0.0, 0.025), ends, [True] * 5)
    col, row = TB3.world_to_cell(1.0, 0.035)
    assert grid.visits[row, col] == 5
