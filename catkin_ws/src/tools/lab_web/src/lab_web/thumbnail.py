"""Camera thumbnails for the page: a sensor_msgs/Image's bytes to a small base64 JPEG. No ROS import (the
bridge passes the message's fields), OpenCV for the scaling and the encoding."""
import base64

import cv2
import numpy as np

THUMBNAIL_WIDTH_PX = 320
JPEG_QUALITY = 70
CHANNELS = {"rgb8": 3, "bgr8": 3, "mono8": 1}


def jpeg_thumbnail(data, width, height, encoding, step):
    """{"jpeg": base64 text, "width", "height"} of the image scaled to THUMBNAIL_WIDTH_PX wide, or None for an
    encoding the page does not show (depth images) or a message whose size does not add up."""
    channels = CHANNELS.get(encoding)
    if channels is None or width <= 0 or height <= 0 or step < width * channels or len(data) < step * height:
        return None
    pixels = np.frombuffer(data, dtype=np.uint8, count=step * height).reshape(height, step)[:, :width * channels]
    pixels = pixels.reshape(height, width, channels) if channels > 1 else pixels.reshape(height, width)
    if encoding == "rgb8":
        pixels = cv2.cvtColor(pixels, cv2.COLOR_RGB2BGR)
    scale = THUMBNAIL_WIDTH_PX / width
    if scale < 1.0:
        pixels = cv2.resize(pixels, (THUMBNAIL_WIDTH_PX, max(1, round(height * scale))), interpolation=cv2.INTER_AREA)
    ok, encoded = cv2.imencode(".jpg", pixels, [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY])
    if not ok:
        return None
    return {"jpeg": base64.b64encode(encoded.tobytes()).decode(), "width": pixels.shape[1], "height": pixels.shape[0]}
