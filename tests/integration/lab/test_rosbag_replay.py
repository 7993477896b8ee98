"""Recording: `rosbag record` of a demo run and `rosbag play` into a fresh master reproduce every /odom message,
count and content, in order: nothing lost."""
import time

import pytest
import rosbag
import rospy
from tuos_msgs.srv import SetBool

from roslab import RosMaster, wait_for_service, wait_until
from roslab.graph import subscribers
from roslab.probe_node import to_plain


def recorder_subscribed(master_uri):
    """True once a rosbag record node (/record_<id>) is among /odom's subscribers."""
    return any(node.startswith("/record_") for node in subscribers(master_uri, "/odom"))


@pytest.fixture(scope="module")
def recorded_bag(ros_master, tmp_path_factory):
    """A bag of /odom while the demo robot drives forwards for 5 s of sim time."""
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "real_time_factor:=2")
    wait_for_service(ros_master.uri, "/move_service", timeout_s=60)
    bag_path = tmp_path_factory.mktemp("bag") / "demo_run.bag"
    recorder = ros_master.start(["rosbag", "record", "-O", str(bag_path), "/odom"], "rosbag_record")
    wait_until(lambda: recorder_subscribed(ros_master.uri), 30, "rosbag record to subscribe to /odom")
    time.sleep(1.0)
    assert rospy.ServiceProxy("/move_service", SetBool)(True).response_signal is True
    recorder.stop()
    assert bag_path.exists(), "rosbag record did not close the bag on Ctrl-C: " + recorder.output()[-2000:]
    return bag_path


def test_replay_into_a_fresh_master_reproduces_every_odom_message(recorded_bag, tmp_path):
    with rosbag.Bag(str(recorded_bag)) as bag:
        recorded = [to_plain(message) for _, message, _ in bag.read_messages(topics=["/odom"])]
    assert len(recorded) > 100   # 5 s of motion at 30 Hz, and more
    fresh = RosMaster(tmp_path)
    try:
        probe = fresh.probe()
        player = fresh.start(["rosbag", "play", "--wait-for-subscribers", str(recorded_bag)], "rosbag_play")
        probe.subscribe("/odom", "nav_msgs/Odometry", wait_s=30)
        wait_until(lambda: not player.running(), 120, "rosbag play to finish")
        time.sleep(1.0)
        replayed = [entry["msg"] for entry in probe.take("/odom")]
    finally:
        fresh.shutdown()
    assert len(replayed) == len(recorded)
    assert replayed == recorded
