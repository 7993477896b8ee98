"""week6_vision.floor_view against the pinhole geometry: a floor point d ahead appears f h / d rows below the
optical axis and the robot's centre line f 0.047 / d columns left of it, at any resolution."""
import math

import pytest

from week6_vision.floor_view import (
    CAMERA_HEIGHT_M,
    CAMERA_RIGHT_OF_CENTRE_M,
    WAFFLE_HFOV_RAD,
    centre_line_column,
    floor_rows,
    focal_length_px,
)


def test_focal_length_is_gazebos():
    assert focal_length_px(1920) == pytest.approx(1920 / (2 * math.tan(WAFFLE_HFOV_RAD / 2)))
    assert focal_length_px(1920) == pytest.approx(1207.0, abs=1.0)


@pytest.mark.parametrize("width,height", [(1920, 1080), (640, 480), (160, 120)])
def test_rows_show_the_floor_between_near_and_far(width, height):
    first, end = floor_rows(width, height, 0.3, 0.5)
    f, axis = focal_length_px(width), (height + 1) / 2
    for row, distance in ((first, 0.5), (end - 1, 0.3)):
        assert CAMERA_HEIGHT_M * f / (row - axis) == pytest.approx(distance, rel=0.05 + 1 / (row - axis))


def test_rows_are_clipped_to_the_image():
    first, end = floor_rows(160, 120, 0.05, 0.1)   # nearer than the bottom row sees
    assert (first, end) == (119, 120)


def test_centre_line_lies_left_of_the_axis_by_the_cameras_offset():
    for width in (1920, 160):
        column = centre_line_column(width, 0.4)
        ground_offset_m = ((width + 1) / 2 - column) * 0.4 / focal_length_px(width)
        assert ground_offset_m == pytest.approx(CAMERA_RIGHT_OF_CENTRE_M)
    assert (1921 / 2 - centre_line_column(1920, 0.4)) / 1920 == pytest.approx(0.074, abs=0.001)
