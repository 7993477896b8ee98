"""rviz: tb3_sim publishes the world as a latched MarkerArray, and `rviz -d rviz/tb3_sim.rviz` (under a virtual
display) loads the config and subscribes to the markers, the scan and the camera image."""
import os

import pytest
import rospkg

from roslab import wait_for_topic, wait_until
from roslab.graph import subscribers

APPROACH_ARENA_SHAPES = 4 + 3   # four walls, three models


@pytest.fixture(scope="module")
def sim(ros_master):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=approach_arena", "gui:=false")
    wait_for_topic(ros_master.uri, "/gazebo/world_markers", timeout_s=60)
    return ros_master


def test_world_markers_are_latched_and_complete(sim):
    probe = sim.probe()
    probe.subscribe("/gazebo/world_markers", "visualization_msgs/MarkerArray")
    markers = probe.wait_for_message("/gazebo/world_markers")["markers"]
    assert len(markers) == 1 + APPROACH_ARENA_SHAPES + 1
    box = next(marker for marker in markers if marker["text"] == "target_box")
    assert (box["pose"]["position"]["x"], box["scale"]["x"]) == (pytest.approx(1.5), pytest.approx(0.4))


def rviz_subscribed(master_uri):
    return all(any(node.startswith("/rviz") for node in subscribers(master_uri, topic))
               for topic in ["/gazebo/world_markers", "/scan", "/camera/rgb/image_raw"])


def test_rviz_loads_the_config_and_subscribes(sim):
    config = os.path.join(rospkg.RosPack().get_path("tb3_sim"), "rviz", "tb3_sim.rviz")
    rviz = sim.start(["env", "-u", "QT_QPA_PLATFORM", "xvfb-run", "-a", "-s", "-screen 0 1024x768x24",
                      "rviz", "-d", config], "rviz")
    wait_until(lambda: rviz_subscribed(sim.uri) or not rviz.running(), 60, "rviz to subscribe")
    assert rviz.running(), rviz.output()[-2000:]
    assert rviz_subscribed(sim.uri)


def test_turtlebot3_gazebo_rviz_shows_the_robot_model_with_turning_wheels(sim):
    """turtlebot3_gazebo_rviz.launch: robot_state_publisher turns /joint_states into the wheels' TF, and rviz
    (with its RobotModel display) subscribes to the scan."""
    launch = sim.start(["env", "-u", "QT_QPA_PLATFORM", "xvfb-run", "-a", "-s", "-screen 0 1024x768x24",
                        "roslaunch", "--wait", "turtlebot3_gazebo", "turtlebot3_gazebo_rviz.launch", "model:=waffle"],
                       "gazebo_rviz")
    wait_until(lambda: any(n.startswith("/rviz") for n in subscribers(sim.uri, "/scan")) or not launch.running(), 60,
               "rviz to subscribe to /scan")
    assert launch.running(), launch.output()[-2000:]
    probe = sim.probe()
    probe.subscribe("/tf", "tf2_msgs/TFMessage")
    wheel = probe.wait_for_message("/tf", predicate=lambda m: any(
        t["child_frame_id"] == "wheel_left_link" for t in m["transforms"]))
    parents = {t["header"]["frame_id"] for t in wheel["transforms"] if t["child_frame_id"] == "wheel_left_link"}
    assert parents == {"base_link"}
    launch.stop()
