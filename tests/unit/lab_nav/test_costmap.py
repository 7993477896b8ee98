"""Costmap layers: cell values, inflation against its formula, marking and clearing by ray tracing."""
import numpy as np
import pytest

from lab_nav.costmap.footprint import BURGER_FOOTPRINT, WAFFLE_FOOTPRINT, Footprint, FootprintError
from lab_nav.costmap.inflation import Inflation
from lab_nav.costmap.layered import CostmapParams, LayeredCostmap, changed_box
from lab_nav.costmap.raytrace import cells_along
from lab_nav.costmap.values import INSCRIBED, LETHAL, NO_INFORMATION, from_map, to_occupancy
from lab_nav.maps.geometry import MapGeometry

WAFFLE = Footprint.padded(WAFFLE_FOOTPRINT)
PARAMS = CostmapParams(WAFFLE)


def test_padded_footprints_give_turtlebot3s_radii():
    assert WAFFLE.inscribed_radius == pytest.approx(0.087)
    assert WAFFLE.circumscribed_radius == pytest.approx(0.271, abs=5e-4)
    burger = Footprint.padded(BURGER_FOOTPRINT)
    assert (burger.inscribed_radius, burger.circumscribed_radius) == pytest.approx((0.051, 0.163), abs=5e-4)


def test_a_footprint_needs_three_points():
    with pytest.raises(FootprintError, match="at least three"):
        Footprint.padded([[0, 0], [1, 1]])


def test_published_values_translate_as_costmap_2d_does():
    assert list(to_occupancy([0, 1, 252, 253, 254, 255])) == [0, 1, 98, 99, 100, -1]
    assert list(from_map([-1, 0, 50, 99, 100])) == [NO_INFORMATION, 0, 0, 0, LETHAL]


@pytest.mark.parametrize("cells", [2, 3, 5, 10, 20])
def test_inflation_follows_the_formula(cells):
    lethal = np.zeros((50, 50), bool)
    lethal[25, 5] = True
    costs = Inflation(0.087).costs(lethal, 0.05)
    d = cells * 0.05
    assert costs[25, 5 + cells] == int(np.floor(252 * np.exp(-3.0 * (d - 0.087))))
    assert costs[25, 5] == LETHAL and costs[25, 6] == INSCRIBED
    assert costs[25, 5 + 21] == 0   # beyond inflation_radius 1.0 m


def _world_map():
    """A 4 x 4 m map at 0.05 m with a wall at x = 1 m, unknown beyond x = 1.5 m."""
    geometry = MapGeometry(0.05, 80, 80, -2.0, -2.0)
    data = np.zeros((80, 80), np.int8)
    data[:, 60] = 100
    data[:, 70:] = -1
    return geometry, data


def test_the_global_costmap_has_no_unknown_cells_and_inflates_walls():
    costmap = LayeredCostmap(*_world_map()[:1], PARAMS)
    costmap.set_map(*_world_map())
    costs = costmap.update()
    assert not np.any(costs == NO_INFORMATION)
    assert costs[40, 60] == LETHAL and costs[40, 59] == INSCRIBED and 0 < costs[40, 55] < INSCRIBED


def test_a_scan_marks_hits_and_clears_along_its_rays():
    geometry, data = _world_map()
    costmap = LayeredCostmap(geometry, PARAMS)
    costmap.set_map(geometry, data)
    costmap.add_scan((0.0, 0.0), [(0.5, 0.0)], [True])
    assert costmap.update()[40, 50] == LETHAL
    costmap.add_scan((0.0, 0.0), [(0.81, 0.0)], [True])   # the box moved away: its cell is cleared
    costs = costmap.update()
    assert costs[40, 50] < INSCRIBED and costs[40, 56] == LETHAL
    costmap.add_scan((0.0, 0.0), [(0.0, 1.2)], [False])  # a max-range reading clears but does not mark
    assert costmap.update()[64, 40] != LETHAL


def test_hits_beyond_obstacle_range_do_not_mark():
    geometry = MapGeometry(0.05, 200, 200, -5.0, -5.0)
    costmap = LayeredCostmap(geometry, PARAMS, static=False)
    costmap.add_scan((0.0, 0.0), [(3.2, 0.0), (2.9, 0.0)], [True, True])
    costs = costmap.update()
    assert costs[100, 164] != LETHAL and costs[100, 158] == LETHAL


def test_a_rolling_window_keeps_marks_in_place_in_the_world():
    costmap = LayeredCostmap(MapGeometry(0.05, 60, 60, -1.5, -1.5), PARAMS, static=False)
    costmap.add_scan((0.0, 0.0), [(1.0, 0.0)], [True])
    costmap.update()
    assert costmap.cost_at(1.0, 0.0) == LETHAL
    costmap.move_to(0.5, 0.0)
    costmap.update()
    assert costmap.geometry.origin_x == pytest.approx(-1.0)
    assert costmap.cost_at(1.0, 0.0) == LETHAL


def test_reset_and_footprint_clearing_erase_marks_but_not_the_map():
    geometry, data = _world_map()
    costmap = LayeredCostmap(geometry, PARAMS)
    costmap.set_map(geometry, data)
    costmap.add_scan((0.0, 0.0), [(0.5, 0.0), (-0.5, 0.0)], [True, True])
    costmap.clear_footprint(0.5, 0.0, 0.0)
    assert costmap.update()[40, 50] != LETHAL and costmap.costs[40, 30] == LETHAL
    costmap.clear_outside(0.0, 0.0, 3.0, ["obstacles"])   # turtlebot3's layer is obstacle_layer: nothing
    assert costmap.update()[40, 30] == LETHAL
    costmap.reset()
    assert costmap.update()[40, 30] != LETHAL and costmap.costs[40, 60] == LETHAL


def test_footprint_clearing_frees_the_cells_its_outline_crosses():
    """A laser mark on a cell the footprint's outline crosses (its centre just outside the polygon), as on a robot
    touching a pillar, is freed: the outline a local planner checks at the robot's own pose then meets no mark."""
    geometry = MapGeometry(0.05, 80, 80, -2.0, -2.0)
    costmap = LayeredCostmap(geometry, PARAMS, static=False)
    side = PARAMS.footprint.array[:, 1].max()   # the left edge, 0.165 m
    mark = (0.0, side + 0.005)                   # in the cell the edge crosses, whose centre lies outside
    col, row = (int(v) for v in geometry.world_to_cell(*mark))
    assert geometry.cell_center(col, row)[1] - geometry.resolution / 2 < side < geometry.cell_center(col, row)[1]
    costmap.add_scan((0.0, 0.0), [mark], [True], clear=False)
    assert costmap.update()[row, col] == LETHAL
    costmap.clear_footprint(0.0, 0.0, 0.0)
    costs = costmap.update()
    assert costs[row, col] != LETHAL
    outline = PARAMS.footprint.outline(0.01)
    cols, rows = geometry.world_to_cell(outline[:, 0], outline[:, 1])
    assert costs[rows, cols].max() < LETHAL


def test_changed_box_bounds_the_differences():
    a = np.zeros((10, 10), np.uint8)
    b = a.copy()
    assert changed_box(a, b) is None
    b[2, 3] = b[5, 7] = 9
    assert changed_box(a, b) == (3, 2, 5, 4)
    assert changed_box(None, b) == (0, 0, 10, 10)


@pytest.mark.parametrize("seed", range(4))
def test_updates_after_each_scan_give_the_grid_one_update_of_all_of_them_gives(seed):
    """The incremental update (only around the cells a scan changed) against the whole grid computed at once."""
    rng = np.random.default_rng(seed)
    geometry, data = _world_map()
    stepwise, at_once = LayeredCostmap(geometry, PARAMS), LayeredCostmap(geometry, PARAMS)
    stepwise.set_map(geometry, data)
    stepwise.update()
    at_once.set_map(geometry, data)
    for _ in range(12):
        origin = rng.uniform(-1.5, 0.5, 2)
        ends = origin + rng.uniform(-2.0, 2.0, (30, 2))
        hit = rng.random(30) < 0.6
        for costmap in (stepwise, at_once):
            costmap.add_scan(origin, ends, hit)
            costmap.clear_footprint(origin[0], origin[1], 0.3)
        before = stepwise.costs
        stepwise.update()
        assert before is stepwise.costs or not np.array_equal(before, stepwise.costs)
    np.testing.assert_array_equal(stepwise.costs, at_once.update())


def test_an_update_with_nothing_changed_keeps_the_grid_and_its_version():
    geometry, data = _world_map()
    costmap = LayeredCostmap(geometry, PARAMS)
    costmap.set_map(geometry, data)
    costs = costmap.update()
    version = costmap.version
    costmap.add_scan((0.0, 0.0), [(1.0, 0.0)], [True])   # the map's wall: marks what the static layer has
    assert costmap.update() is costs and costmap.version == version
    costmap.add_scan((0.0, 0.0), [(0.5, 0.0)], [True])
    assert costmap.update() is not costs and costmap.version == version + 1
    assert costs[40, 50] != LETHAL   # the array a reader held is never written


def test_rays_are_cut_to_the_grid_and_leave_no_gap():
    geometry = MapGeometry(0.05, 60, 60, -1.5, -1.5)
    rng = np.random.default_rng(3)
    for _ in range(50):
        origin, end = rng.uniform(-3.0, 3.0, 2), rng.uniform(-3.0, 3.0, 2)
        cols, rows = cells_along(geometry, origin, [end])
        t = np.linspace(0.0, 1.0, 20000)
        dense = set(zip(*geometry.world_to_cell(origin[0] + t * (end - origin)[0], origin[1] + t * (end - origin)[1])))
        dense = {(c, r) for c, r in dense if 0 <= c < 60 and 0 <= r < 60}
        assert set(zip(cols.tolist(), rows.tolist())) <= dense
        assert (len(cols) == 0) == (len(dense) == 0)
        if len(cols):
            assert np.all(np.abs(np.diff(cols)) <= 1) and np.all(np.abs(np.diff(rows)) <= 1)


def test_cost_at_reads_no_information_anywhere_off_the_grid():
    geometry, data = _world_map()
    costmap = LayeredCostmap(geometry, PARAMS)
    costmap.set_map(geometry, data)
    costmap.update()
    x = np.array([-2.0, -2.01, 1.99, 2.0, 0.0, 1e9, -1e9, 0.0])
    y = np.array([-2.0, 0.0, 1.99, 0.0, 1.0, 0.0, 0.0, -7.0])
    cols, rows = geometry.world_to_cell(x, y)
    inside = geometry.contains(cols, rows)
    expected = np.where(inside, costmap.costs[np.clip(rows, 0, 79), np.clip(cols, 0, 79)], NO_INFORMATION)
    np.testing.assert_array_equal(costmap.cost_at(x, y), expected)
    assert costmap.cost_at(1.0, 0.0) == LETHAL


def test_footprint_clearing_at_a_repeated_pose_frees_the_same_cells_as_a_fresh_costmap():
    """The cells of the last pose are reused (a standing robot): marks made again under it are freed again, and a
    new pose or a rolled grid gives the cells a costmap that never cleared before computes."""
    geometry = MapGeometry(0.05, 80, 80, -2.0, -2.0)
    rng = np.random.default_rng(7)
    marks = rng.uniform(-0.5, 0.5, (200, 2))

    def cleared(costmap, pose):
        costmap.add_scan((0.0, 0.0), marks, np.ones(len(marks), bool), clear=False)
        costmap.clear_footprint(*pose)
        return costmap.update().copy()

    reused = LayeredCostmap(geometry, PARAMS, static=False)
    for pose in ((0.1, 0.0, 0.3), (0.1, 0.0, 0.3), (0.12, -0.03, 0.9), (0.12, -0.03, 0.9)):
        np.testing.assert_array_equal(cleared(reused, pose), cleared(LayeredCostmap(geometry, PARAMS, static=False),
                                                                     pose))
    reused.move_to(0.37, 0.21)   # the rolling window's origin moves: same pose, other cells
    fresh = LayeredCostmap(geometry, PARAMS, static=False)
    fresh.move_to(0.37, 0.21)
    np.testing.assert_array_equal(cleared(reused, (0.12, -0.03, 0.9)), cleared(fresh, (0.12, -0.03, 0.9)))
