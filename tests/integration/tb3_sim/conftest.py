"""Fixtures shared by the tb3_sim test modules."""
import pytest

from roslab import RosProcess, stop_together, wait_for_service, wait_for_service_gone, wait_for_topic

SIMULATOR_SERVICE = "/gazebo/get_world_properties"


@pytest.fixture
def launch(ros_master, tmp_path):
    """`launch(*roslaunch_args, robot_topic="/odom", unset=(), **env)` starts `roslaunch <args>` with the module's
    environment minus `unset` plus `env`, and waits until the simulator offers its services and a robot publishes
    `robot_topic` (spawn_model may come after the simulator). Every launch is ended after the test, which waits
    until the simulator has left the master."""
    started = []

    def start(*args, robot_topic="/odom", unset=(), **env):
        environment = {k: v for k, v in ros_master.env.items() if k not in unset}
        environment.update(env)
        process = RosProcess(["roslaunch", "--wait", *args], environment, tmp_path / f"launch{len(started)}.log")
        started.append(process)
        wait_for_service(ros_master.uri, SIMULATOR_SERVICE)
        wait_for_topic(ros_master.uri, robot_topic)
        return process

    yield start
    stop_together(started)
    wait_for_service_gone(ros_master.uri, SIMULATOR_SERVICE)
