"""tb3_sim.ros.outputs.camera.JpegImage: the compressed image's JPEG is encoded when its data is first read (as the
queued publisher's thread serialises it), and is then the JPEG compressed_image_transport would have written."""
import io

import cv2
import numpy as np
from sensor_msgs.msg import CompressedImage

from tb3_sim.ros.outputs.camera import JPEG_QUALITY, JpegImage


def test_the_jpeg_is_made_when_read_and_serialises_as_a_compressed_image():
    rgb = np.zeros((24, 32, 3), dtype=np.uint8)
    rgb[:, :16] = (255, 0, 0)
    message = JpegImage(rgb)
    assert message._jpeg == b""                      # nothing encoded at construction (in the physics loop)
    expected = cv2.imencode(".jpg", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_JPEG_QUALITY,
                                                                         JPEG_QUALITY])[1].tobytes()
    buffer = io.BytesIO()
    message.serialize(buffer)
    received = CompressedImage().deserialize(buffer.getvalue())
    assert received.data == expected and message.data is message.data
    blue, green, red = cv2.imdecode(np.frombuffer(received.data, np.uint8), cv2.IMREAD_COLOR)[12, 4]
    assert blue < 5 and green < 5 and red > 250   # red stays red: BGR samples, as the format string says
