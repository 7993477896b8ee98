"""Colour thresholds in OpenCV's HSV (hue 0-179, saturation and value 0-255) and the blob centroid, as the course
teaches them: cv2.cvtColor to HSV, cv2.inRange per colour, cv2.moments for the centroid.

The ranges are the ones a student picks for Gazebo's pure material colours (red, yellow, green, turquoise, blue,
purple/magenta) as the camera shows them lit: any brightness from dark shade to full (V >= 50), strongly
saturated (S >= 150), hue within 10 of the colour's. Grey and white walls (S about 0) and the course floors'
wood colour #d7b262 (S 138) fall outside every range. Red straddles hue 0, so it has two ranges.
"""
import cv2
import numpy as np

MIN_SATURATION = 150
MIN_VALUE = 50
HUE_HALF_WIDTH = 10
COLOUR_HUES = {"red": 0, "yellow": 30, "green": 60, "turquoise": 90, "blue": 120, "purple": 150}
COLOUR_ALIASES = {"cyan": "turquoise", "magenta": "purple", "pink": "purple"}


class UnknownColour(ValueError):
    """A colour name that has no threshold here; the text lists the names that have one."""


def colour_name(name):
    """The canonical name of colour `name` (case and spaces ignored; cyan, magenta and pink are aliases)."""
    key = str(name).strip().lower()
    key = COLOUR_ALIASES.get(key, key)
    if key not in COLOUR_HUES:
        known = ", ".join(sorted(COLOUR_HUES) + sorted(COLOUR_ALIASES))
        raise UnknownColour(f"unknown colour {name!r} (known: {known})")
    return key


def hsv_ranges(name):
    """[(lower, upper), ...] HSV bounds for cv2.inRange: one range, two for red (it wraps round hue 0)."""
    hue = COLOUR_HUES[colour_name(name)]
    low, high = hue - HUE_HALF_WIDTH, hue + HUE_HALF_WIDTH
    bounds = [(max(low, 0), min(high, 179))]
    if low < 0:
        bounds.append((180 + low, 179))
    return [(np.array([lo, MIN_SATURATION, MIN_VALUE]), np.array([hi, 255, 255])) for lo, hi in bounds]


def colour_mask(bgr_image, name):
    """A uint8 mask (255 where the pixel has colour `name`) of a BGR image."""
    hsv = cv2.cvtColor(bgr_image, cv2.COLOR_BGR2HSV)
    mask = np.zeros(hsv.shape[:2], np.uint8)
    for lower, upper in hsv_ranges(name):
        mask |= cv2.inRange(hsv, lower, upper)
    return mask


def centroid(mask, min_fraction=0.001):
    """(cx, cy) in pixels of the mask's white pixels, or None when they cover less than `min_fraction` of it
    (noise, or a colour just at the image's edge)."""
    moments = cv2.moments(mask, binaryImage=True)
    if moments["m00"] < max(1.0, min_fraction * mask.size):
        return None
    return moments["m10"] / moments["m00"], moments["m01"] / moments["m00"]


def column_span(mask):
    """The fraction of the mask's width between its leftmost and rightmost white pixel (0 when it has none)."""
    columns = np.flatnonzero(mask.any(axis=0))
    return 0.0 if columns.size == 0 else (columns[-1] - columns[0] + 1) / mask.shape[1]
