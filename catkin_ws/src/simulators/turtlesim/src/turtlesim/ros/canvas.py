"""~canvas/compressed: the pen canvas as a PNG sensor_msgs/CompressedImage, for viewers without a window (the
lab's web page, `rosrun image_view image_view image:=/turtlesim/canvas _image_transport:=compressed`).

Published from the tick, only while someone subscribes, only when the canvas changed, and at most CANVAS_RATE_HZ
(wall time, like the tick): encoding a 500x500 PNG takes milliseconds, drawing a trail changes it every tick."""
import rospy
from sensor_msgs.msg import CompressedImage

CANVAS_RATE_HZ = 10.0


class CanvasPublisher:
    def __init__(self):
        self._publisher = rospy.Publisher('~canvas/compressed', CompressedImage, queue_size=1, latch=True)
        self._sent_version = None
        self._sent_at = None

    def publish_if_changed(self, canvas, now_s):
        """Publish `canvas` (core.canvas.Canvas) if it changed since the last message, someone listens and the
        last message is at least 1 / CANVAS_RATE_HZ old; `now_s` is a monotonic wall time."""
        if canvas.version == self._sent_version or self._publisher.get_num_connections() == 0:
            return
        if self._sent_at is not None and now_s - self._sent_at < 1.0 / CANVAS_RATE_HZ:
            return
        message = CompressedImage(format='png', data=canvas.png_bytes())
        message.header.stamp = rospy.Time.now()
        message.header.frame_id = 'turtlesim'
        self._publisher.publish(message)
        self._sent_version, self._sent_at = canvas.version, now_s
