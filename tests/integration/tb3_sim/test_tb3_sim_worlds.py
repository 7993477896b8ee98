"""`roslaunch turtlebot3_gazebo turtlebot3_house.launch` and turtlebot3_stage_1..4.launch start tb3_sim in the
original's world: the world's models and the robot carry the original's names, the robot stands at the original's
spawn defaults, /scan reads the walls (and pillars, and table legs) where the original's SDF puts them, and the
robot answers /cmd_vel.

Expected ranges are worked out here from the SDF numbers: a beam i points i x 6.28319/359 rad from base_scan's +x,
base_scan is 6.4 cm behind base_footprint, and a hit at 3.5 m or more reads inf. Each world is launched once (gui off,
4x real time) on this module's master and ended after its tests."""
import math
import statistics

import pytest
import rospy
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from std_srvs.srv import Empty

from roslab import RosProcess, private_master, wait_for_service, wait_until

SCAN_X_M = -0.064
ANGLE_INCREMENT_RAD = 6.28319 / 359
RANGE_MAX_M = 3.5
SCANS_AVERAGED = 5          # the scan's noise has sigma 0.01 m; five scans make 2 cm a wide margin
TOLERANCE_M = 0.02
HALF_WALL_M = 0.15 / 2      # every wall box of the house, the square and the plaza is 0.15 m thick
REAL_TIME_FACTOR = 4


def to_x(x):
    """A wall face at world x = `x` (each beam below meets its wall within the wall's length, as the SDF places it)."""
    return ("x", x)


def to_y(y):
    return ("y", y)


def to_circle(x, y, radius):
    return ("circle", x, y, radius)


def expected_range(origin, beam, target):
    """Noise-free reading of `beam` from the LiDAR at `origin` (x, y; the robot faces +x) on `target`."""
    angle = beam * ANGLE_INCREMENT_RAD
    dx, dy = math.cos(angle), math.sin(angle)
    if target[0] == "x":
        distance = (target[1] - origin[0]) / dx
    elif target[0] == "y":
        distance = (target[1] - origin[1]) / dy
    else:
        _, cx, cy, radius = target
        vx, vy = cx - origin[0], cy - origin[1]
        along = vx * dx + vy * dy
        miss = vx * dy - vy * dx
        distance = along - math.sqrt(radius ** 2 - miss ** 2)
    assert distance > 0
    return distance if distance < RANGE_MAX_M else math.inf


SQUARE_INNER = 1.925 - HALF_WALL_M            # turtlebot3_square: walls at +-1.925
SQUARE_BEAMS = {0: to_x(SQUARE_INNER), 90: to_y(SQUARE_INNER), 180: to_x(-SQUARE_INNER), 270: to_y(-SQUARE_INNER)}
PILLAR_BEAMS = {42: to_circle(0.6, 0.6, 0.15), 131: to_circle(-0.6, 0.6, 0.15)}   # the stage_2/_3 pillars

# world: (spawn (x, y) = the launch defaults, static model, world models, the original's robot name, beams)
WORLDS = {
    "turtlebot3_house": ((-3.0, 1.0), "turtlebot3_house", [], "turtlebot3", {
        0: to_x(-0.05 - HALF_WALL_M),                    # Wall_101, x = -0.05
        90: to_y(5.275 - HALF_WALL_M),                   # Wall_83, y = 5.275: 4.2 m away, beyond range
        104: to_circle(-2.65728 - 0.68, 2.42376 - 0.38, 0.02),   # a leg of the table at (-2.65728, 2.42376)
        180: to_x(-5.15 + HALF_WALL_M),                  # Wall_99, x = -5.15
        270: to_y(-0.17488 + HALF_WALL_M),               # Wall_108, y = -0.17488 (the 1 m half-wall)
    }),
    "turtlebot3_stage_1": ((0.0, 0.0), "turtlebot3_square", [], "turtlebot3_burger", SQUARE_BEAMS),
    "turtlebot3_stage_2": ((0.0, 0.0), "turtlebot3_square", [], "turtlebot3_burger", {**SQUARE_BEAMS, **PILLAR_BEAMS}),
    "turtlebot3_stage_3": ((0.0, 0.0), "turtlebot3_square", [], "turtlebot3_burger", {**SQUARE_BEAMS, **PILLAR_BEAMS}),
    "turtlebot3_stage_4": ((-0.7, 0.0), "turtlebot3_plaza", ["obstacle_1", "obstacle_2"], "turtlebot3_burger", {
        0: to_x(0.204 - HALF_WALL_M),                    # Wall_21, x = 0.204
        90: to_y(1.548 - HALF_WALL_M),                   # Wall_7, y = 1.548
        180: to_x(-1.502 + HALF_WALL_M),                 # Wall_9, x = -1.502
        270: to_y(-2.425 + HALF_WALL_M),                 # Wall_4, y = -2.425
    }),
}


@pytest.fixture(scope="module", params=sorted(WORLDS))
def world_master(request, tmp_path_factory):
    """(world name, a master of the world's own). With one master for all worlds, the master once sent an XML-RPC
    update meant for a node of the previous world to the port that node had used, which the new simulator's TCPROS
    server had been given meanwhile; rospy's server read the request as a connection header and stopped accepting
    connections."""
    with private_master(tmp_path_factory.mktemp("ros")) as master:
        yield request.param, master


@pytest.fixture(scope="module")
def world(world_master, tmp_path_factory):
    """One world's launch file running with TURTLEBOT3_MODEL=waffle, its robot spawned; ended after its tests."""
    name, ros_master = world_master
    env = dict(ros_master.env, TURTLEBOT3_MODEL="waffle")
    log = tmp_path_factory.mktemp("launch") / f"{name}.log"
    process = RosProcess(["roslaunch", "--wait", "turtlebot3_gazebo", f"{name}.launch", "gui:=false",
                          f"real_time_factor:={REAL_TIME_FACTOR}"], env, log)
    try:
        wait_for_service(ros_master.uri, "/gazebo/get_world_properties", timeout_s=60)
        wait_until(lambda: robot_names(name), 60, "spawn_model to add the robot")
        yield name
    finally:
        process.stop()


@pytest.fixture(scope="module")
def probe(world_master):
    """A probe node on the world's own master."""
    return world_master[1].probe()


def model_names():
    return list(rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)().model_names)


def robot_names(world):
    """The models that are not the ground plane nor part of `world`."""
    _, static_model, models, _, _ = WORLDS[world]
    return [n for n in model_names() if n not in ["ground_plane", static_model, *models]]


def fresh_messages(probe, topic, msg_type, count):
    """The next `count` messages on `topic` (earlier ones are dropped)."""
    probe.subscribe(topic, msg_type)
    probe.take(topic)
    messages = []

    def enough():
        messages.extend(entry["msg"] for entry in probe.take(topic))
        return len(messages) >= count
    wait_until(enough, 30, f"{count} messages on {topic}")
    return messages[:count]


def odom_position(message):
    position = message["pose"]["pose"]["position"]
    return position["x"], position["y"]


def test_models_are_the_originals_and_the_robot_stands_at_the_launch_defaults(world):
    spawn, static_model, models, robot, _ = WORLDS[world]
    assert model_names() == ["ground_plane", static_model, *models, robot]
    reply = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)(model_name=robot, relative_entity_name="")
    assert reply.success, reply.status_message
    assert (reply.pose.position.x, reply.pose.position.y) == pytest.approx(spawn, abs=1e-3)


def test_scan_beams_read_the_original_geometry(world, probe):
    spawn, _, _, _, beams = WORLDS[world]
    origin = (spawn[0] + SCAN_X_M, spawn[1])
    scans = fresh_messages(probe, "/scan", "sensor_msgs/LaserScan", SCANS_AVERAGED)
    for beam, target in sorted(beams.items()):
        readings = [float(scan["ranges"][beam]) for scan in scans]
        expected = expected_range(origin, beam, target)
        if math.isinf(expected):
            assert all(math.isinf(r) for r in readings), (beam, readings)
        else:
            assert statistics.mean(readings) == pytest.approx(expected, abs=TOLERANCE_M), (beam, readings)


def test_robot_answers_cmd_vel(world, probe):
    spawn = WORLDS[world][0]
    probe.subscribe("/odom", "nav_msgs/Odometry")
    probe.take("/odom")
    try:
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
        moved = probe.wait_for_message("/odom", predicate=lambda m: odom_position(m)[0] > spawn[0] + 0.05)
    finally:
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    assert odom_position(moved)[1] == pytest.approx(spawn[1], abs=0.01)
    rospy.ServiceProxy("/gazebo/reset_world", Empty)()
