"""MapGeometry: cells and world coordinates as nav_msgs/MapMetaData lays them out."""
import pytest

from lab_nav.maps.geometry import MapGeometry

TB3_MAP = MapGeometry(resolution=0.05, width=384, height=384, origin_x=-10.0, origin_y=-10.0)


def test_the_origin_corner_is_cell_zero_and_the_far_edge_is_outside():
    assert tuple(map(int, TB3_MAP.world_to_cell(-10.0, -10.0))) == (0, 0)
    assert tuple(map(int, TB3_MAP.world_to_cell(9.199, 9.199))) == (383, 383)
    assert not TB3_MAP.contains(*TB3_MAP.world_to_cell(9.25, 0.0))


def test_a_cell_centre_maps_back_to_its_cell():
    x, y = TB3_MAP.cell_center(200, 17)
    assert (float(x), float(y)) == pytest.approx((0.025, -9.125))
    assert tuple(map(int, TB3_MAP.world_to_cell(x, y))) == (200, 17)
