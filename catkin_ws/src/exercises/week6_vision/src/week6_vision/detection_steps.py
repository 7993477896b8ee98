"""Object detection on one camera frame, step by step as the course shows it, each step an image to save:
the original frame, the crop (the middle COLUMNS_KEPT of the width and ROWS_KEPT of the height: the course's
"region of interest"), the HSV mask of the colour looked for, and the crop with everything but that colour
blacked out (cv2.bitwise_and with the mask)."""
from typing import NamedTuple, Optional, Tuple

import cv2
import numpy as np

from week6_vision.colour_masks import centroid, colour_mask

COLUMNS_KEPT = 0.5
ROWS_KEPT = 0.5


class DetectionSteps(NamedTuple):
    original: np.ndarray
    cropped: np.ndarray
    mask: np.ndarray
    masked: np.ndarray
    centroid: Optional[Tuple[float, float]]   # (cx, cy) of the colour in the crop's pixels, None if not in view

    def images(self):
        """{file stem: image} of the four steps, in order."""
        return {"step1_original": self.original, "step2_cropped": self.cropped, "step3_mask": self.mask,
                "step4_masked": self.masked}


def crop_middle(image, columns_kept=COLUMNS_KEPT, rows_kept=ROWS_KEPT):
    height, width = image.shape[:2]
    top, left = int(height * (1 - rows_kept) / 2), int(width * (1 - columns_kept) / 2)
    return image[top:height - top, left:width - left]


def detect(bgr_image, colour):
    """The four steps for `colour` (a name week6_vision.colour_masks knows) on a BGR frame."""
    cropped = crop_middle(bgr_image)
    mask = colour_mask(cropped, colour)
    masked = cv2.bitwise_and(cropped, cropped, mask=mask)
    return DetectionSteps(bgr_image, cropped, mask, masked, centroid(mask))
