"""Find a fruit in a camera image by its colour (plain Python + OpenCV + numpy, no rospy).

Images are OpenCV's BGR, uint8, shape (height, width, 3): what cv_bridge's `imgmsg_to_cv2(msg, "bgr8")` returns
for the robot's rgb8 camera. Pixel coordinates are OpenCV's: x to the right, y down, origin at the top-left
corner of the image given (not of the downscaled copy the detection runs on).

How it works: the image is shrunk to at most DETECTION_WIDTH_PX wide (a 1920x1080 frame costs 9x less and a
fruit still spans tens of pixels), converted to HSV and thresholded with the fruit's colour ranges; an opening
(erode then dilate) removes specks, and the largest remaining blob is the fruit if it covers at least
MIN_BLOB_AREA_FRACTION of the image.

OpenCV's HSV for 8-bit images: hue H in 0..179 is degrees / 2 (so red, at 0 degrees, is both just above 0 and
just below 180: the apple needs two ranges), saturation S and value V in 0..255.
"""
from typing import NamedTuple, Optional, Tuple

import cv2
import numpy as np

FRUITS = ("apple", "banana")

# Apple red: hue within 20 degrees of pure red on either side of the wrap (H <= 10 or H >= 170). A red-orange
# (H 11..19, 22..38 degrees) is neither red nor yellow on purpose, so an orange is not an apple.
RED_LOW_HUE = (0, 10)
RED_HIGH_HUE = (170, 179)
# Banana yellow: 40..70 degrees (H 20..35), from golden to lemon yellow; greenish yellow above that is not.
YELLOW_HUE = (20, 35)
# Both fruits are strongly coloured: S >= 120 rules out greys, whites and pale pinks (a white wall under a
# warm light). V >= 70 rules out near-black pixels, whose hue is noise, but keeps shaded faces: tb3_sim (like
# Gazebo) lights a face at 60..100 % and dims it with distance down to 60 %, so a pure red or yellow face can
# be as dark as V = 92.
MIN_SATURATION = 120
MIN_VALUE = 70

# A fruit must cover at least this fraction of the image: 92 px in a 640x480 image, a blob about 10 px across.
# The 8 cm apple is about 30 px wide at 1 m in a 640 px image from the Waffle's R200 (77 degree field of view),
# so it counts out to about 3 m; isolated noisy pixels and specks that survive the opening do not.
MIN_BLOB_AREA_FRACTION = 0.0003
DETECTION_WIDTH_PX = 640
OPENING_KERNEL_PX = 3

# Annotation (BGR): a green box and label, readable on red, yellow and grey alike.
BOX_COLOUR_BGR = (0, 255, 0)
TEXT_COLOUR_BGR = (0, 255, 0)
LINE_WIDTH_PER_640_PX = 2
FONT_SCALE_PER_640_PX = 0.6


class Box(NamedTuple):
    """An axis-aligned bounding box in pixels: top-left corner (x, y), width and height."""

    x: int
    y: int
    width: int
    height: int


class Detection(NamedTuple):
    """What the camera shows of one fruit. `box`, `centroid` (x, y in px) and `area_px` describe the largest
    blob of the fruit's colour, in the coordinates of the image given; all three are None when the fruit is not
    in view. `image_size` is that image's (width, height)."""

    fruit: str
    box: Optional[Box]
    centroid: Optional[Tuple[float, float]]
    area_px: Optional[float]
    image_size: Tuple[int, int]

    @property
    def in_view(self):
        return self.box is not None


def colour_mask(hsv, fruit):
    """255 where a pixel of the HSV image has the colour of `fruit` ("apple" or "banana"), else 0."""
    if fruit == "apple":
        low = cv2.inRange(hsv, (RED_LOW_HUE[0], MIN_SATURATION, MIN_VALUE), (RED_LOW_HUE[1], 255, 255))
        high = cv2.inRange(hsv, (RED_HIGH_HUE[0], MIN_SATURATION, MIN_VALUE), (RED_HIGH_HUE[1], 255, 255))
        return cv2.bitwise_or(low, high)
    if fruit == "banana":
        return cv2.inRange(hsv, (YELLOW_HUE[0], MIN_SATURATION, MIN_VALUE), (YELLOW_HUE[1], 255, 255))
    raise ValueError("no colour for fruit {!r}; known: {}".format(fruit, ", ".join(FRUITS)))


def detect_fruit(image_bgr, fruit):
    """The Detection of `fruit` ("apple" or "banana") in a BGR image (see the module docstring)."""
    height, width = image_bgr.shape[:2]
    scale = min(1.0, DETECTION_WIDTH_PX / width)
    small = image_bgr if scale == 1.0 else cv2.resize(
        image_bgr, (max(1, round(width * scale)), max(1, round(height * scale))), interpolation=cv2.INTER_AREA)
    mask = colour_mask(cv2.cvtColor(small, cv2.COLOR_BGR2HSV), fruit)
    mask = cv2.morphologyEx(mask, cv2.MORPH_OPEN, np.ones((OPENING_KERNEL_PX, OPENING_KERNEL_PX), np.uint8))
    count, _, stats, centroids = cv2.connectedComponentsWithStats(mask)
    if count < 2:   # label 0 is the background
        return Detection(fruit, None, None, None, (width, height))
    largest = 1 + int(np.argmax(stats[1:, cv2.CC_STAT_AREA]))
    area = stats[largest, cv2.CC_STAT_AREA]
    if area < MIN_BLOB_AREA_FRACTION * small.shape[0] * small.shape[1]:
        return Detection(fruit, None, None, None, (width, height))
    x, y, w, h = (stats[largest, key] / scale for key in
                  (cv2.CC_STAT_LEFT, cv2.CC_STAT_TOP, cv2.CC_STAT_WIDTH, cv2.CC_STAT_HEIGHT))
    box = Box(int(round(x)), int(round(y)), int(round(w)), int(round(h)))
    cx, cy = centroids[largest] / scale
    return Detection(fruit, box, (float(cx), float(cy)), float(area / scale ** 2), (width, height))


def annotate(image_bgr, detection):
    """A copy of the image with the detection drawn on it: a box and the fruit's name above it when in view,
    otherwise "no <fruit> in view" in the top-left corner. Line width and text size follow the image width."""
    annotated = image_bgr.copy()
    size = annotated.shape[1] / DETECTION_WIDTH_PX
    line_width = max(1, round(LINE_WIDTH_PER_640_PX * size))
    font_scale = FONT_SCALE_PER_640_PX * size
    if detection.in_view:
        box = detection.box
        cv2.rectangle(annotated, (box.x, box.y), (box.x + box.width, box.y + box.height), BOX_COLOUR_BGR,
                      line_width)
        label, origin = detection.fruit, (box.x, max(box.y - 2 * line_width, round(20 * size)))
    else:
        label, origin = "no {} in view".format(detection.fruit), (round(10 * size), round(30 * size))
    cv2.putText(annotated, label, origin, cv2.FONT_HERSHEY_SIMPLEX, font_scale, TEXT_COLOUR_BGR, line_width,
                cv2.LINE_AA)
    return annotated
