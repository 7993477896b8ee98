"""The camera panel: <ns>/camera/rgb/image_raw/compressed as JPEG thumbnails in true colour, while a page shows them.

The simulator renders (and JPEG-encodes) its 1920x1080 camera at 30 Hz of sim time for as long as anyone subscribes,
most of a core; a page needs a few pictures a second. So the panel takes snapshots, as `rospy.wait_for_message` does:
every CAMERA_PERIOD_S it subscribes, takes the first image, and unsubscribes, and the simulator renders a frame or two
per snapshot instead of 30 a second (it keeps real time with the camera shown). Nothing is subscribed, rendered or
decoded while no page shows the camera. The compressed topic carries a tenth of the raw image's bytes, decoded at a
reduced size (lab_web.thumbnail). The first snapshot after a page asks is of the raw image: the simulator imports
OpenCV at its first compressed frame (1.7 s under load 8), so the first picture shows in a fifth of a second and the
second one pays for the import."""
import threading

import rospy
from sensor_msgs.msg import CompressedImage, Image

from lab_web import commands
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import now_s
from lab_web.thumbnail import compressed_thumbnail, raw_thumbnail

RAW_TOPIC = "camera/rgb/image_raw"
COMPRESSED_TOPIC = RAW_TOPIC + "/compressed"
CAMERA_PERIOD_S = 0.5
"""Wall seconds from one snapshot to the next (2 Hz); the first comes as soon as a page asks. Each snapshot costs the
simulator one or two 1920x1080 frames. Measured at load 4-8 on 2 cores (Week 4 demo at 1x, 10 s each): a plain
subscriber took 97 % of a core in tb3_sim and held it at 0.935x; snapshots every 0.5 s 30 % and 1.000x (every 0.25 s
51 %, 1.000x; none 8-9 %, 0.97-1.00x). Under load 13 a plain subscriber gave 0.19x, snapshots 0.25-0.54x."""
SNAPSHOT_WAIT_S = 3.0
"""A snapshot waits this long for an image (a robot without a camera sends none) before it subscribes afresh."""


class CameraPanel(Panel):
    name = "camera"
    FRAMES = {"camera": '{"jpeg": base64 JPEG thumbnail, "width", "height"}  only while the page asked for it '
                        '(<= 2 Hz)'}
    COMMANDS = {"camera": commands.CommandSpec((("on", commands.boolean),), "camera thumbnails on or off")}

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.camera = Versioned()
        self._owners = set()
        self._wanted = threading.Event()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, daemon=True, name="lab_web_camera")
        self._thread.start()

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
            (self._wanted.set if self._owners else self._wanted.clear)()

    def _loop(self):
        """A snapshot every CAMERA_PERIOD_S while a page shows the camera."""
        first = True
        while not self._stop.is_set():
            if not self._wanted.is_set():
                first = True
                self._wanted.wait()
                continue
            started = now_s()
            if first:
                image = self._snapshot(self.ros.name(RAW_TOPIC), Image)
                thumbnail = image and raw_thumbnail(image.data, image.width, image.height, image.encoding, image.step)
            else:
                image = self._snapshot(self.ros.name(COMPRESSED_TOPIC), CompressedImage)
                thumbnail = image and compressed_thumbnail(image.data)
            if thumbnail:
                first = False
                with self._lock:
                    self.camera.set(thumbnail)
            self._stop.wait(max(0.0, CAMERA_PERIOD_S - (now_s() - started)))

    def _snapshot(self, topic, message_class):
        """The first image on `topic` after subscribing, or None within SNAPSHOT_WAIT_S (or when no page wants one
        any more); the subscription ends either way."""
        images = []
        arrived = threading.Event()

        def take(image):
            if not images:
                images.append(image)
                arrived.set()
        subscriber = rospy.Subscriber(topic, message_class, take, queue_size=1, buff_size=2 ** 24)
        try:
            deadline = now_s() + SNAPSHOT_WAIT_S
            while not arrived.wait(0.1) and now_s() < deadline and self._wanted.is_set() and not self._stop.is_set():
                pass
        finally:
            subscriber.unregister()
        return images[0] if images else None

    def disconnect(self, owner):
        self._show(owner, False)

    def shutdown(self):
        self._stop.set()
        self._wanted.set()   # wakes the loop, which then ends
