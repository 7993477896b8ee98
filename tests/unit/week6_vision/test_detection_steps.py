"""week6_vision.detection_steps: the crop is the image's middle, the mask marks the colour, the masked image keeps
only its pixels, and the centroid is where the colour is in the crop."""
import numpy as np
import pytest

from week6_vision.detection_steps import crop_middle, detect


def frame_with_blue_square():
    """A 160x120 white BGR frame with a blue square at columns 70-89, rows 50-69 (inside the middle crop)."""
    image = np.full((120, 160, 3), 255, np.uint8)
    image[50:70, 70:90] = (255, 0, 0)
    return image


def test_crop_keeps_the_middle_half_of_each_side():
    image = np.arange(120 * 160).reshape(120, 160)
    assert (crop_middle(image) == image[30:90, 40:120]).all()


def test_steps_of_a_frame_with_the_colour():
    steps = detect(frame_with_blue_square(), "blue")
    assert steps.cropped.shape == (60, 80, 3)
    assert steps.mask.shape == (60, 80) and steps.mask.sum() == 255 * 400
    blue = steps.mask > 0
    assert (steps.masked[blue] == (255, 0, 0)).all() and not steps.masked[~blue].any()
    assert steps.centroid == pytest.approx((39.5, 29.5))
    assert list(steps.images()) == ["step1_original", "step2_cropped", "step3_mask", "step4_masked"]


def test_steps_of_a_frame_without_the_colour():
    steps = detect(frame_with_blue_square(), "red")
    assert steps.centroid is None and not steps.masked.any()
