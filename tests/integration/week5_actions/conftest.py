"""What the CameraSweep integration tests share (fixture `sweeper`): tb3_sim in colour_search with a 640x480
camera at 2x real time, the action server from its launch file, HOME pointed at a temporary folder for every
process of the module's master (the server saves under HOME), and goals sent and followed through a probe."""
import math
import time

import pytest

from roslab import wait_for_param, wait_for_topic
from roslab.robot_view import RobotView, angle_between

ACTION = "/camera_sweep_action_server"
GOAL, CANCEL = ACTION + "/goal", ACTION + "/cancel"
FEEDBACK, RESULT = ACTION + "/feedback", ACTION + "/result"
WIDTH, HEIGHT = 640, 480
REAL_TIME_FACTOR = "2"
STILL_RADPS = 0.01


@pytest.fixture(scope="module")
def sweeper(ros_master, tmp_path_factory):
    home = tmp_path_factory.mktemp("home")
    ros_master.env["HOME"] = str(home)
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=colour_search", "gui:=false",
                         "real_time_factor:=" + REAL_TIME_FACTOR,
                         "camera_width:={}".format(WIDTH), "camera_height:={}".format(HEIGHT))
    wait_for_param(ros_master.uri, "/use_sim_time")   # before the server and the probe read it
    server = ros_master.roslaunch("week5_actions", "camera_sweep.launch")
    wait_for_topic(ros_master.uri, RESULT, timeout_s=60)
    return Sweeper(ros_master.probe(), server, home)


class Sweeper:
    """Goals, cancels, feedback and results of the action through a probe (its clock is sim time), the
    robot's /odom through a RobotView, the server's process and the HOME folder it saves under."""

    width, height = WIDTH, HEIGHT

    def __init__(self, probe, server, home):
        self.probe = probe
        self.server = server
        self.home = home
        self.view = RobotView(probe)
        probe.subscribe(RESULT, "tuos_msgs/CameraSweepActionResult")
        probe.subscribe(FEEDBACK, "tuos_msgs/CameraSweepActionFeedback")
        self._goals = 0

    def send(self, sweep_angle, image_count):
        """Send a goal; returns its id. Feedback and results of earlier goals are discarded."""
        self._goals += 1
        goal_id = "sweep-{}-{}".format(self._goals, time.monotonic())
        self.probe.take(FEEDBACK)
        self.probe.take(RESULT)
        self.probe.publish(GOAL, "tuos_msgs/CameraSweepActionGoal",
                           {"goal_id": {"id": goal_id}, "goal": {"sweep_angle": sweep_angle,
                                                                 "image_count": image_count}})
        return goal_id

    def cancel(self, goal_id):
        self.probe.publish(CANCEL, "actionlib_msgs/GoalID", {"id": goal_id})

    def result(self, goal_id, timeout_s=60):
        """The result message of goal `goal_id`: {"header", "status": {"status", "text", ...}, "result"}."""
        return self.probe.wait_for_message(RESULT, timeout_s, lambda msg: msg["status"]["goal_id"]["id"] == goal_id)

    def feedback(self, goal_id):
        """The feedback of goal `goal_id` received so far, as (current_image, current_angle) pairs, once."""
        return [(msg["feedback"]["current_image"], msg["feedback"]["current_angle"])
                for msg in (entry["msg"] for entry in self.probe.take(FEEDBACK))
                if msg["status"]["goal_id"]["id"] == goal_id]

    def wait_for_feedback(self, goal_id, image, timeout_s=30):
        """Wait until feedback reports `image` captured; returns that feedback's (current_image, angle)."""
        message = self.probe.wait_for_message(
            FEEDBACK, timeout_s, lambda msg: msg["status"]["goal_id"]["id"] == goal_id
            and msg["feedback"]["current_image"] >= image, interval_s=0.02)
        return message["feedback"]["current_image"], message["feedback"]["current_angle"]

    def odom_after(self, stamp_s, timeout_s=20):
        """The first /odom message stamped at or after `stamp_s` (sim seconds)."""
        return self.probe.wait_for_message("/odom", timeout_s, lambda odom: odom["header"]["stamp"] >= stamp_s)

    @staticmethod
    def turned_deg(before, after):
        """Degrees turned (anticlockwise positive) between two (x, y, yaw) poses."""
        return math.degrees(angle_between(before[2], after[2]))

    @staticmethod
    def is_still(odom):
        twist = odom["twist"]["twist"]
        return abs(twist["angular"]["z"]) < STILL_RADPS and abs(twist["linear"]["x"]) < STILL_RADPS

    def folder(self, image_path):
        """The folder an image_path "~/..." names, under this module's HOME."""
        assert image_path.startswith("~/myrosdata/action_examples/"), image_path
        return self.home / image_path.split(" [")[0][2:]

    def saved_folders(self):
        root = self.home / "myrosdata" / "action_examples"
        return sorted(root.iterdir()) if root.exists() else []
