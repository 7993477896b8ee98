"""The fruit detector before the simulator starts, while it runs, and after it stops: success False saying
no image has arrived yet, real answers, then success False saying the last image is too old."""
import time

import rospy
from custom_interfaces.srv import StringServiceMessage

from roslab import wait_for_param, wait_for_service, wait_until

STALE_AFTER_S = 2.0


def detect(word):
    return rospy.ServiceProxy("/detect_fruit_service", StringServiceMessage)(word)


def first_success(word, timeout_s):
    def answered():
        reply = detect(word)
        return reply if reply.success else None
    return wait_until(answered, timeout_s, "a successful answer to {!r}".format(word))


def test_answers_follow_the_camera_coming_and_going(ros_master):
    ros_master.roslaunch("fruit_detector_pkg", "detect_fruit_launch_file.launch")
    wait_for_service(ros_master.uri, "/detect_fruit_service", timeout_s=60)
    reply = detect("apple")
    assert (reply.success, reply.message) == (
        False, "no camera image has arrived on /camera/rgb/image_raw yet: is the simulator running?")
    assert detect("kiwi").message.startswith("unknown fruit 'kiwi'"), "the word is checked first"

    sim = ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=fruit_world", "gui:=false",
                               "camera_width:=320", "camera_height:=240")
    wait_for_param(ros_master.uri, "/use_sim_time")
    assert first_success("banana", timeout_s=60).message.startswith("banana detected at")

    sim.stop()
    time.sleep(STALE_AFTER_S + 0.5)
    reply = detect("banana")
    assert reply.success is False
    assert "arrived" in reply.message and "ago: is the simulator still running?" in reply.message, reply.message
