"""The launch-file harness of the course-world modules: each module lists its launch files as `CASES`
(world_checks.WorldCase); every case runs once on a master of its own, at REAL_TIME_FACTOR with a small, slow
camera, and the module's tests run against each in turn."""
import pytest

from roslab import RosProcess, private_master, wait_for_service, wait_until
from roslab.launch_args import CHEAP_CAMERA

REAL_TIME_FACTOR = 10
ROBOT_NAME = "turtlebot3_waffle"   # TURTLEBOT3_MODEL=waffle, as the course sets it


def pytest_generate_tests(metafunc):
    if "case" in metafunc.fixturenames:
        cases = metafunc.module.CASES
        metafunc.parametrize("case", cases, ids=[c.id for c in cases], scope="module")


@pytest.fixture(scope="module")
def case_master(case, tmp_path_factory):
    """A master of the case's own (see test_tb3_sim_worlds: one master per world launch)."""
    with private_master(tmp_path_factory.mktemp("ros")) as master:
        yield master


@pytest.fixture(scope="module")
def world(case, case_master, tmp_path_factory):
    """The case's launch file running with TURTLEBOT3_MODEL=waffle, its robot spawned; ended after its tests."""
    env = dict(case_master.env, TURTLEBOT3_MODEL="waffle")
    log = tmp_path_factory.mktemp("launch") / "roslaunch.log"
    process = RosProcess(["roslaunch", "--wait", case.package, case.launch_file, *case.args,
                          f"real_time_factor:={REAL_TIME_FACTOR}", *CHEAP_CAMERA], env, log)
    try:
        wait_for_service(case_master.uri, "/gazebo/get_model_state", timeout_s=60)
        probe = case_master.probe()
        probe.subscribe("/gazebo/model_states", "gazebo_msgs/ModelStates")
        wait_until(lambda: any(ROBOT_NAME in entry["msg"]["name"] for entry in probe.take("/gazebo/model_states")),
                   60, "spawn_model to add the robot")
        yield probe
    finally:
        process.stop()
