"""week6_vision.colour_masks: each course colour, lit or in shade, falls in its own range and no other; grey,
white and the wood colour in none; names and aliases; the centroid of a blob and of too little."""
import colorsys

import numpy as np
import pytest

from week6_vision.colour_masks import COLOUR_HUES, UnknownColour, centroid, colour_mask, colour_name, column_span

GAZEBO_RGB = {"red": (255, 0, 0), "yellow": (255, 255, 0), "green": (0, 255, 0), "turquoise": (0, 255, 255),
              "blue": (0, 0, 255), "purple": (255, 0, 255)}
NO_COLOUR_RGB = {"white": (255, 255, 255), "grey": (179, 179, 179), "wood": (0xd7, 0xb2, 0x62), "black": (0, 0, 0)}


def patch(rgb, shade=1.0):
    """A 4x4 BGR image of one colour at `shade` of its brightness."""
    r, g, b = (round(c * shade) for c in rgb)
    return np.full((4, 4, 3), (b, g, r), np.uint8)


@pytest.mark.parametrize("name", sorted(GAZEBO_RGB))
@pytest.mark.parametrize("shade", [1.0, 0.6, 0.3])
def test_each_colour_lit_or_shaded_is_in_its_own_range_only(name, shade):
    image = patch(GAZEBO_RGB[name], shade)
    for other in COLOUR_HUES:
        assert bool(colour_mask(image, other).all()) == (other == name), other


@pytest.mark.parametrize("name", sorted(NO_COLOUR_RGB))
def test_grey_white_black_and_wood_are_in_no_range(name):
    for colour in COLOUR_HUES:
        assert not colour_mask(patch(NO_COLOUR_RGB[name]), colour).any(), colour


def test_red_either_side_of_hue_zero_is_red():
    for hue_degrees in (354, 6):
        rgb = tuple(round(255 * c) for c in colorsys.hsv_to_rgb(hue_degrees / 360, 1.0, 1.0))
        assert colour_mask(patch(rgb), "red").all(), hue_degrees


def test_names_ignore_case_and_spaces_and_know_the_aliases():
    assert colour_name(" Blue ") == "blue"
    assert colour_name("magenta") == colour_name("pink") == "purple"
    assert colour_name("cyan") == "turquoise"
    with pytest.raises(UnknownColour, match="unknown colour 'orange' \\(known: blue, green"):
        colour_name("orange")


def test_centroid_of_a_blob_and_none_for_too_little():
    mask = np.zeros((100, 200), np.uint8)
    mask[40:60, 150:170] = 255
    assert centroid(mask) == pytest.approx((159.5, 49.5))
    assert centroid(np.zeros((100, 200), np.uint8)) is None
    speck = np.zeros((100, 200), np.uint8)
    speck[0, 0] = 255
    assert centroid(speck) is None   # one pixel of 20000 is below the 0.1 % floor


def test_column_span_is_the_share_of_the_width_between_the_outermost_pixels():
    mask = np.zeros((10, 200), np.uint8)
    assert column_span(mask) == 0.0
    mask[3, 50] = mask[7, 149] = 255
    assert column_span(mask) == 0.5
