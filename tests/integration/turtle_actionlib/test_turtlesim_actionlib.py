"""turtle_actionlib on the turtlesim replica: shape_server's action interface, a preempted goal, and
shape_client's pentagon finishing SUCCEEDED with the original's result."""
import math

import pytest
import rosgraph
import rospy
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_for_topic, wait_until

CENTRE = 5.544444561004639
POSE = "/turtle1/pose"
RESULT = "/turtle_shape/result"
PREEMPTED, SUCCEEDED = 2, 3


def master_api(master):
    return rosgraph.Master("/turtlesim_test", master_uri=master.uri)


@pytest.fixture(scope="module")
def shape_server(ros_master, probe):
    ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_for_service(ros_master.uri, "/reset")
    server = ros_master.rosrun("turtle_actionlib", "shape_server")
    wait_for_topic(ros_master.uri, RESULT)
    probe.subscribe(RESULT, "turtle_actionlib/ShapeActionResult")
    probe.subscribe(POSE, "turtlesim/Pose")
    return server


def test_action_topics_are_under_the_nodes_resolved_name(ros_master, shape_server):
    types = dict(master_api(ros_master).getTopicTypes())
    assert {name: types.get("/turtle_shape/" + name) for name in
            ("goal", "cancel", "status", "feedback", "result")} == {
        "goal": "turtle_actionlib/ShapeActionGoal", "cancel": "actionlib_msgs/GoalID",
        "status": "actionlib_msgs/GoalStatusArray", "feedback": "turtle_actionlib/ShapeActionFeedback",
        "result": "turtle_actionlib/ShapeActionResult"}
    publishers, subscribers, _ = master_api(ros_master).getSystemState()
    assert "/turtle_shape" in dict(subscribers)["/turtle1/pose"]
    assert "/turtle_shape" in dict(publishers)["/turtle1/cmd_vel"]


def test_cancel_preempts_the_goal(ros_master, shape_server, probe):
    probe.publish("/turtle_shape/goal", "turtle_actionlib/ShapeActionGoal",
                  {"goal_id": {"id": "square-to-cancel"}, "goal": {"edges": 4, "radius": 1.0}})
    probe.take(POSE)
    probe.wait_for_message(POSE, 10, lambda pose: pose["linear_velocity"] > 0)
    probe.publish("/turtle_shape/cancel", "actionlib_msgs/GoalID", {"id": "square-to-cancel"})
    result = probe.wait_for_message(RESULT, 10)
    assert (result["status"]["goal_id"]["id"], result["status"]["status"]) == ("square-to-cancel", PREEMPTED)
    wait_until(lambda: "/turtle_shape: Preempted" in shape_server.output(), 5, "the Preempted log line")


@pytest.mark.realtime   # turtlesim moves in wall time: the shape closes only if the server's timing holds
def test_shape_client_finishes_the_pentagon(ros_master, shape_server, probe):
    rospy.ServiceProxy("/reset", Empty)()
    probe.take(RESULT)
    client = ros_master.rosrun("turtle_actionlib", "shape_client")
    assert client.popen.wait(timeout=60) == 0
    output = client.log_path.read_text()
    assert "Action server started, sending goal." in output
    assert "Action finished: SUCCEEDED" in output
    result = probe.wait_for_message(RESULT, 5)
    assert result["status"]["status"] == SUCCEEDED
    assert result["result"] == {"interior_angle": pytest.approx(1.884955, abs=1e-6),
                                "apothem": pytest.approx(1.051722, abs=1e-6)}
    assert "/turtle_shape: Succeeded" in shape_server.output()
    probe.take(POSE)
    final = probe.wait_for_message(POSE, 5)
    assert math.hypot(final["x"] - CENTRE, final["y"] - CENTRE) < 0.01, "the pentagon closes"
