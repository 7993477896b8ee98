"""rviz: tb3_sim publishes the world as a latched MarkerArray, and `rviz -d rviz/tb3_sim.rviz` (under a virtual
display) loads the config and subscribes to the markers, the scan and the camera image; the mapping and navigation
courses' configs load and subscribe to every topic their displays show."""
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


COURSE_CONFIGS = {
    ("turtlebot3_slam", "turtlebot3_gmapping.rviz"): ["/scan", "/map"],
    ("turtlebot3_navigation", "turtlebot3_navigation.rviz"): [
        "/scan", "/map", "/move_base/NavfnROS/plan", "/move_base/global_costmap/costmap",
        "/move_base/DWAPlannerROS/global_plan", "/move_base/local_costmap/footprint",
        "/move_base/local_costmap/costmap", "/move_base/DWAPlannerROS/local_plan", "/particlecloud",
        "/move_base_simple/goal"],
}


def rviz_subscribed(master_uri, topics=("/gazebo/world_markers", "/scan", "/camera/rgb/image_raw")):
    return all(any(node.startswith("/rviz") for node in subscribers(master_uri, topic)) for topic in topics)


def start_rviz(sim, package, config):
    return sim.start(["env", "-u", "QT_QPA_PLATFORM", "xvfb-run", "-a", "-s", "-screen 0 1024x768x24",
                      "rviz", "-d", os.path.join(rospkg.RosPack().get_path(package), "rviz", config)], "rviz")


def test_rviz_loads_the_config_and_subscribes(sim):
    rviz = start_rviz(sim, "tb3_sim", "tb3_sim.rviz")
    wait_until(lambda: rviz_subscribed(sim.uri) or not rviz.running(), 60, "rviz to subscribe")
    assert rviz.running(), rviz.output()[-2000:]
    assert rviz_subscribed(sim.uri)
    rviz.stop()


@pytest.mark.parametrize("package, config", list(COURSE_CONFIGS))
def test_the_courses_rviz_configs_load_with_every_display(sim, package, config):
    """A display missing from the config, or a config rviz cannot read (it would open its default one), leaves
    one of the topics without rviz as a subscriber."""
    topics = COURSE_CONFIGS[package, config]
    rviz = start_rviz(sim, package, config)
    wait_until(lambda: rviz_subscribed(sim.uri, topics) or not rviz.running(), 60, "rviz to subscribe")
    assert rviz.running(), rviz.output()[-2000:]
    rviz.stop()


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
