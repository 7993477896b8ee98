"""`roslaunch turtlebot3_description turtlebot3_model.launch` (under a virtual display): the model from
TURTLEBOT3_MODEL or waffle when it is unset, joint_state_publisher and robot_state_publisher giving every link a
TF frame, and rviz loading rviz/model.rviz and staying up; model:= and multi_robot_name:= as in the original."""
import re
import time
import warnings

import pytest
import rosgraph

from roslab import RosProcess, stop_together, wait_for_param, wait_until
from roslab.graph import node_pid, subscribers

STAYS_UP_S = 5.0
TF_ECHO_DECIMALS = 0.0011
RVIZ_SEGFAULT = re.compile(r"\[rviz-\d+\] process has died \[pid \d+, exit code -11\b")


@pytest.fixture
def model_launch(ros_master, tmp_path):
    """start(*args, stays_up_s=0): turtlebot3_model.launch with `args` under xvfb-run, TURTLEBOT3_MODEL unset,
    returned once rviz has subscribed and then stayed up `stays_up_s`; ended after the test.

    rviz draws here with Debian 12's Mesa software renderer (llvmpipe) in Xvfb, which on a loaded machine
    segfaults now and then within rviz's first seconds: in 1 of 48 starts when the rviz test modules ran in a
    loop on three workers, and in 2 of 33 fresh-clone runs of the suite. Its core dump shows a pointer inside
    swrast_dri.so overwritten with rendered pixels (0xff303030, rviz's background colour). Such a start is
    launched once more, with a warning in the test summary; a second segfault, or rviz exiting any other way,
    fails the test."""
    started = []

    def launch(args, stays_up_s):
        # A previous test's parameters stay on the master, as after any roslaunch.
        master = rosgraph.Master("/test", master_uri=ros_master.uri)
        if master.hasParam("/robot_description"):
            master.deleteParam("/robot_description")
        env = {k: v for k, v in ros_master.env.items() if k not in ("TURTLEBOT3_MODEL", "QT_QPA_PLATFORM")}
        command = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", "roslaunch", "--wait", "turtlebot3_description",
                   "turtlebot3_model.launch", *args]
        process = RosProcess(command, env, tmp_path / "model{}.log".format(len(started)))
        started.append(process)
        wait_until(lambda: rviz_subscribed(ros_master.uri) or rviz_segfault(process) or not process.running(), 90,
                   "rviz to subscribe")
        if not rviz_segfault(process):
            time.sleep(stays_up_s)
        return process

    def start(*args, stays_up_s=0.0):
        process = launch(args, stays_up_s)
        crash = rviz_segfault(process)
        if crash:
            warnings.warn("rviz segfaulted in Mesa's software renderer and was launched again: " + crash.group(0))
            process.stop()
            process = launch(args, stays_up_s)
        assert process.running() and not rviz_segfault(process), process.output()[-3000:]
        return process

    yield start
    stop_together(started)


def rviz_segfault(launch):
    """roslaunch's line reporting that rviz was killed by SIGSEGV (exit code -11), or None."""
    return RVIZ_SEGFAULT.search(launch.output())


def rviz_subscribed(master_uri):
    """A running rviz has loaded model.rviz: its LaserScan display subscribes to /scan. (The master may still
    list an rviz that a previous test ended, until the new one registers under the same name.)"""
    return any(node.startswith("/rviz") and responds(master_uri, node) for node in subscribers(master_uri, "/scan"))


def responds(master_uri, node):
    try:
        return node_pid(master_uri, node) > 0
    except (OSError, RuntimeError, rosgraph.MasterError):
        return False


def robot_description(master_uri):
    return rosgraph.Master("/test", master_uri=master_uri).getParam("/robot_description")


def test_default_model_is_waffle_and_everything_stays_up(model_launch, ros_master, tf_echo):
    model_launch(stays_up_s=STAYS_UP_S)   # fails unless the launch and its rviz are still up after it
    assert '<robot name="turtlebot3_waffle"' in robot_description(ros_master.uri)
    for node in ("/rviz", "/robot_state_publisher", "/joint_state_publisher"):
        assert responds(ros_master.uri, node), node
    # The wheel frames need joint_state_publisher's /joint_states: robot_state_publisher publishes them on /tf.
    translation, _ = tf_echo("base_footprint", "wheel_left_link")
    assert translation == pytest.approx((0.0, 0.144, 0.033), abs=TF_ECHO_DECIMALS)


def test_model_and_multi_robot_name_args(model_launch, ros_master, tf_echo):
    model_launch("model:=burger", "multi_robot_name:=tb3_1")
    wait_for_param(ros_master.uri, "/robot_description")
    assert '<robot name="turtlebot3_burger"' in robot_description(ros_master.uri)
    translation, _ = tf_echo("tb3_1/base_footprint", "tb3_1/base_scan")
    assert translation == pytest.approx((-0.032, 0.0, 0.182), abs=TF_ECHO_DECIMALS)
