"""Camera thumbnails for the page: a sensor_msgs/CompressedImage's JPEG (or, for the first picture, a raw
sensor_msgs/Image) to a small base64 JPEG in true colour. No ROS import (the bridge passes the message's fields),
OpenCV for the decoding, scaling and encoding.

The simulator's JPEG (compressed_image_transport's format: BGR samples, so true colour once decoded) is decoded at
a half, a quarter or an eighth of its size where the thumbnail is still THUMBNAIL_WIDTH_PX wide: libjpeg then skips
most of the work (a 1920x1080 frame decodes as 480x270 in about a tenth of the full decode's time).
"""
import base64
import struct

import cv2
import numpy as np

THUMBNAIL_WIDTH_PX = 320
JPEG_QUALITY = 70
CHANNELS = {"rgb8": 3, "bgr8": 3, "mono8": 1}
REDUCED_READS = ((8, cv2.IMREAD_REDUCED_COLOR_8), (4, cv2.IMREAD_REDUCED_COLOR_4), (2, cv2.IMREAD_REDUCED_COLOR_2))
"""libjpeg's scaled decodes, the smallest first."""
START_OF_FRAME = frozenset(range(0xC0, 0xD0)) - {0xC4, 0xC8, 0xCC}
"""JPEG markers whose segment holds the image size (SOF0-SOF15 but DHT, JPG and DAC)."""
STANDALONE = frozenset(range(0xD0, 0xDA)) | {0x01}
"""Markers without a length: RSTn, SOI, EOI and TEM."""


def jpeg_size(data):
    """(width, height) from a JPEG's start-of-frame segment, or None when `data` is not a JPEG with one."""
    if data[:2] != b"\xff\xd8":
        return None
    at = 2
    while at + 4 <= len(data):
        if data[at] != 0xFF:
            return None
        marker = data[at + 1]
        if marker == 0xFF:          # fill byte
            at += 1
            continue
        if marker in STANDALONE:
            at += 2
            continue
        length = struct.unpack_from(">H", data, at + 2)[0]
        if marker in START_OF_FRAME:
            if at + 9 > len(data):
                return None
            height, width = struct.unpack_from(">HH", data, at + 5)
            return (width, height) if width and height else None
        if marker == 0xDA:          # start of scan before any frame header
            return None
        at += 2 + length
    return None


def raw_thumbnail(data, width, height, encoding, step):
    """The thumbnail of a raw image, or None for an encoding the page does not show (depth images) or a message
    whose size does not add up."""
    channels = CHANNELS.get(encoding)
    if channels is None or width <= 0 or height <= 0 or step < width * channels or len(data) < step * height:
        return None
    pixels = np.frombuffer(data, dtype=np.uint8, count=step * height).reshape(height, step)[:, :width * channels]
    pixels = pixels.reshape(height, width, channels) if channels > 1 else pixels.reshape(height, width)
    return _thumbnail(cv2.cvtColor(pixels, cv2.COLOR_RGB2BGR) if encoding == "rgb8" else pixels)


def compressed_thumbnail(data):
    """{"jpeg": base64 text, "width", "height"} of the JPEG `data` scaled to THUMBNAIL_WIDTH_PX wide (smaller images
    kept as they are), or None for data that is not a JPEG (a PNG-compressed depth image, a broken message)."""
    size = jpeg_size(bytes(data[:65536]))
    if size is None:
        return None
    width = size[0]
    flag = next((flag for factor, flag in REDUCED_READS if width // factor >= THUMBNAIL_WIDTH_PX), cv2.IMREAD_COLOR)
    pixels = cv2.imdecode(np.frombuffer(data, dtype=np.uint8), flag)
    return None if pixels is None else _thumbnail(pixels)


def _thumbnail(pixels):
    """{"jpeg", "width", "height"} of BGR (or grey) `pixels` scaled to THUMBNAIL_WIDTH_PX wide at most."""
    if pixels.shape[1] > THUMBNAIL_WIDTH_PX:
        height = max(1, round(pixels.shape[0] * THUMBNAIL_WIDTH_PX / pixels.shape[1]))
        pixels = cv2.resize(pixels, (THUMBNAIL_WIDTH_PX, height), interpolation=cv2.INTER_AREA)
    ok, encoded = cv2.imencode(".jpg", pixels, [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY])
    if not ok:
        return None
    return {"jpeg": base64.b64encode(encoded.tobytes()).decode(), "width": pixels.shape[1], "height": pixels.shape[0]}
