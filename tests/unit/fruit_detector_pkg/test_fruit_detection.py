"""Colour segmentation on synthetic BGR images: a red disc is an apple (on both sides of the hue wrap), a
yellow bar a banana; red-orange, dark, pale, tiny or speckled blobs are neither; coordinates are those of the
image given, also when the detection runs on a downscaled copy."""
import cv2
import numpy as np
import pytest

from fruit_detector_pkg.fruit_detection import (
    BOX_COLOUR_BGR,
    MIN_BLOB_AREA_FRACTION,
    annotate,
    colour_mask,
    detect_fruit,
)

GREY_BGR = (128, 128, 128)
RED_BGR = (30, 30, 200)
YELLOW_BGR = (30, 220, 230)


def bgr_of_hsv(hue, saturation=230, value=220):
    """The BGR colour with OpenCV HSV (hue 0..179, saturation and value 0..255)."""
    return tuple(int(c) for c in cv2.cvtColor(np.uint8([[[hue, saturation, value]]]), cv2.COLOR_HSV2BGR)[0, 0])


def scene(width=640, height=480, background=GREY_BGR):
    image = np.empty((height, width, 3), np.uint8)
    image[:] = background
    return image


def disc(image, centre, radius, colour):
    cv2.circle(image, centre, radius, colour, -1)
    return image


def bar(image, top_left, size, colour):
    cv2.rectangle(image, top_left, (top_left[0] + size[0] - 1, top_left[1] + size[1] - 1), colour, -1)
    return image


def test_a_red_disc_is_an_apple_and_not_a_banana():
    image = disc(scene(), (200, 240), 20, RED_BGR)
    apple = detect_fruit(image, "apple")
    assert apple.in_view
    assert apple.centroid == pytest.approx((200, 240), abs=0.5)
    assert apple.box == pytest.approx((180, 220, 41, 41), abs=2)   # the opening trims the disc's outermost pixels
    assert apple.area_px == pytest.approx(np.pi * 20 ** 2, rel=0.05)
    assert apple.image_size == (640, 480)
    assert not detect_fruit(image, "banana").in_view


@pytest.mark.parametrize("hue", [0, 5, 10, 170, 175, 179])
def test_red_on_both_sides_of_the_hue_wrap_is_an_apple(hue):
    assert detect_fruit(disc(scene(), (320, 240), 15, bgr_of_hsv(hue)), "apple").in_view


def test_a_yellow_bar_is_a_banana_and_not_an_apple():
    image = bar(scene(), (400, 300), (80, 20), YELLOW_BGR)
    banana = detect_fruit(image, "banana")
    assert banana.in_view
    assert banana.box == (400, 300, 80, 20)
    assert banana.centroid == pytest.approx((439.5, 309.5))
    assert not detect_fruit(image, "apple").in_view


def test_both_fruits_are_found_where_they_are():
    image = bar(disc(scene(), (150, 200), 18, RED_BGR), (420, 210), (90, 22), YELLOW_BGR)
    assert detect_fruit(image, "apple").centroid == pytest.approx((150, 200), abs=0.5)
    assert detect_fruit(image, "banana").centroid == pytest.approx((464.5, 220.5), abs=0.5)


@pytest.mark.parametrize("background", [GREY_BGR, (255, 255, 255), (0, 0, 0), (200, 120, 40)])
def test_no_fruit_in_plain_scenes(background):
    image = scene(background=background)
    assert not detect_fruit(image, "apple").in_view
    assert not detect_fruit(image, "banana").in_view


def test_scattered_red_and_yellow_noise_is_not_a_fruit():
    rng = np.random.default_rng(7)
    image = scene()
    for colour in (RED_BGR, YELLOW_BGR):
        noisy = rng.random(image.shape[:2]) < 0.05
        image[noisy] = colour
    assert not detect_fruit(image, "apple").in_view
    assert not detect_fruit(image, "banana").in_view


@pytest.mark.parametrize("hue", [12, 15, 18])
def test_red_orange_is_neither_apple_nor_banana(hue):
    image = disc(scene(), (320, 240), 30, bgr_of_hsv(hue))
    assert not detect_fruit(image, "apple").in_view
    assert not detect_fruit(image, "banana").in_view


@pytest.mark.parametrize("hue", [22, 30, 35])
def test_golden_to_lemon_yellow_is_a_banana(hue):
    assert detect_fruit(bar(scene(), (100, 100), (60, 20), bgr_of_hsv(hue)), "banana").in_view


@pytest.mark.parametrize("fruit, hue", [("apple", 0), ("apple", 178), ("banana", 30)])
def test_faces_shaded_as_tb3_sim_shades_them_still_count(fruit, hue):
    """Pure red or yellow lit at 60 % and dimmed by distance to 60 %: V = 255 * 0.36 = 92."""
    assert detect_fruit(disc(scene(), (320, 240), 20, bgr_of_hsv(hue, 255, 92)), fruit).in_view


@pytest.mark.parametrize("hue, saturation, value, fruit", [
    (0, 230, 50, "apple"),       # too dark: a shadow, not a red
    (0, 60, 230, "apple"),       # too pale: pink
    (28, 230, 50, "banana"),     # too dark: dark olive
    (28, 80, 230, "banana"),     # too pale: cream
    (45, 230, 220, "banana"),    # greenish yellow: lime
])
def test_dark_pale_or_off_hue_colours_do_not_count(hue, saturation, value, fruit):
    image = disc(scene(), (320, 240), 30, bgr_of_hsv(hue, saturation, value))
    assert not detect_fruit(image, fruit).in_view


def test_a_blob_must_reach_the_minimum_area():
    min_area = MIN_BLOB_AREA_FRACTION * 640 * 480
    small_side = int(np.sqrt(min_area)) - 2
    large_side = int(np.sqrt(min_area)) + 2
    assert not detect_fruit(bar(scene(), (100, 100), (small_side, small_side), RED_BGR), "apple").in_view
    assert detect_fruit(bar(scene(), (100, 100), (large_side, large_side), RED_BGR), "apple").in_view


def test_the_largest_of_several_blobs_is_reported():
    image = disc(disc(scene(), (100, 100), 12, RED_BGR), (500, 300), 25, RED_BGR)
    assert detect_fruit(image, "apple").centroid == pytest.approx((500, 300), abs=0.5)


def test_full_hd_frames_are_detected_downscaled_but_reported_in_full_resolution():
    image = disc(scene(1920, 1080), (1500, 400), 45, RED_BGR)
    apple = detect_fruit(image, "apple")
    assert apple.image_size == (1920, 1080)
    assert apple.centroid == pytest.approx((1500, 400), abs=2)
    assert apple.box.x == pytest.approx(1455, abs=3) and apple.box.width == pytest.approx(91, abs=4)
    assert apple.area_px == pytest.approx(np.pi * 45 ** 2, rel=0.08)


def test_a_thin_image_still_works():
    assert detect_fruit(disc(scene(64, 48), (30, 20), 6, RED_BGR), "apple").in_view


def test_annotation_boxes_the_fruit_on_a_copy():
    image = disc(scene(), (200, 240), 20, RED_BGR)
    original = image.copy()
    box = detect_fruit(image, "apple").box
    annotated = annotate(image, detect_fruit(image, "apple"))
    assert np.array_equal(image, original)
    assert annotated.shape == image.shape and annotated.dtype == np.uint8
    assert tuple(annotated[240, box.x]) == BOX_COLOUR_BGR                 # the box's left edge, level with the centre
    assert tuple(annotated[240, box.x + box.width]) == BOX_COLOUR_BGR     # its right edge
    assert (annotated[box.y - 30:box.y - 2, box.x:box.x + 80] == BOX_COLOUR_BGR).all(axis=2).any()   # the label
    assert np.array_equal(annotated[240, box.x + 5:box.x + box.width - 5], image[240, box.x + 5:box.x + box.width - 5])


def test_annotation_says_when_the_fruit_is_not_in_view():
    image = scene()
    annotated = annotate(image, detect_fruit(image, "banana"))
    assert (annotated[:40, :200] == BOX_COLOUR_BGR).all(axis=2).any()
    assert np.array_equal(annotated[100:], image[100:])


def test_an_unknown_fruit_has_no_colour():
    with pytest.raises(ValueError, match="known: apple, banana"):
        colour_mask(cv2.cvtColor(scene(), cv2.COLOR_BGR2HSV), "kiwi")
