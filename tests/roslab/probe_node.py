"""The probe node: a rospy node in its own process that a test drives over stdin/stdout, one JSON object per
line. It exists because rospy allows one init_node per process while each test module has its own master.

Requests:  {"op": "subscribe", "topic": t, "type": "pkg/Msg"}            -> {"ok": true, "connections": n}
           {"op": "subscribe", ..., "image_file": path}  for sensor_msgs/Image or CompressedImage: messages come
               back without their `data` (its length instead), and the latest image, decoded by cv_bridge
               (imgmsg_to_cv2 or compressed_imgmsg_to_cv2), is saved as a numpy .npy file at `path`
           {"op": "take", "topic": t}  (and clears the buffer)           -> {"ok": true, "messages": [...]}
           {"op": "publish", "topic": t, "type": "pkg/Msg", "msg": {...}, "wait_s": 5}
                                                                         -> {"ok": true, "subscribers": n}
           {"op": "now"}                                                 -> {"ok": true, "now": ros seconds}
Each message comes back as {"wall": time.time(), "ros": rospy time (sim time when /use_sim_time), "msg": dict}.
Errors come back as {"ok": false, "error": text}.
"""
import json
import math
import os
import sys
import threading
import time

import genpy
import numpy
import rosgraph
import roslib.message
import rospy

from roslab.graph import subscribers
from sim_clock import quiet_time_notifications


def to_plain(value):
    """A message as JSON-able plain data: dicts of fields, lists, seconds for Time/Duration, str for inf/nan."""
    if isinstance(value, (genpy.Time, genpy.Duration)):
        return value.to_sec()
    if isinstance(value, genpy.Message):
        return {slot: to_plain(getattr(value, slot)) for slot in value.__slots__}
    if isinstance(value, (list, tuple)):
        return [to_plain(item) for item in value]
    if isinstance(value, bytes):
        return list(value)
    if isinstance(value, float) and not math.isfinite(value):
        return repr(value)
    return value


def subscriber_count(topic):
    """How many nodes other than this one the master lists as subscribers of `topic`."""
    return len([node for node in subscribers(rosgraph.get_master_uri(), topic) if node != rospy.get_name()])


class Probe:
    def __init__(self):
        self._lock = threading.Lock()
        self._buffers = {}
        self._subscribers = {}
        self._publishers = {}
        self._image_files = {}
        self._bridge = None   # cv_bridge (and with it OpenCV) loads at the first image subscription: 0.35 s

    def subscribe(self, topic, type, wait_s=5.0, image_file=None):
        """Subscribe, then wait up to `wait_s` for a connection to a publisher, so that a message published
        right after this returns is not missed."""
        msg_class = self._message_class(type)
        with self._lock:
            if image_file is not None:
                if self._bridge is None:
                    from cv_bridge import CvBridge
                    self._bridge = CvBridge()
                self._image_files[topic] = image_file
            if topic not in self._subscribers:
                self._buffers[topic] = []
                self._subscribers[topic] = rospy.Subscriber(topic, msg_class, self._record, callback_args=topic,
                                                            queue_size=1000)
            subscriber = self._subscribers[topic]
        deadline = time.monotonic() + wait_s
        while subscriber.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.02)
        return {"connections": subscriber.get_num_connections()}

    def _record(self, msg, topic):
        image_file = self._image_files.get(topic)
        if image_file is not None:
            self._save_image(msg, image_file)
            plain = to_plain(msg)
            plain["data"] = len(msg.data)
        else:
            plain = to_plain(msg)
        entry = {"wall": time.time(), "ros": rospy.get_rostime().to_sec(), "msg": plain}
        with self._lock:
            self._buffers[topic].append(entry)

    def _save_image(self, msg, path):
        """Decode `msg` as a course's node would and save the array where the test reads it (atomically)."""
        if hasattr(msg, "format"):
            pixels = self._bridge.compressed_imgmsg_to_cv2(msg)
        else:
            pixels = self._bridge.imgmsg_to_cv2(msg)
        with open(path + ".part", "wb") as part:
            numpy.save(part, pixels)
        os.replace(path + ".part", path)

    def take(self, topic):
        with self._lock:
            messages, self._buffers[topic] = self._buffers[topic], []
        return {"messages": messages}

    def publish(self, topic, type, msg, wait_s=5.0):
        """Publish once every subscriber the master lists (at least one) has connected, or once `wait_s` has
        passed: a node that subscribed but has not connected yet would miss the message."""
        if topic not in self._publishers:
            self._publishers[topic] = rospy.Publisher(topic, self._message_class(type), queue_size=10)
        publisher = self._publishers[topic]
        deadline = time.monotonic() + wait_s
        while publisher.get_num_connections() < max(1, subscriber_count(publisher.resolved_name)) \
                and time.monotonic() < deadline:
            time.sleep(0.02)
        message = publisher.data_class()
        genpy.message.fill_message_args(message, [msg])
        publisher.publish(message)
        return {"subscribers": publisher.get_num_connections()}

    def now(self):
        return {"now": rospy.get_rostime().to_sec()}

    @staticmethod
    def _message_class(type_name):
        msg_class = roslib.message.get_message_class(type_name)
        if msg_class is None:
            raise ValueError("unknown message type " + type_name)
        return msg_class


def main():
    quiet_time_notifications()   # the probe follows /clock at the test's factor: up to 1000 messages a second
    rospy.init_node("roslab_probe", anonymous=True, disable_signals=True)
    probe = Probe()
    print(json.dumps({"ok": True, "ready": True}), flush=True)
    for line in sys.stdin:
        request = json.loads(line)
        op = request.pop("op")
        try:
            reply = dict(getattr(probe, op)(**request), ok=True)
        except Exception as error:  # reported to the test, which raises it there
            reply = {"ok": False, "error": "{}: {}".format(type(error).__name__, error)}
        print(json.dumps(reply), flush=True)
    rospy.signal_shutdown("probe input closed")


if __name__ == "__main__":
    main()
