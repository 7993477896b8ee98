"""/detect_fruit_service requests and replies as plain data: which fruit was asked for, and the words of the
answer (plain Python, no rospy).

The reply is (success, message): success is True only when the fruit asked for is in view in the latest camera
image. Everything that prevents an answer (an unknown word, no camera image yet, an image too old to trust)
is a FruitRequestError whose text is the reply message, with success False.
"""
from typing import NamedTuple

from fruit_detector_pkg.fruit_detection import FRUITS

# An image older than this (wall-clock seconds since it arrived) no longer shows what the robot sees: the
# simulator or camera has stopped. The camera publishes at 30 Hz of sim time, so even a simulator running at a
# tenth of real time sends a frame every 0.33 s.
STALE_IMAGE_S = 2.0


class FruitRequestError(ValueError):
    """The request cannot be answered; the text says why and what to do."""


class FruitReply(NamedTuple):
    success: bool
    message: str


def fruit_from_request(detect):
    """The fruit named by the request's `detect` field: "apple" or "banana", ignoring case and surrounding
    white space; anything else is a FruitRequestError naming the allowed words."""
    fruit = detect.strip().lower()
    if fruit not in FRUITS:
        raise FruitRequestError("unknown fruit '{}': detect must be {}".format(detect, " or ".join(FRUITS)))
    return fruit


def check_image_age(topic, age_s):
    """FruitRequestError unless an image has arrived on `topic` (age_s None: never) within STALE_IMAGE_S."""
    if age_s is None:
        raise FruitRequestError(
            "no camera image has arrived on {} yet: is the simulator running?".format(topic))
    if age_s > STALE_IMAGE_S:
        raise FruitRequestError(
            "the last camera image on {} arrived {:.1f} s ago: is the simulator still running?".format(topic, age_s))


def reply_for(detection):
    """The FruitReply for a Detection: "<fruit> detected at x=..., y=... (...), in view" or "no <fruit> in view"."""
    if not detection.in_view:
        return FruitReply(False, "no {} in view".format(detection.fruit))
    (cx, cy), box, (width, height) = detection.centroid, detection.box, detection.image_size
    side = "left of" if cx < width / 2 else "right of" if cx > width / 2 else "at"
    return FruitReply(True, "{} detected at x={:.0f}, y={:.0f} ({}x{} px box, {} the centre of the {}x{} image), "
                            "in view".format(detection.fruit, cx, cy, box.width, box.height, side, width, height))
