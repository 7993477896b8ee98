"""Map images to cells in every mode, as map_server converts them, and map_saver's files loading back."""
import numpy as np
import pytest
from PIL import Image

from lab_nav.maps.errors import MapFileError
from lab_nav.maps.map_loader import deprecated_description, load_map
from lab_nav.maps.map_saver_files import pgm_bytes, yaml_text
from lab_nav.maps.pixel_cells import pixels_to_cells

HEADER = "resolution: 0.1\norigin: [1.0, 2.0, 0.0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"


def write_map(folder, pixels, mode_line="", negate=0, image_name="map.png"):
    Image.fromarray(np.asarray(pixels, dtype=np.uint8)).save(folder / image_name)
    yaml_path = folder / "map.yaml"
    yaml_path.write_text("image: {}\nnegate: {}\n{}{}".format(image_name, negate, HEADER, mode_line))
    return str(yaml_path)


def grey(values):
    return np.array([values], dtype=np.uint8)[:, :, None]


def test_trinary_thresholds_fall_where_the_standard_thresholds_put_them():
    cells = pixels_to_cells(grey([0, 89, 90, 205, 206, 254, 255]), False, "trinary", 0, 0.65, 0.196)
    assert cells.tolist() == [[100, 100, -1, -1, 0, 0, 0]]


def test_negate_swaps_black_and_white():
    cells = pixels_to_cells(grey([0, 128, 255]), False, "trinary", 1, 0.65, 0.196)
    assert cells.tolist() == [[0, -1, 100]]


def test_scale_mode_spreads_the_in_between_band_over_1_to_99():
    # p = (255 - v) / 255; v = 166 gives p = 0.349: 1 + 98 * (0.349 - 0.196) / (0.65 - 0.196) = 34.0 -> 34
    cells = pixels_to_cells(grey([0, 166, 205, 90, 255]), False, "scale", 0, 0.65, 0.196)
    assert cells.tolist() == [[100, 34, 1, 98, 0]]


def test_scale_mode_leaves_transparent_pixels_unknown_and_ignores_alpha_in_the_mean():
    rgba = np.array([[[166, 166, 166, 0], [166, 166, 166, 255], [0, 0, 0, 0]]], dtype=np.uint8)
    assert pixels_to_cells(rgba, True, "scale", 0, 0.65, 0.196).tolist() == [[-1, 34, 100]]


def test_trinary_mode_averages_alpha_in():
    # (255 * 3 + 0) / 4 = 191.25: p = 0.25, unknown; without alpha it would be free
    rgba = np.array([[[255, 255, 255, 0]]], dtype=np.uint8)
    assert pixels_to_cells(rgba, True, "trinary", 0, 0.65, 0.196).tolist() == [[-1]]


def test_raw_mode_stores_the_value_itself_and_wraps_above_127():
    cells = pixels_to_cells(grey([0, 100, 127, 128, 255]), False, "raw", 0, 0.65, 0.196)
    assert cells.tolist() == [[0, 100, 127, -128, -1]]
    assert pixels_to_cells(grey([0, 155]), False, "raw", 1, 0.65, 0.196).tolist() == [[-1, 100]]


def test_the_top_image_row_becomes_the_last_map_row(tmp_path):
    _, grid = load_map(write_map(tmp_path, [[0, 0, 0], [255, 255, 255]]))
    assert grid.cells.tolist() == [[0, 0, 0], [100, 100, 100]]
    geometry = grid.geometry
    assert (geometry.width, geometry.height, geometry.resolution) == (3, 2, 0.1)
    assert (geometry.origin_x, geometry.origin_y, geometry.origin_yaw) == (1.0, 2.0, 0.0)


def test_colour_and_palette_images_are_read_by_their_colours(tmp_path):
    rgb = np.array([[[255, 0, 0], [250, 250, 250]]], dtype=np.uint8)    # red: mean 85 -> occupied
    _, grid = load_map(write_map(tmp_path, rgb))
    assert grid.cells.tolist() == [[100, 0]]
    Image.fromarray(rgb).convert("P").save(tmp_path / "palette.png")
    (tmp_path / "palette.yaml").write_text("image: palette.png\nnegate: 0\n" + HEADER)
    assert load_map(str(tmp_path / "palette.yaml"))[1].cells.tolist() == [[100, 0]]


def test_map_savers_files_load_back_as_the_same_grid(tmp_path):
    cells = np.array([[0, 100, -1, 0], [-1, -1, 100, 0]], dtype=np.int8)
    (tmp_path / "saved.pgm").write_bytes(pgm_bytes(cells, 0.05))
    (tmp_path / "saved.yaml").write_text(yaml_text("saved.pgm", 0.05, -10.0, -10.0, 0.0))
    description, grid = load_map(str(tmp_path / "saved.yaml"))
    assert grid.cells.tolist() == cells.tolist()
    assert (description.mode, grid.geometry.origin_x) == ("trinary", -10.0)


def test_a_missing_or_broken_image_is_named_with_the_reason(tmp_path):
    with pytest.raises(MapFileError, match=r'^failed to open image file ".*/nothing\.png": No such file'):
        (tmp_path / "map.yaml").write_text("image: nothing.png\nnegate: 0\n" + HEADER)
        load_map(str(tmp_path / "map.yaml"))
    (tmp_path / "junk.png").write_bytes(b"not an image")
    (tmp_path / "map.yaml").write_text("image: junk.png\nnegate: 0\n" + HEADER)
    with pytest.raises(MapFileError, match=r'^failed to open image file ".*/junk\.png": cannot identify'):
        load_map(str(tmp_path / "map.yaml"))


def test_the_deprecated_form_uses_origin_zero_and_trinary():
    description = deprecated_description("room.pgm", 0.05, 1, 0.7, 0.2)
    assert (description.image, description.origin, description.mode, description.negate) == (
        "room.pgm", (0.0, 0.0, 0.0), "trinary", 1)
