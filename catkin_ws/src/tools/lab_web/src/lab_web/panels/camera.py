"""The camera panel: <ns>/camera/rgb/image_raw as JPEG thumbnails, subscribed only while a page shows them."""
import threading

import rospy
from sensor_msgs.msg import Image

from lab_web import commands
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import now_s
from lab_web.thumbnail import jpeg_thumbnail

CAMERA_PERIOD_S = 0.2


class CameraPanel(Panel):
    name = "camera"
    FRAMES = {"camera": '{"jpeg": base64 JPEG thumbnail, "width", "height"}  only while the page asked for it '
                        '(<= 5 Hz)'}
    COMMANDS = {"camera": commands.CommandSpec((("on", commands.boolean),), "camera thumbnails on or off")}

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.camera = Versioned()
        self._owners = set()
        self._subscriber = None
        self._time = 0.0

    def frames(self, session):
        with self._lock:
            if session.owner not in self._owners:
                return []
        return self.lacking(session, ("camera", self.camera))

    def handle(self, session, kind, args):
        session.sent.pop("camera", None)
        self._show(session.owner, args["on"])

    def _show(self, owner, on):
        with self._lock:
            (self._owners.add if on else self._owners.discard)(owner)
            wanted = bool(self._owners)
            if wanted and self._subscriber is None:
                self._subscriber = rospy.Subscriber(self.ros.name("camera/rgb/image_raw"), Image, self._on_image,
                                                    queue_size=1, buff_size=2 ** 24)
            elif not wanted and self._subscriber is not None:
                self._subscriber.unregister()
                self._subscriber = None

    def _on_image(self, image):
        now = now_s()
        if now - self._time < CAMERA_PERIOD_S:
            return
        self._time = now
        thumbnail = jpeg_thumbnail(image.data, image.width, image.height, image.encoding, image.step)
        if thumbnail is not None:
            with self._lock:
                self.camera.set(thumbnail)

    def disconnect(self, owner):
        self._show(owner, False)
