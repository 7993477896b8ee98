"""Echo text for the page: fields one per line like `rostopic echo`, nested messages indented, long arrays and
image bytes shortened."""
import math

from nav_msgs.msg import Odometry
from sensor_msgs.msg import Image, LaserScan

from lab_web.message_text import MAX_ITEMS, message_text


def test_nested_fields_are_indented():
    odom = Odometry()
    odom.header.frame_id = "odom"
    odom.pose.pose.position.x = 1.5
    lines = message_text(odom).splitlines()
    assert lines[:4] == ["header:", "  seq: 0", "  stamp: 0.000000000", "  frame_id: odom"]
    assert "      x: 1.5" in lines


def test_long_arrays_and_image_bytes_are_shortened():
    scan = LaserScan(ranges=[math.inf] + [1.0] * 359)
    text = message_text(scan)
    assert "ranges: [inf, " + ", ".join(["1.0"] * (MAX_ITEMS - 1)) + ", ... (360 items)]" in text
    image = Image(width=640, height=480, encoding="rgb8", data=bytes(640 * 480 * 3))
    assert "data: <921600 bytes>" in message_text(image)
