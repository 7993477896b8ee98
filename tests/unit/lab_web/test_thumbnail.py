"""Camera thumbnails from the compressed topic: a JPEG scaled to 320 px wide, decoded at a reduced size where that
still gives 320 px, true colours kept; what is not a JPEG is not shown."""
import base64

import cv2
import numpy as np
import pytest

from lab_web.thumbnail import compressed_thumbnail, jpeg_size, raw_thumbnail


def jpeg_of(rgb):
    """The JPEG the simulator publishes: BGR samples at quality 80."""
    return cv2.imencode(".jpg", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_JPEG_QUALITY, 80])[1].tobytes()


def decoded(thumbnail):
    return cv2.imdecode(np.frombuffer(base64.b64decode(thumbnail["jpeg"]), np.uint8), cv2.IMREAD_COLOR)


@pytest.mark.parametrize("width, height", [(1920, 1080), (640, 480), (160, 120)])
def test_a_frame_becomes_a_jpeg_320_px_wide_at_most_in_its_true_colours(width, height):
    rgb = np.zeros((height, width, 3), np.uint8)
    rgb[:, :width // 2] = (150, 90, 40)     # left half the boxes' brown
    rgb[:, width // 2:] = (20, 40, 230)     # right half blue
    thumbnail = compressed_thumbnail(jpeg_of(rgb))
    shown = min(width, 320)
    assert (thumbnail["width"], thumbnail["height"]) == (shown, round(height * shown / width))
    image = decoded(thumbnail)
    assert image.shape == (thumbnail["height"], thumbnail["width"], 3)
    for column, expected in ((shown // 4, (150, 90, 40)), (3 * shown // 4, (20, 40, 230))):
        blue, green, red = (int(value) for value in image[image.shape[0] // 2, column])
        assert all(abs(a - b) <= 12 for a, b in zip((red, green, blue), expected)), (red, green, blue)


def test_the_jpeg_size_is_read_from_its_frame_header():
    assert jpeg_size(jpeg_of(np.zeros((1080, 1920, 3), np.uint8))) == (1920, 1080)


@pytest.mark.parametrize("data", [b"", b"\xff\xd8", b"\x89PNG\r\n\x1a\n" + bytes(64), b"\xff\xd8\xff\xe0\x00\x10",
                                  b"\xff\xd8\xff\xc0\x00\x11\x08\x00\x00\x00\x00" + bytes(16)])
def test_what_is_not_a_whole_jpeg_is_not_shown(data):
    assert compressed_thumbnail(data) is None


def test_a_raw_rgb8_frame_becomes_the_same_thumbnail_and_depth_is_not_shown():
    rgb = np.zeros((480, 640, 3), np.uint8)
    rgb[:, :320] = (20, 40, 230)     # left half blue
    thumbnail = raw_thumbnail(rgb.tobytes(), 640, 480, "rgb8", 640 * 3)
    assert (thumbnail["width"], thumbnail["height"]) == (320, 240)
    blue, green, red = (int(value) for value in decoded(thumbnail)[120, 80])
    assert all(abs(a - b) <= 12 for a, b in zip((red, green, blue), (20, 40, 230))), (red, green, blue)
    assert raw_thumbnail(bytes(16), 2, 2, "32FC1", 8) is None
    assert raw_thumbnail(bytes(10), 640, 480, "rgb8", 1920) is None
