#!/usr/bin/env python3
"""COM2009 Assignment #1 Part 6 Exercise 2: object detection on one camera frame, saving each step as a picture.

Takes one frame from /camera/rgb/image_raw (waiting up to 10 s), crops its middle (week6_vision.detection_steps),
thresholds the crop in HSV for ~colour (default "blue") and saves step1_original.jpg, step2_cropped.jpg,
step3_mask.jpg and step4_masked.jpg in ~folder (default ~/myrosdata/object_detection), then prints where the
colour is in the crop, and exits. Needs no display: look at the pictures afterwards (e.g. `eog`), or pass
_show:=true to also open them with cv2.imshow when $DISPLAY is set.
"""
import os
from pathlib import Path

import cv2
import rospy
from sensor_msgs.msg import Image

from week6_vision.colour_masks import UnknownColour, colour_name
from week6_vision.detection_steps import detect
from week6_vision.ros_node import CAMERA_TOPIC, bgr_image

FRAME_TIMEOUT_S = 10.0


def main():
    rospy.init_node("object_detection")
    folder = Path(os.path.expanduser(rospy.get_param("~folder", "~/myrosdata/object_detection")))
    try:
        colour = colour_name(rospy.get_param("~colour", "blue"))
        image = bgr_image(rospy.wait_for_message(CAMERA_TOPIC, Image, timeout=FRAME_TIMEOUT_S))
        folder.mkdir(parents=True, exist_ok=True)
    except (UnknownColour, OSError) as error:
        rospy.logerr(f"Object detection: {error}")
        return
    except rospy.ROSException:
        rospy.logerr(f"Object detection: no image on {CAMERA_TOPIC} within {FRAME_TIMEOUT_S:.0f} s")
        return
    if image is None:
        return
    steps = detect(image, colour)
    for stem, picture in steps.images().items():
        path = folder / f"{stem}.jpg"
        if not cv2.imwrite(str(path), picture):
            rospy.logerr(f"Object detection: cannot write {path}")
            return
        rospy.loginfo(f"Saved {path}")
    if steps.centroid is None:
        rospy.loginfo(f"No {colour} object in the cropped image.")
    else:
        rospy.loginfo(f"The {colour} object is at x={steps.centroid[0]:.0f}, y={steps.centroid[1]:.0f} "
                      f"of the {steps.cropped.shape[1]}x{steps.cropped.shape[0]} cropped image.")
    if rospy.get_param("~show", False) and os.environ.get("DISPLAY"):
        for stem, picture in steps.images().items():
            cv2.imshow(stem, picture)
        cv2.waitKey(0)
        cv2.destroyAllWindows()


if __name__ == "__main__":
    main()
