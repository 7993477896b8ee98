"""`roslaunch turtlebot3_gazebo turtlebot3_simulation.launch` (the turtlebot3_drive obstacle-avoidance demo) on
turtlebot3_world: over 120 s of simulated time the robot wanders the arena without touching a wall or pillar,
measured from ground truth (/gazebo/model_states) against the world file's geometry; the node's name and its
command topic follow the launch args; Ctrl-C stops the robot; a bad topic name ends the launch with one line.

The simulator runs at WANDER_REAL_TIME_FACTOR x real time: the demo times everything in simulated time, so the
assertions hold at any factor the machine keeps up with (see the wander test for what that means).
"""
import math

import pytest
import rosgraph
import rospy
from gazebo_msgs.srv import GetModelState

from roslab import RosProcess, wait_for_param, wait_for_service, wait_for_topic, wait_until
from tb3_sim.core.shapes import Circle, Polygon, Segment
from tb3_sim.core.world_file import load_world, shipped_world_path

ROBOT = "turtlebot3_waffle"
WANDER_REAL_TIME_FACTOR = 10
WANDER_SIM_S = 120.0

# Box2D keeps touching shapes about 1-2 cm apart (its polygon skin), so a robot against a wall measures that.
TOUCHING_M = 0.02
# /gazebo/model_states comes at 100 Hz of sim time: 3-4 mm of motion of any point of the robot between two
# messages. The probe may drop some when the machine is busy; more than this between two samples is too sparse.
MAX_SWEEP_M = 0.02
MIN_TRAVELLED_M = 3.0
MIN_QUADRANTS_VISITED = 2

# The Waffle's collision outline in base_footprint (turtlebot3_waffle.urdf.xacro): the base box and the two
# wheels, which stick out past it to y = +-0.153 m.
WAFFLE_BASE = ((-0.197, -0.133), (0.069, -0.133), (0.069, 0.133), (-0.197, 0.133))
WAFFLE_LEFT_WHEEL = ((-0.033, 0.135), (0.033, 0.135), (0.033, 0.153), (-0.033, 0.153))
WAFFLE_RIGHT_WHEEL = tuple((x, -y) for x, y in reversed(WAFFLE_LEFT_WHEEL))
WAFFLE_OUTLINE = (WAFFLE_BASE, WAFFLE_LEFT_WHEEL, WAFFLE_RIGHT_WHEEL)
WAFFLE_REACH_M = max(math.hypot(x, y) for part in WAFFLE_OUTLINE for x, y in part)


# ---- clearance between the robot and the static world geometry (plain 2D geometry)


def _edges(points):
    return [(points[i], points[(i + 1) % len(points)]) for i in range(len(points))]


def _point_segment_distance(p, a, b):
    ex, ey = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey)))
    return math.hypot(a[0] + t * ex - p[0], a[1] + t * ey - p[1])


def _separated(a_points, b_points):
    """True if an edge normal of either convex outline separates them (separating axis theorem)."""
    for points in (a_points, b_points):
        for (ax, ay), (bx, by) in _edges(points):
            nx, ny = by - ay, ax - bx
            a_proj = [nx * x + ny * y for x, y in a_points]
            b_proj = [nx * x + ny * y for x, y in b_points]
            if max(a_proj) < min(b_proj) or max(b_proj) < min(a_proj):
                return True
    return False


def _inside(p, points):
    crosses = [(b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) for a, b in _edges(points)]
    return all(c >= 0 for c in crosses) or all(c <= 0 for c in crosses)


def _convex_distance(a_points, b_points):
    """Distance between two convex outlines (a segment is a two-point outline); 0 when they overlap."""
    if not _separated(a_points, b_points):
        return 0.0
    return min(min(_point_segment_distance(p, a, b) for p in a_points for a, b in _edges(b_points)),
               min(_point_segment_distance(p, a, b) for p in b_points for a, b in _edges(a_points)))


def _shape_distance(outline, shape):
    if isinstance(shape, Circle):
        if _inside(shape.center, outline):
            return 0.0
        return max(0.0, min(_point_segment_distance(shape.center, a, b) for a, b in _edges(outline)) - shape.radius)
    if isinstance(shape, Polygon):
        return _convex_distance(outline, shape.points)
    if isinstance(shape, Segment):
        return _convex_distance(outline, (shape.start, shape.end))
    raise TypeError(f"no distance to a {type(shape).__name__}")


def _point_distance(point, shape):
    """Distance from `point` to `shape` (0 inside it)."""
    if isinstance(shape, Circle):
        return max(0.0, math.dist(point, shape.center) - shape.radius)
    outline = shape.points if isinstance(shape, Polygon) else (shape.start, shape.end)
    if len(outline) > 2 and _inside(point, outline):
        return 0.0
    return min(_point_segment_distance(point, a, b) for a, b in _edges(outline))


def sweep(a, b):
    """Farthest any point of the robot can have moved between poses `a` and `b` ((x, y, yaw) each)."""
    turn = abs(math.remainder(b[2] - a[2], 2.0 * math.pi))
    return math.dist(a[:2], b[:2]) + WAFFLE_REACH_M * turn


def clearance(shapes, x, y, yaw):
    """Smallest distance (m) from the Waffle at (x, y, yaw) in the world frame to any of `shapes`.

    Shapes are measured nearest first, by a lower bound (distance from the robot's origin less its reach), and
    the search stops once no remaining shape can be closer than the best so far.
    """
    c, s = math.cos(yaw), math.sin(yaw)
    outlines = [[(x + c * px - s * py, y + s * px + c * py) for px, py in part] for part in WAFFLE_OUTLINE]
    bounds = sorted(((_point_distance((x, y), shape) - WAFFLE_REACH_M, i) for i, shape in enumerate(shapes)))
    best = math.inf
    for bound, i in bounds:
        if bound >= best:
            break
        best = min(best, min(_shape_distance(outline, shapes[i]) for outline in outlines))
    return best


@pytest.fixture(scope="module")
def world_shapes():
    return load_world(shipped_world_path("turtlebot3_world")).static_shapes


@pytest.mark.parametrize("yaw, expected", [
    (0.0, 0.4 - 0.069 - 0.15),       # front face to pillar (0, 0)
    (math.pi, 0.4 - 0.197 - 0.15),   # rear face to pillar (0, 0)
])
def test_clearance_to_a_pillar(world_shapes, yaw, expected):
    assert clearance(world_shapes, -0.4, 0.0, yaw) == pytest.approx(expected, abs=1e-9)


def test_clearance_is_zero_on_a_pillar(world_shapes):
    assert clearance(world_shapes, 0.0, 0.0, 0.3) == 0.0


def test_clearance_at_the_spawn_pose_is_the_gap_to_the_arena_wall(world_shapes):
    # Rear-right corner (-2.197, -0.633) to the inner wall edge from (-2.93, 0) to (-1.465, -2.537).
    corner, a, b = (-2.197, -0.633), (-2.93, 0.0), (-1.465, -2.537)
    expected = abs((b[0] - a[0]) * (corner[1] - a[1]) - (b[1] - a[1]) * (corner[0] - a[0])) / math.dist(a, b)
    assert clearance(world_shapes, -2.0, -0.5, 0.0) == pytest.approx(expected, abs=1e-9)


# ---- the demo on the simulator


@pytest.fixture
def launch(ros_master, tmp_path):
    """Start `roslaunch <args>`; every launch is ended after the test (the simulator last)."""
    started = []

    def start(*args):
        process = RosProcess(["roslaunch", "--wait", *args], ros_master.env, tmp_path / f"launch{len(started)}.log")
        started.append(process)
        return process

    yield start
    for process in reversed(started):
        process.stop()
    wait_until(lambda: not _service_up(ros_master, "/gazebo/get_model_state"), 20, "the simulator to leave the master")


def _node_up(ros_master, name):
    """True while `name` has a topic or service registered (the master keeps a node's URI after it exits)."""
    state = rosgraph.Master("/test", master_uri=ros_master.uri).getSystemState()
    return any(name in nodes for registrations in state for _, nodes in registrations)


def _service_up(ros_master, name):
    try:
        rosgraph.Master("/test", master_uri=ros_master.uri).lookupService(name)
        return True
    except rosgraph.MasterError:
        return False


def start_world(launch, ros_master, real_time_factor):
    process = launch("turtlebot3_gazebo", "turtlebot3_world.launch", "gui:=false", "model:=waffle",
                     f"real_time_factor:={real_time_factor}")
    wait_for_service(ros_master.uri, "/gazebo/get_model_state")
    wait_for_param(ros_master.uri, "/use_sim_time")
    return process


def model_state():
    """(x, y, yaw, speed, turn rate) of the robot from /gazebo/get_model_state (world frame)."""
    reply = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)(model_name=ROBOT, relative_entity_name="")
    assert reply.success, reply.status_message
    q, v = reply.pose.orientation, reply.twist.linear
    yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
    return reply.pose.position.x, reply.pose.position.y, yaw, math.hypot(v.x, v.y), reply.twist.angular.z


def ground_truth(entries):
    """(sim time, x, y, yaw) of the robot from probe entries of /gazebo/model_states."""
    samples = []
    for entry in entries:
        msg = entry["msg"]
        pose = msg["pose"][msg["name"].index(ROBOT)]
        q = pose["orientation"]
        yaw = math.atan2(2.0 * (q["w"] * q["z"] + q["x"] * q["y"]), 1.0 - 2.0 * (q["y"] ** 2 + q["z"] ** 2))
        samples.append((entry["ros"], pose["position"]["x"], pose["position"]["y"], yaw))
    return samples


def is_drive_command(entry):
    twist = entry["msg"]
    return (twist["linear"]["x"], twist["angular"]["z"]) in {(0.3, 0.0), (0.0, 1.5), (0.0, -1.5)}


@pytest.mark.slow
def test_the_robot_wanders_for_120_sim_seconds_without_touching_anything(launch, ros_master, world_shapes):
    """At 10x real time the run takes about 12 s of wall time plus start-up.

    The node decides in simulated time (a Rate of 125 Hz on /clock), but a message still takes a few wall
    milliseconds to reach it and its command a few more to reach the simulator: at factor F that delay is F times
    longer in simulated time. At 1x and 10x it is a few millimetres to centimetres of travel, far inside the
    demo's 0.7 m / 0.6 m margins, so the robot behaves alike (not the same trajectory, which depends on exact
    timings, but the same kind of run: tens of metres, clear of everything). Unpaced (factor 0: 15-30x on two
    cores with the demo running) the delay reaches tenths of a simulated second and the robot can hit a wall.
    """
    start_world(launch, ros_master, WANDER_REAL_TIME_FACTOR)
    probe = ros_master.probe()
    probe.subscribe("/gazebo/model_states", "gazebo_msgs/ModelStates")
    probe.subscribe("/cmd_vel", "geometry_msgs/Twist")
    demo = launch("turtlebot3_gazebo", "turtlebot3_simulation.launch")
    wait_until(lambda: _node_up(ros_master, "/turtlebot3_drive"), 30, "the node /turtlebot3_drive")
    wait_until(lambda: any(is_drive_command(e) for e in probe.take("/cmd_vel")), 30, "a command on /cmd_vel")

    start_s = probe.now()
    entries = probe.take("/gazebo/model_states")
    wall_timeout_s = 30.0 + 20.0 * WANDER_SIM_S / WANDER_REAL_TIME_FACTOR

    def collected_enough():
        entries.extend(probe.take("/gazebo/model_states"))
        return entries and entries[-1]["ros"] >= start_s + WANDER_SIM_S
    wait_until(collected_enough, wall_timeout_s, f"{WANDER_SIM_S:.0f} s of sim time", interval_s=0.2)

    # Ctrl-C: the node's last command is a zero Twist, which the simulator holds.
    demo.stop()
    wait_until(lambda: max(abs(v) for v in model_state()[3:]) < 1e-3, 20, "the robot to stop after Ctrl-C")
    last_command = probe.take("/cmd_vel")[-1]["msg"]
    assert (last_command["linear"]["x"], last_command["angular"]["z"]) == (0.0, 0.0)
    assert "Traceback" not in demo.output()

    # Between two samples the clearance can be smaller than at either by at most the sweep between them.
    samples = [s for s in ground_truth(entries) if start_s <= s[0] <= start_s + WANDER_SIM_S]
    poses = [s[1:] for s in samples]
    largest_sweep = max(sweep(a, b) for a, b in zip(poses, poses[1:]))
    assert largest_sweep < MAX_SWEEP_M, f"ground truth too sparse: {largest_sweep:.3f} m of motion between two samples"
    clearances = [(clearance(world_shapes, x, y, yaw), t - start_s, (x, y)) for t, x, y, yaw in samples]
    closest = min(clearances)
    assert closest[0] - largest_sweep > TOUCHING_M, \
        f"the robot touched something: {closest[0]:.3f} m at {closest[2]}, {closest[1]:.1f} s into the run"
    travelled = sum(math.dist(a[1:3], b[1:3]) for a, b in zip(samples, samples[1:]))
    assert travelled > MIN_TRAVELLED_M
    quadrants = {(x > 0.0, y > 0.0) for _, x, y, _ in samples}
    assert len(quadrants) >= MIN_QUADRANTS_VISITED


def test_node_name_and_command_topic_follow_the_launch_args(launch, ros_master):
    start_world(launch, ros_master, 5)
    probe = ros_master.probe()
    probe.subscribe("/my_cmd_vel", "geometry_msgs/Twist")
    start_x, start_y = model_state()[:2]
    launch("turtlebot3_gazebo", "turtlebot3_simulation.launch", "cmd_vel:=/my_cmd_vel", "name:=robot1")
    wait_for_topic(ros_master.uri, "/my_cmd_vel")
    assert _node_up(ros_master, "/robot1_drive")
    assert not _node_up(ros_master, "/turtlebot3_drive")
    command = probe.wait_for_message("/my_cmd_vel", predicate=lambda msg: msg["linear"]["x"] > 0.0)
    assert (command["linear"]["x"], command["angular"]["z"]) == (0.3, 0.0)
    publishers = dict(rosgraph.Master("/test", master_uri=ros_master.uri).getSystemState()[0])
    assert "/robot1_drive" not in publishers.get("/cmd_vel", [])
    # The simulator listens on /cmd_vel only, so the commands on /my_cmd_vel leave the robot where it was.
    probe.sleep_sim(2.0)
    x, y, _, speed, _ = model_state()
    assert (x, y) == pytest.approx((start_x, start_y), abs=1e-3)
    assert speed < 1e-3


def test_a_bad_topic_name_ends_the_launch_with_one_clear_line(launch, ros_master):
    demo = launch("turtlebot3_gazebo", "turtlebot3_simulation.launch", "cmd_vel:=not a topic")
    wait_until(lambda: not demo.running(), 60, "roslaunch to end (the node is required)")
    output = demo.output()
    assert "turtlebot3_drive: parameter /cmd_vel_topic_name must be a topic name such as /cmd_vel, " \
           "got 'not a topic'" in output
    assert "Traceback" not in output

