"""map_saver's two files for a small known grid, byte for byte."""
import math

import numpy as np
import pytest

from lab_nav.maps.map_saver_files import pgm_bytes, quaternion_yaw, yaml_text

# 3 rows x 4 columns, row 0 at the origin (the bottom of the image)
CELLS = np.array([[0, 25, 26, 64],
                  [65, 100, -1, 50],
                  [-1, 0, 100, 1]], dtype=np.int8)


def test_the_pgm_has_the_originals_header_and_the_last_map_row_on_top():
    expected = (b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n4 3\n255\n"
                + bytes([205, 254, 0, 254])       # map row 2
                + bytes([0, 0, 205, 205])         # map row 1
                + bytes([254, 254, 205, 205]))    # map row 0
    assert pgm_bytes(CELLS, 0.05000000074505806) == expected


def test_the_thresholds_move_the_free_and_occupied_bands():
    body = pgm_bytes(CELLS, 0.1, occupied_threshold=50, free_threshold=0)[-12:]
    assert body[8:] == bytes([254, 205, 205, 0])   # 0 free; 25, 26 in between; 64 >= 50 occupied
    assert body[4:8] == bytes([0, 0, 205, 0])      # 65, 100 occupied; -1 unknown; 50 occupied


def test_the_yaml_matches_the_originals_text_to_the_byte():
    text = yaml_text("maps/room.pgm", 0.05000000074505806, -10.0, -10.0, 0.0)
    assert text == ("image: maps/room.pgm\nresolution: 0.050000\norigin: [-10.000000, -10.000000, 0.000000]\n"
                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n")


@pytest.mark.parametrize("quaternion, yaw", [
    ((0.0, 0.0, 0.0, 1.0), 0.0),
    ((0.0, 0.0, math.sin(0.25), math.cos(0.25)), 0.5),
    ((0.0, 0.0, 1.0, 0.0), math.pi),
    ((0.0, 0.0, 0.0, 0.0), 0.0),          # an unset Pose
    ((0.0, 0.0, 0.0, 2.0), 0.0),          # not normalised: tf2 normalises
])
def test_the_yaw_comes_from_the_origin_quaternion(quaternion, yaw):
    assert quaternion_yaw(*quaternion) == pytest.approx(yaw)


def test_a_negative_yaw_is_written_with_its_sign():
    yaw = quaternion_yaw(0.0, 0.0, -math.sin(0.5), math.cos(0.5))
    assert "origin: [1.500000, -2.250000, -1.000000]" in yaml_text("m.pgm", 0.1, 1.5, -2.25, yaw)
