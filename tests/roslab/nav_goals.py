"""Seeded random navigation goals on a map, goals sent through the move_base action's topics, and the measures of a
run to each: the shortest grid path, the path driven, and how close the LiDAR saw anything to the robot's body.
Shared by tests/integration/navigation and tests/bench/nav_bench.py.

Goals are the map's free cells whose global-costmap cost (turtlebot3's inflation) is below GOAL_MAX_COST, so at
least ~0.4 m from any obstacle (room to turn to any yaw at the goal: at 0.31 m, cost 128, the cells' coverage
left a turn in place colliding), at least MIN_GOAL_DISTANCE_M from the previous goal, and reachable from it.
"""
import math

import numpy as np
import rospy
from gazebo_msgs.srv import GetModelState
from std_srvs.srv import Empty

from lab_nav.costmap.footprint import WAFFLE_FOOTPRINT, Footprint
from lab_nav.costmap.layered import CostmapParams, LayeredCostmap
from lab_nav.costmap.values import INSCRIBED
from lab_nav.planning import global_planner
from roslab.waiting import wait_until

GOAL_TIMEOUT_SIM_S = 90.0
GOAL_MAX_COST = 100
MIN_GOAL_DISTANCE_M = 1.0
WAFFLE_SCAN_X_M = -0.064   # base_scan ahead of base_footprint (behind it: the Waffle's LiDAR sits back)


def global_costs(geometry, cells, footprint=WAFFLE_FOOTPRINT):
    """The global costmap move_base builds from this map (static + inflation, turtlebot3's parameters)."""
    costmap = LayeredCostmap(geometry, CostmapParams(Footprint.padded(footprint)))
    costmap.set_map(geometry, cells)
    return costmap.update()


def _cell(geometry, xy):
    return tuple(int(v) for v in geometry.world_to_cell(xy[0], xy[1]))


def shortest_grid_path_m(costs, geometry, start_xy, goal_xy, within_cost=False):
    """Length (m) of the shortest 8-connected cell path through the planner's free space (cells below the
    inscribed cost, their cost ignored), or with `within_cost` of the cheapest one by the planner's cost (navfn's
    path, which keeps away from obstacles where that is cheap); None when there is none."""
    grid = costs if within_cost else np.where(costs >= INSCRIBED, costs, 0).astype(np.uint8)
    cells = global_planner.plan(grid, _cell(geometry, start_xy), _cell(geometry, goal_xy), geometry.resolution)
    if cells is None:
        return None
    steps = np.diff(np.array(cells, dtype=float), axis=0)
    return float(np.hypot(steps[:, 0], steps[:, 1]).sum() * geometry.resolution)


def random_goals(cells, costs, geometry, start_xy, count, seed):
    """[(x, y, yaw, shortest grid path from the previous goal in m, the cheapest one's length), ...]: `count`
    goals, each reachable from the one before (the first from start_xy)."""
    rng = np.random.default_rng(seed)
    rows, cols = np.nonzero((np.asarray(cells) == 0) & (costs < GOAL_MAX_COST))
    goals, here = [], tuple(start_xy)
    while len(goals) < count:
        k = rng.integers(len(rows))
        x, y = (float(v) for v in geometry.cell_center(cols[k], rows[k]))
        if math.hypot(x - here[0], y - here[1]) < MIN_GOAL_DISTANCE_M:
            continue
        shortest = shortest_grid_path_m(costs, geometry, here, (x, y))
        if shortest is None:
            continue
        goals.append((x, y, float(rng.uniform(-math.pi, math.pi)), shortest,
                      shortest_grid_path_m(costs, geometry, here, (x, y), within_cost=True)))
        here = (x, y)
    return goals


def path_length_m(points):
    """Length of the polyline through (x, y) points."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    return float(np.hypot(*np.diff(points, axis=0).T).sum()) if len(points) > 1 else 0.0


def body_edge_m(angles, footprint=WAFFLE_FOOTPRINT, scan_x=WAFFLE_SCAN_X_M):
    """Distance (m) from the LiDAR to the footprint's edge along each beam (angles in rad, base_scan's axes =
    base_footprint's): a reading shorter than this is something inside the body, i.e. a contact."""
    polygon = np.asarray(footprint, dtype=float) - (scan_x, 0.0)
    a, b = polygon, np.roll(polygon, -1, axis=0)
    dx, dy = np.cos(angles)[:, None], np.sin(angles)[:, None]
    ex, ey = (b - a)[:, 0], (b - a)[:, 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        denominator = dx * ey - dy * ex
        t = (a[:, 0] * ey - a[:, 1] * ex) / denominator        # along the beam
        s = (a[:, 0] * dy - a[:, 1] * dx) / denominator        # along the edge
    hits = np.where((s >= 0) & (s <= 1) & (t > 0), t, np.inf)
    return hits.min(axis=1)


def closest_clearance_m(scans):
    """The smallest clearance (reading - body edge) over LaserScan dicts (the probe's), each beam's averaged with
    its four nearest neighbours': how near anything came to the body; +inf when nothing was seen.

    Why averaged: every reading carries the LiDAR's own Gaussian noise (0.01 m, independent per beam), and the
    smallest of the thousands of single readings taken while the robot passes an obstacle lies ~3.5 sigma
    (0.035 m) below the true distance, so a single beam's minimum calls a pass 0.04 m clear a contact. Five
    beams 1 deg apart see the same surface within a centimetre at these ranges and cut the noise by sqrt(5), at
    the cost of reading up to ~4 mm too far where a footprint corner is nearest; beams next to one that saw
    nothing are left out (anything near the body spans many beams)."""
    clearance = math.inf
    for scan in scans:
        ranges = np.array([float(r) for r in scan["ranges"]])
        angles = scan["angle_min"] + scan["angle_increment"] * np.arange(len(ranges))
        per_beam = np.full(len(ranges), np.inf)
        seen = np.isfinite(ranges)
        per_beam[seen] = ranges[seen] - body_edge_m(angles[seen])
        averaged = sum(np.roll(per_beam, shift) for shift in range(-2, 3)) / 5.0
        if np.isfinite(averaged).any():
            clearance = min(clearance, float(np.min(averaged)))
    return clearance


# ---- goals through the move_base action's topics (a TopicProbe subscribed to /move_base/result, /odom, /scan and
# /move_base/feedback)

class Goals:
    """Goal ids are unique within a process: test-goal-1, test-goal-2, ..."""
    counter = 0


def send_goal(probe, x, y, yaw=0.0, quaternion=None):
    """Publish a MoveBaseActionGoal with a fresh id; returns the id."""
    Goals.counter += 1
    goal_id = f"test-goal-{Goals.counter}"
    qx, qy, qz, qw = quaternion or (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    probe.publish("/move_base/goal", "move_base_msgs/MoveBaseActionGoal", {
        "goal_id": {"id": goal_id},
        "goal": {"target_pose": {"header": {"frame_id": "map"},
                                 "pose": {"position": {"x": x, "y": y},
                                          "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}}}}})
    return goal_id


def wait_result(probe, goal_id, timeout_sim_s=GOAL_TIMEOUT_SIM_S):
    """(status, text, sim seconds from now until the probe received the goal's result message); status None when
    no result came within timeout_sim_s."""
    start = probe.now()
    found = []

    def done():
        for entry in probe.take("/move_base/result"):
            if entry["msg"]["status"]["goal_id"]["id"] == goal_id:
                found.append(entry)
        return bool(found) or probe.now() - start > timeout_sim_s
    wait_until(done, timeout_sim_s * 3 + 60, f"the result of {goal_id}", interval_s=0.2)
    if not found:
        return None, f"no result for {goal_id} within {timeout_sim_s} s of sim time", timeout_sim_s
    return found[0]["msg"]["status"]["status"], found[0]["msg"]["status"]["text"], found[0]["ros"] - start


def drive_to(probe, goal):
    """Send one goal (x, y, yaw, ...) and measure the run: status, text, sim seconds, the pose move_base last
    reported, the /odom path length and the closest the LiDAR saw anything to the body."""
    for topic in ("/odom", "/scan", "/move_base/feedback"):
        probe.take(topic)
    goal_id = send_goal(probe, goal[0], goal[1], goal[2])
    status, text, waited = wait_result(probe, goal_id)
    odom = probe.take("/odom")
    feedback = [e["msg"]["feedback"]["base_position"]["pose"] for e in probe.take("/move_base/feedback")
                if e["msg"]["status"]["goal_id"]["id"] == goal_id]
    last = feedback[-1] if feedback else None
    return dict(status=status, text=text, waited=waited, last=last,
                driven=path_length_m([(e["msg"]["pose"]["pose"]["position"]["x"],
                                                 e["msg"]["pose"]["pose"]["position"]["y"]) for e in odom]),
                clearance=closest_clearance_m([e["msg"] for e in probe.take("/scan")]))


def yaw_of(pose):
    """Yaw (rad) of a Pose dict."""
    q = pose["orientation"]
    return math.atan2(2 * (q["w"] * q["z"] + q["x"] * q["y"]), 1 - 2 * (q["y"] ** 2 + q["z"] ** 2))


# ---- amcl against the simulator's ground truth (/gazebo/get_model_state); the calling process's ROS_MASTER_URI
# must name the master

def true_pose(model="turtlebot3_waffle"):
    """(x, y, yaw) of the model in the simulator's world (= map: the maps are drawn from the world)."""
    state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)(model_name=model)
    pose = state.pose
    return pose.position.x, pose.position.y, yaw_of({"orientation": {k: getattr(pose.orientation, k)
                                                                     for k in "xyzw"}})


def amcl_error_after_drive(probe, offset_m, offset_rad, speed_m_s, drive_sim_s):
    """Set amcl's pose offset_m (diagonally) and offset_rad off the true one (with RViz's 2D Pose Estimate
    covariance: 0.5 m, 15 deg), drive straight at speed_m_s for drive_sim_s on /cmd_vel, stop; returns
    (position error m, yaw error rad) of the /amcl_pose a no-motion update then publishes against the true pose.
    The probe must subscribe /amcl_pose."""
    x, y, yaw = true_pose()
    off = (x + offset_m / math.sqrt(2), y + offset_m / math.sqrt(2), yaw + offset_rad)
    probe.publish("/initialpose", "geometry_msgs/PoseWithCovarianceStamped", {
        "header": {"frame_id": "map"},
        "pose": {"pose": {"position": {"x": off[0], "y": off[1]},
                          "orientation": {"z": math.sin(off[2] / 2), "w": math.cos(off[2] / 2)}},
                 "covariance": [0.25, 0, 0, 0, 0, 0, 0, 0.25] + [0] * 27 + [math.radians(15.0) ** 2]}})
    probe.sleep_sim(1.0, 30)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": speed_m_s}})
    probe.sleep_sim(drive_sim_s, 60 + 3 * drive_sim_s)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    probe.sleep_sim(1.0, 30)
    probe.take("/amcl_pose")
    rospy.ServiceProxy("/request_nomotion_update", Empty)()   # a standing robot's amcl publishes no pose else
    estimate = probe.wait_for_message("/amcl_pose", 20)["pose"]["pose"]
    truth = true_pose()
    position = estimate["position"]
    return (math.hypot(position["x"] - truth[0], position["y"] - truth[1]),
            abs(math.remainder(yaw_of(estimate) - truth[2], math.tau)))
