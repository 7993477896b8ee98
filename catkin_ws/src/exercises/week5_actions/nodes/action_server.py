#!/usr/bin/env python3
"""COM2009 Week 5: the CameraSweep action server (node camera_sweep_action_server, action
/camera_sweep_action_server, type tuos_msgs/CameraSweep).

A goal asks for `image_count` images over a `sweep_angle` degree turn. The robot turns anticlockwise on the spot
at ~angular_speed (default 0.4 rad/s; at most 1.82) and, each time the angle turned (measured from /odom, unwrapped)
reaches the next capture angle (sweep_angle * k / image_count, k = 1..image_count), saves the latest image from
/camera/rgb/image_raw/compressed (sensor_msgs/CompressedImage, decoded with cv_bridge) as
~/myrosdata/action_examples/<YYYYMMDD_HHMMSS>/imgNNN.jpg and publishes feedback: current_image (images saved so
far) and current_angle (degrees turned so far). The robot stops as soon as it has turned sweep_angle, and the
goal succeeds with image_path = that folder ("~/..."). Each image is the newest frame when its angle is reached,
at most one camera period (1/30 s of sim time, 0.8 degrees at 0.4 rad/s) old; captures closer together than
that can repeat a frame.

Refused at once, without motion, as aborted with image_path "None [ABORTED: <reason>]" (the reason also in the
status text and the log): image_count outside 1..50, sweep_angle outside (0, 180] degrees, NaN. See
week5_actions.sweep_plan and week5_actions.image_folder for these choices.
Cancelled (or replaced by a new goal): the robot stops at once and the goal ends preempted with image_path
"<folder> [PRE-EMPTED at image k of n]"; the k images saved so far stay.
Aborted with the reason: no camera image within 5 s of the goal or none for 2 s during the sweep, /odom silent
for 1 s (the simulator died), the sweep taking more than twice its ideal time plus 5 s, or a file that cannot be
written. The robot is stopped (zero Twist) whenever a goal ends, however it ends, and when the node shuts down
(Ctrl-C; a running goal then ends aborted: "the action server is shutting down").
All robot timing is rospy time (sim time under tb3_sim); the camera and /odom watchdogs use the wall clock.
"""
import datetime
import sys
import threading
import time
from pathlib import Path

import actionlib
import cv2
import rospy
from cv_bridge import CvBridge, CvBridgeError
from sensor_msgs.msg import CompressedImage
from tuos_msgs.msg import CameraSweepAction, CameraSweepFeedback, CameraSweepResult

from tb3_client.motion import MAX_ANGULAR_RADPS, InvalidRequest, check_speed
from tb3_client.robot import Robot, RobotError
from week5_actions.heading import HeadingTracker, yaw_from_quaternion
from week5_actions.image_folder import (
    aborted_text,
    display_path,
    image_file_name,
    new_sweep_folder,
    preempted_text,
)
from week5_actions.sweep_plan import DEFAULT_ANGULAR_SPEED_RADPS, InvalidGoal, SweepFailed, plan_sweep

NODE_NAME = "camera_sweep_action_server"
ACTION_NAME = "/camera_sweep_action_server"
CAMERA_TOPIC = "/camera/rgb/image_raw/compressed"
FIRST_IMAGE_GRACE_S = 5.0    # wall seconds a goal waits for the first camera image (the camera is lazy)
STALE_IMAGE_S = 2.0          # wall seconds without a new image after which the camera counts as stopped
IMAGE_BUFFER_BYTES = 2 ** 24
LAST_FEEDBACK_LEAD_S = 0.1   # sim seconds between the last feedback and the result (see on_goal)


class Sweep:
    """One goal's progress: its plan, folder, images saved and angle turned (degrees)."""

    def __init__(self, plan):
        self.plan = plan
        self.folder = None
        self.folder_text = None
        self.captured = 0
        self.turned_deg = 0.0
        self.preempted = False


class CameraSweepServer:
    def __init__(self, angular_speed):
        self.angular_speed = angular_speed
        self.bridge = CvBridge()
        self.latest_image = None   # (CompressedImage, time.monotonic() of its arrival)
        self.image_arrived = threading.Event()
        self.robot = Robot()
        self.camera = rospy.Subscriber(CAMERA_TOPIC, CompressedImage, self.on_image, queue_size=1,
                                       buff_size=IMAGE_BUFFER_BYTES)
        self.server = actionlib.SimpleActionServer(ACTION_NAME, CameraSweepAction, self.on_goal, auto_start=False)
        self.server.start()
        rospy.on_shutdown(self.on_shutdown)
        rospy.loginfo("The '%s' action server is ready (turning at %.2f rad/s).", ACTION_NAME, angular_speed)

    def on_image(self, image):
        self.latest_image = (image, time.monotonic())
        self.image_arrived.set()

    def on_goal(self, goal):
        try:
            plan = plan_sweep(goal.sweep_angle, goal.image_count, self.angular_speed)
        except InvalidGoal as error:
            self.abort(aborted_text(error))
            return
        rospy.loginfo("Goal: %d images over a %.1f degree sweep, one every %.1f degrees, about %.1f s...",
                      plan.image_count, plan.sweep_angle_deg, plan.step_deg, plan.ideal_duration_s)
        sweep = Sweep(plan)
        started = rospy.get_rostime()
        try:
            with self.robot.exclusive():
                self.wait_for_first_image()
                sweep.folder = new_sweep_folder(Path.home(), datetime.datetime.now())
                sweep.folder_text = display_path(sweep.folder, Path.home())
                self.turn_and_capture(sweep)
        except (RobotError, SweepFailed, OSError) as error:
            self.abort(aborted_text(error, sweep.folder_text, sweep.captured))
            return
        if sweep.preempted:
            text = preempted_text(sweep.folder_text, sweep.captured, plan.image_count)
            rospy.logwarn("Sweep cancelled after %d of %d images (%.1f degrees): %s", sweep.captured,
                          plan.image_count, sweep.turned_deg, text)
            self.server.set_preempted(CameraSweepResult(text), "cancelled after {} of {} images".format(
                sweep.captured, plan.image_count))
            return
        rospy.loginfo("Sweep complete: %.1f degrees, %d images in %s, %.1f s.", sweep.turned_deg, sweep.captured,
                      sweep.folder_text, (rospy.get_rostime() - started).to_sec())
        # Feedback and result reach the client on two connections: a short pause lets the last feedback arrive
        # first, so a client prints every image's line before the result (SimpleActionClient drops feedback that
        # comes after it).
        rospy.sleep(LAST_FEEDBACK_LEAD_S)
        self.server.set_succeeded(CameraSweepResult(sweep.folder_text), "{} images saved".format(sweep.captured))

    def abort(self, text):
        """End the current goal as aborted, with `text` as image_path and status text (unless it has ended
        already: on shutdown the hook below and the goal's own thread both try)."""
        if self.server.is_active():
            rospy.logwarn("Goal aborted: %s", text)
            self.server.set_aborted(CameraSweepResult(text), text)

    def on_shutdown(self):
        """Ctrl-C: the robot stops (tb3_client.Robot's own hook) and a running goal ends aborted, so that its
        client hears why instead of waiting for ever."""
        self.abort(aborted_text("the action server is shutting down"))

    def wait_for_first_image(self):
        if not self.image_arrived.wait(FIRST_IMAGE_GRACE_S):
            raise SweepFailed("no image on {} within {:.0f} s: is the simulator running?".format(
                CAMERA_TOPIC, FIRST_IMAGE_GRACE_S))

    def turn_and_capture(self, sweep):
        """Turn, capturing at each capture angle, until every image is saved, the goal is cancelled (robot
        stopped at once) or something fails (SweepFailed, RobotError)."""
        plan = sweep.plan
        heading = HeadingTracker(self.yaw())
        started = rospy.get_rostime()
        self.robot.drive(0.0, plan.angular_speed_radps)
        while sweep.captured < plan.image_count:
            if self.server.is_preempt_requested():
                self.robot.stop()
                sweep.preempted = True
                return
            if (rospy.get_rostime() - started).to_sec() > plan.time_limit_s:
                raise SweepFailed("the robot turned only {:.1f} of {:.1f} degrees in {:.0f} s: is it blocked?".format(
                    sweep.turned_deg, plan.sweep_angle_deg, plan.time_limit_s))
            self.robot.wait_for_update()
            sweep.turned_deg = heading.update(self.yaw())
            if sweep.turned_deg >= plan.capture_angles_deg[-1]:
                self.robot.stop()
            while sweep.captured < plan.image_count and sweep.turned_deg >= plan.capture_angles_deg[sweep.captured]:
                self.capture(sweep)

    def capture(self, sweep):
        """Save the newest camera image as the next image of the sweep and publish the feedback."""
        image_message, arrived = self.latest_image
        if time.monotonic() - arrived > STALE_IMAGE_S:
            raise SweepFailed("no image on {} for {:.0f} s: has the camera stopped?".format(
                CAMERA_TOPIC, STALE_IMAGE_S))
        number = sweep.captured + 1
        path = sweep.folder / image_file_name(number)
        self.save(image_message, path)
        sweep.captured = number
        rospy.loginfo("Captured image %d of %d at %.1f degrees: %s", number, sweep.plan.image_count,
                      sweep.turned_deg, path.name)
        self.server.publish_feedback(CameraSweepFeedback(current_image=number, current_angle=sweep.turned_deg))

    def save(self, image_message, path):
        try:
            image = self.bridge.compressed_imgmsg_to_cv2(image_message)
        except CvBridgeError as error:
            raise SweepFailed("could not decode the camera image: {}".format(error)) from error
        if image is None:
            raise SweepFailed("could not decode the camera image (format '{}')".format(image_message.format))
        if not cv2.imwrite(str(path), image):
            raise SweepFailed("could not write {}".format(path))

    def yaw(self):
        q = self.robot.odom.pose.pose.orientation
        return yaw_from_quaternion(q.x, q.y, q.z, q.w)


def main():
    rospy.init_node(NODE_NAME)
    speed = rospy.get_param("~angular_speed", DEFAULT_ANGULAR_SPEED_RADPS)
    try:
        angular_speed = check_speed("~angular_speed", speed, MAX_ANGULAR_RADPS)
    except (InvalidRequest, TypeError):
        rospy.logfatal("~angular_speed %r must be a number of rad/s in (0, %s]", speed, MAX_ANGULAR_RADPS)
        sys.exit(1)
    CameraSweepServer(angular_speed)
    rospy.spin()


if __name__ == "__main__":
    main()
