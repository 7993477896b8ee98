"""The robot picker's logic: which namespaces hold a robot (a publisher of nav_msgs/Odometry on <ns>/odom), and a
pick_robot command validated like the others and refused for a namespace without a robot; the topics and odom
frame the map and navigation displays follow for the picked robot."""
import json

import pytest

from lab_web.commands import ProtocolError, parse_command
from lab_web.panels.map import odom_frame
from lab_web.panels.robots import RobotsPanel, robot_namespaces
from lab_web.ros_context import GraphState, canonical_namespace, own_or_global

ODOMETRY = "nav_msgs/Odometry"


def test_every_namespace_publishing_odometry_on_odom_is_a_robot():
    publishers = [("/tb3_1/odom", ["/tb3_sim"]), ("/tb3_0/odom", ["/tb3_sim"]), ("/odom", ["/tb3_sim"]),
                  ("/tb3_2/odom", []), ("/wheel_odom", ["/a"]), ("/fake/odom", ["/a"]), ("/tb3_0/scan", ["/a"])]
    types = {"/tb3_0/odom": ODOMETRY, "/tb3_1/odom": ODOMETRY, "/odom": ODOMETRY, "/tb3_2/odom": ODOMETRY,
             "/wheel_odom": ODOMETRY, "/fake/odom": "std_msgs/String", "/tb3_0/scan": "sensor_msgs/LaserScan"}
    assert robot_namespaces(publishers, types) == ["/", "/tb3_0", "/tb3_1"]


@pytest.mark.parametrize("given, canonical", [("", ""), ("/", ""), ("tb3_0", "/tb3_0"), ("/tb3_0/", "/tb3_0")])
def test_namespaces_are_joined_without_a_trailing_slash(given, canonical):
    assert canonical_namespace(given) == canonical


class Context:
    """What the robots panel uses of lab_web.ros_context.RosContext."""

    def __init__(self):
        self.namespace = ""
        self.picked = []

    def pick_robot(self, namespace):
        self.picked.append(namespace)
        self.namespace = canonical_namespace(namespace)


def test_a_robot_is_picked_only_among_those_running():
    context = Context()
    panel = RobotsPanel(context)
    panel.on_graph(GraphState([("/tb3_0/odom", ["/sim"]), ("/tb3_1/odom", ["/sim"])], [], [],
                              {"/tb3_0/odom": ODOMETRY, "/tb3_1/odom": ODOMETRY}))
    assert panel.robots.value == {"robots": ["/tb3_0", "/tb3_1"], "picked": "/"}
    command = parse_command(json.dumps({"type": "pick_robot", "namespace": "tb3_1"}), RobotsPanel.COMMANDS)
    panel.handle(None, command.type, command.args)
    assert context.picked == ["/tb3_1"] and panel.robots.value["picked"] == "/tb3_1"
    with pytest.raises(ValueError, match="no robot publishes /tb3_7/odom; the robots are /tb3_0, /tb3_1"):
        panel.handle(None, "pick_robot", {"namespace": "/tb3_7"})
    with pytest.raises(ProtocolError, match="namespace must be a name"):
        parse_command(json.dumps({"type": "pick_robot", "namespace": "../x"}), RobotsPanel.COMMANDS)


def test_a_display_follows_the_robots_own_topic_where_it_is_published_else_the_global_one():
    published = {"/tb3_0/map", "/map", "/particlecloud"}
    assert own_or_global("/tb3_0", "map", published) == "/tb3_0/map"
    assert own_or_global("/tb3_0", "particlecloud", published) == "/particlecloud"
    assert own_or_global("", "map", published) == "/map"
    assert odom_frame("/tb3_0") == "tb3_0/odom" and odom_frame("") == "odom"
