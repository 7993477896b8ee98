"""beginner_tutorials' scan service (my_service) against tb3_sim: a box placed at a known bearing is reported
at that index, and a bad index is an error that leaves the server serving."""
import subprocess

import pytest
import rospy

from beginner_tutorials.srv import gazebo_server
from roslab import wait_for_service, wait_for_topic, wait_until

BOX_SIZE_M = 0.3
BOX_Y_M = 1.0
SCAN_X_M = -0.064          # base_scan sits 6.4 cm behind base_footprint
NOISE_TOLERANCE_M = 0.04   # 4 sigma of the simulated LiDAR noise


@pytest.fixture(scope="module")
def my_service(ros_master):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "gui:=false", "real_time_factor:=2")
    wait_for_topic(ros_master.uri, "/scan", timeout_s=60)
    spawn = subprocess.run(["rosrun", "tb3_sim", "spawn_box", "left_box", str(SCAN_X_M), str(BOX_Y_M),
                            "--size", str(BOX_SIZE_M)], env=ros_master.env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=60)
    assert spawn.returncode == 0, spawn.stdout
    ros_master.rosrun("beginner_tutorials", "scan_server.py")
    wait_for_service(ros_master.uri, "/my_service")
    call = rospy.ServiceProxy("/my_service", gazebo_server)

    def has_a_scan():
        try:
            return call(0) is not None
        except rospy.ServiceException as error:
            assert "no /scan message received yet" in str(error)
            return False
    wait_until(has_a_scan, 20, "scan_server's first /scan")
    return call


def test_box_to_the_left_is_seen_at_index_90(my_service):
    expected = BOX_Y_M - BOX_SIZE_M / 2
    assert my_service(90).distance == pytest.approx(expected, abs=NOISE_TOLERANCE_M)


def test_nothing_ahead_is_inf(my_service):
    assert my_service(0).distance == float("inf")


def test_bad_index_is_an_error_and_the_server_keeps_serving(my_service):
    with pytest.raises(rospy.ServiceException, match="direction must be an index from 0 to 359"):
        my_service(400)
    assert my_service(90).distance < 1.0
