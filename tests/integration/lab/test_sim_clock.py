"""A stuck /use_sim_time: tb3_sim puts the parameter back as it found it when it exits (through its launch file
or rosrun), so a roscore that outlives a TurtleBot3 launch serves wall-clock nodes again; and the lab's nodes say
once, clearly, when /use_sim_time is true and no /clock has come (they would otherwise stand at time 0)."""
import time

import pytest
import rosgraph

from roslab import wait_for_param, wait_for_topic, wait_until

PARAM = "/use_sim_time"
CLOCK_GRACE_WALL_S = 5.0   # sim_clock.watch's


@pytest.fixture
def master_api(ros_master):
    """The module's master with no /use_sim_time before and after each test."""
    api = rosgraph.Master("/test_sim_clock", master_uri=ros_master.uri)
    if api.hasParam(PARAM):
        api.deleteParam(PARAM)
    yield api
    if api.hasParam(PARAM):
        api.deleteParam(PARAM)


def use_sim_time(api):
    return api.getParam(PARAM) if api.hasParam(PARAM) else "unset"


@pytest.mark.parametrize("before", ["unset", False])
def test_tb3_sim_launch_puts_use_sim_time_back(ros_master, master_api, before):
    if before != "unset":
        master_api.setParam(PARAM, before)
    launch = ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "gui:=false", "real_time_factor:=5")
    wait_for_topic(ros_master.uri, "/clock", timeout_s=60)
    assert use_sim_time(master_api) is True
    assert launch.stop() == 0, launch.output()[-2000:]
    assert use_sim_time(master_api) == before, launch.output()[-2000:]
    assert not master_api.hasParam("/gazebo/use_sim_time_before"), "a stale record for the next simulator"


def test_tb3_sim_by_rosrun_puts_use_sim_time_back(ros_master, master_api):
    sim = ros_master.rosrun("tb3_sim", "tb3_sim_node", "_real_time_factor:=5", "_headless:=true", "__name:=gazebo")
    wait_for_topic(ros_master.uri, "/clock", timeout_s=60)
    assert use_sim_time(master_api) is True
    sim.stop()
    assert use_sim_time(master_api) == "unset", sim.output()[-2000:]


@pytest.mark.parametrize("package, executable", [("turtlesim", "turtlesim_node"),
                                                 ("week4_services", "move_server.py")])
def test_a_node_says_once_that_no_clock_comes(ros_master, master_api, package, executable):
    """/use_sim_time left true with no simulator: the node warns once, naming the way out."""
    master_api.setParam(PARAM, True)
    wait_for_param(ros_master.uri, PARAM)
    node = ros_master.rosrun(package, executable, "_headless:=true")
    wait_until(lambda: "no /clock has arrived" in node.output(), 30, f"{executable}'s warning")
    wait_until(lambda: not node.running() or "rosparam set /use_sim_time false" in node.output(), 5, "the hint")
    node.stop()
    assert node.output().count("no /clock has arrived") == 1, node.output()


def test_no_warning_while_the_clock_runs(ros_master, master_api):
    """The warning is for a clock that never came: none beside a running simulator."""
    sim = ros_master.rosrun("tb3_sim", "tb3_sim_node", "_real_time_factor:=5", "_headless:=true", "__name:=gazebo")
    wait_for_topic(ros_master.uri, "/clock", timeout_s=60)
    node = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_until(lambda: "Spawning turtle" in node.output(), 30, "turtlesim to start")
    time.sleep(CLOCK_GRACE_WALL_S + 2)   # wall time: the warning would come CLOCK_GRACE_WALL_S after the start
    node.stop()
    sim.stop()
    assert "no /clock has arrived" not in node.output(), node.output()


def test_a_server_started_before_the_simulator_logs_sim_time(ros_master, master_api):
    """The Week 4 servers wait for the first /clock before their 'ready' line: started beside the simulator (here
    even before it), the line carries the simulator's time, not 0.000000."""
    master_api.setParam(PARAM, True)
    server = ros_master.rosrun("week4_services", "move_server.py")
    sim = ros_master.rosrun("tb3_sim", "tb3_sim_node", "_real_time_factor:=5", "_headless:=true", "__name:=gazebo")
    wait_until(lambda: "service is ready to be called" in server.output(), 60, "the server's ready line")
    ready = next(line for line in server.output().splitlines() if "service is ready to be called" in line)
    server.stop()
    sim.stop()
    assert ", 0.000000]" not in ready, ready
    assert "no /clock has arrived" not in server.output(), server.output()
