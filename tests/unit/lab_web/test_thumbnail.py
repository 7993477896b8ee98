"""Camera thumbnails: an rgb8 image scaled to 320 px wide as JPEG, colours kept; depth images not shown."""
import base64

import cv2
import numpy as np

from lab_web.thumbnail import jpeg_thumbnail


def test_an_rgb_frame_becomes_a_small_jpeg_with_its_colours():
    rgb = np.zeros((480, 640, 3), np.uint8)
    rgb[:, :320] = (255, 0, 0)     # left half red
    thumbnail = jpeg_thumbnail(rgb.tobytes(), 640, 480, "rgb8", 640 * 3)
    assert (thumbnail["width"], thumbnail["height"]) == (320, 240)
    decoded = cv2.imdecode(np.frombuffer(base64.b64decode(thumbnail["jpeg"]), np.uint8), cv2.IMREAD_COLOR)
    assert decoded.shape == (240, 320, 3)
    blue, green, red = decoded[120, 80]
    assert red > 200 and green < 50 and blue < 50


def test_depth_and_inconsistent_images_are_not_shown():
    assert jpeg_thumbnail(bytes(16), 2, 2, "32FC1", 8) is None
    assert jpeg_thumbnail(bytes(10), 640, 480, "rgb8", 1920) is None
