"""What the Week 5 integration tests share: tb3_sim in colour_search with a 640x480 camera at 2x real time, the
CameraSweep server from its launch file (fixture `sweeper`) and the Search server from its own (fixture
`searcher`, on the same master and simulator), HOME pointed at a temporary folder for every process of the
module's master (the sweep server saves under HOME), and goals sent and followed through a probe."""
import math
import time

import pytest

from roslab import wait_for_param, wait_for_topic
from roslab.robot_view import RobotView, angle_between

ACTION = "/camera_sweep_action_server"
SEARCH_ACTION = "/search_action_server"
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
    wait_for_topic(ros_master.uri, ACTION + "/result", timeout_s=60)
    return Sweeper(ros_master.probe(), server, home)


@pytest.fixture(scope="module")
def searcher(ros_master, sweeper):
    """The Search server beside the sweep server: goals through a GoalChannel, the robot through the sweeper."""
    ros_master.roslaunch("week5_actions", "search.launch")
    wait_for_topic(ros_master.uri, SEARCH_ACTION + "/result", timeout_s=60)
    return GoalChannel(sweeper.probe, SEARCH_ACTION, "tuos_msgs/Search")


class GoalChannel:
    """One action's goals, cancels, feedback and results through a probe (its clock is sim time)."""

    def __init__(self, probe, action, action_type):
        self.probe = probe
        self.action, self.type = action, action_type
        self.feedback_topic, self.result_topic = action + "/feedback", action + "/result"
        probe.subscribe(self.result_topic, action_type + "ActionResult")
        probe.subscribe(self.feedback_topic, action_type + "ActionFeedback")
        self._goals = 0

    def send(self, **goal):
        """Send a goal; returns its id. Feedback and results of earlier goals are discarded."""
        self._goals += 1
        goal_id = "{}-{}-{}".format(self.action.strip("/"), self._goals, time.monotonic())
        self.probe.take(self.feedback_topic)
        self.probe.take(self.result_topic)
        self.probe.publish(self.action + "/goal", self.type + "ActionGoal", {"goal_id": {"id": goal_id}, "goal": goal})
        return goal_id

    def cancel(self, goal_id):
        self.probe.publish(self.action + "/cancel", "actionlib_msgs/GoalID", {"id": goal_id})

    def result(self, goal_id, timeout_s=60):
        """The result message of goal `goal_id`: {"header", "status": {"status", "text", ...}, "result"}."""
        return self.probe.wait_for_message(self.result_topic, timeout_s,
                                           lambda msg: msg["status"]["goal_id"]["id"] == goal_id)

    def feedback(self, goal_id):
        """The feedback fields of goal `goal_id` received so far, in order, once."""
        return [msg["feedback"] for msg in (entry["msg"] for entry in self.probe.take(self.feedback_topic))
                if msg["status"]["goal_id"]["id"] == goal_id]

    def wait_for_feedback(self, goal_id, predicate, timeout_s=30):
        """Wait for a feedback of goal `goal_id` whose fields satisfy `predicate`; returns those fields."""
        message = self.probe.wait_for_message(
            self.feedback_topic, timeout_s, lambda msg: msg["status"]["goal_id"]["id"] == goal_id
            and predicate(msg["feedback"]), interval_s=0.02)
        return message["feedback"]


class Sweeper:
    """The CameraSweep action's goals through a GoalChannel, the robot's /odom through a RobotView, the server's
    process and the HOME folder it saves under."""

    width, height = WIDTH, HEIGHT

    def __init__(self, probe, server, home):
        self.probe = probe
        self.server = server
        self.home = home
        self.view = RobotView(probe)
        self.goals = GoalChannel(probe, ACTION, "tuos_msgs/CameraSweep")

    def send(self, sweep_angle, image_count):
        """Send a goal; returns its id. Feedback and results of earlier goals are discarded."""
        return self.goals.send(sweep_angle=sweep_angle, image_count=image_count)

    def cancel(self, goal_id):
        self.goals.cancel(goal_id)

    def result(self, goal_id, timeout_s=60):
        return self.goals.result(goal_id, timeout_s)

    def feedback(self, goal_id):
        """The feedback of goal `goal_id` received so far, as (current_image, current_angle) pairs, once."""
        return [(fields["current_image"], fields["current_angle"]) for fields in self.goals.feedback(goal_id)]

    def wait_for_feedback(self, goal_id, image, timeout_s=30):
        """Wait until feedback reports `image` captured; returns that feedback's (current_image, angle)."""
        fields = self.goals.wait_for_feedback(goal_id, lambda fields: fields["current_image"] >= image, timeout_s)
        return fields["current_image"], fields["current_angle"]

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
