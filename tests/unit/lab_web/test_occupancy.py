"""The map as the page draws it: one PNG pixel per cell, RViz's map colours, row 0 first."""
import base64

import cv2
import numpy as np
import pytest

from lab_web.occupancy import UNKNOWN_RGB, grid_png


def decoded(text):
    image = cv2.imdecode(np.frombuffer(base64.b64decode(text), dtype=np.uint8), cv2.IMREAD_UNCHANGED)
    return cv2.cvtColor(image, cv2.COLOR_BGRA2RGBA)[:, :, :3]


def test_the_costmap_scheme_is_rvizs_free_clear_lethal_purple_inscribed_cyan():
    image = cv2.imdecode(np.frombuffer(base64.b64decode(grid_png([0, 100, 99, 50], 4, 1, "costmap")), dtype=np.uint8),
                         cv2.IMREAD_UNCHANGED)
    rgba = cv2.cvtColor(image, cv2.COLOR_BGRA2RGBA)[0]
    assert rgba[0][3] == 0
    assert tuple(rgba[1]) == (255, 0, 255, 255) and tuple(rgba[2]) == (0, 255, 255, 255)
    assert tuple(rgba[3]) == (127, 0, 128, 255)


def test_free_occupied_unknown_and_partial_cells_get_rviz_colours_in_message_order():
    image = decoded(grid_png([0, 100, -1, 50, 0, 0], 3, 2))
    assert image.shape == (2, 3, 3)
    assert tuple(image[0, 0]) == (255, 255, 255) and tuple(image[0, 1]) == (0, 0, 0)
    assert tuple(image[0, 2]) == UNKNOWN_RGB and tuple(image[1, 0]) == (128, 128, 128)


def test_bytes_are_read_as_int8_cells():
    assert tuple(decoded(grid_png(bytes([255, 100]), 2, 1))[0, 0]) == UNKNOWN_RGB


@pytest.mark.parametrize("data, width, height, reason", [
    ([0, 0, 0], 2, 2, "the map has 3 cells, its info says 2 x 2"),
    ([], 0, 0, "is not drawn"),
])
def test_a_grid_whose_size_does_not_add_up_is_refused_with_a_reason(data, width, height, reason):
    with pytest.raises(ValueError, match=reason):
        grid_png(data, width, height)
