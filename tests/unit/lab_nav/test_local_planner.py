"""The DWA local planner: samples within turtlebot3's limits, never a colliding trajectory, goal handling."""
import numpy as np
import pytest

from lab_nav.costmap.footprint import WAFFLE_FOOTPRINT, Footprint
from lab_nav.costmap.layered import CostmapParams, LayeredCostmap
from lab_nav.costmap.values import INSCRIBED
from lab_nav.maps.geometry import MapGeometry
from lab_nav.planning.local_planner import DwaParams, DwaPlanner

FOOTPRINT = Footprint.padded(WAFFLE_FOOTPRINT)
PARAMS = DwaParams()


def _local_costmap(obstacles=()):
    costmap = LayeredCostmap(MapGeometry(0.05, 60, 60, -1.5, -1.5), CostmapParams(FOOTPRINT), static=False)
    if len(obstacles):
        costmap.add_scan((0.0, 0.0), obstacles, np.ones(len(obstacles), bool))
    costmap.update()
    return costmap


def _straight_plan(goal):
    return np.column_stack((np.linspace(0, goal[0], 50), np.linspace(0, goal[1], 50)))


def test_samples_stay_within_the_limits_and_one_control_periods_acceleration():
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    samples = planner.samples((0.1, 0.0))
    v, w = samples[:, 0], samples[:, 1]
    assert v.max() <= 0.26 + 1e-9 and v.min() >= -0.15 - 1e-9
    assert np.abs(w).max() <= 0.32 + 1e-9
    assert np.all((np.abs(v) >= 0.13 - 1e-9) | (np.abs(w) >= 0.9 - 1e-9))


@pytest.mark.parametrize("seed", range(8))
def test_the_chosen_trajectory_never_hits_an_obstacle(seed):
    rng = np.random.default_rng(seed)
    obstacles = rng.uniform(-1.4, 1.4, size=(40, 2))
    obstacles = obstacles[np.linalg.norm(obstacles, axis=1) > 0.35]
    costmap = _local_costmap(obstacles)
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    goal = tuple(rng.uniform(-1.2, 1.2, 2)) + (0.0,)
    planner.set_plan(_straight_plan(goal), goal)
    command = planner.compute((0.0, 0.0, rng.uniform(-np.pi, np.pi)), tuple(rng.uniform(-0.2, 0.2, 2)), costmap)
    if not command.valid:
        return
    _, collides = planner.footprint_costs(command.trajectory[None], costmap)
    assert not collides.any()
    assert np.all(costmap.cost_at(command.trajectory[:, 0], command.trajectory[:, 1]) < INSCRIBED)


def test_no_command_when_every_trajectory_collides():
    ring = [(0.3 * np.cos(a), 0.3 * np.sin(a)) for a in np.linspace(0, 2 * np.pi, 120)]
    costmap = _local_costmap(np.array(ring))
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    planner.set_plan(_straight_plan((1.0, 0.0)), (1.0, 0.0, 0.0))
    command = planner.compute((0.0, 0.0, 0.0), (0.0, 0.0), costmap)
    assert not command.valid and (command.v, command.w) == (0.0, 0.0)


def _drive(planner, pose, costmap, cycles=400):
    """Integrate the commands as an ideal diff-drive robot at the control period."""
    velocity = (0.0, 0.0)
    dt = PARAMS.sim_period
    for _ in range(cycles):
        command = planner.compute(pose, velocity, costmap)
        assert command.valid
        if command.reached:
            return pose
        v, w = command.v, command.w
        assert abs(v) <= 0.26 + 1e-9 and abs(w) <= 1.82 + 1e-9
        assert abs(v - velocity[0]) <= 2.5 * dt + 1e-9
        # the turn at the goal starts at min_vel_theta whatever the acceleration, as the original's
        turning_at_goal = planner.at_goal_position(pose) and v == 0.0 and abs(w) >= 0.9 - 1e-9
        assert turning_at_goal or abs(w - velocity[1]) <= 3.2 * dt + 1e-9
        pose = (pose[0] + v * dt * np.cos(pose[2] + w * dt / 2), pose[1] + v * dt * np.sin(pose[2] + w * dt / 2),
                pose[2] + w * dt)
        velocity = (v, w)
    raise AssertionError(f"goal not reached, robot at {pose}")


def test_the_robot_reaches_the_goal_and_turns_in_place_to_its_yaw():
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    goal = (1.0, 0.4, 2.0)
    planner.set_plan(_straight_plan(goal), goal)
    pose = _drive(planner, (0.0, 0.0, 0.0), _local_costmap())
    assert np.hypot(pose[0] - 1.0, pose[1] - 0.4) <= 0.05
    assert abs((pose[2] - 2.0 + np.pi) % (2 * np.pi) - np.pi) <= 0.17


def test_at_the_goal_position_it_only_rotates():
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    planner.set_plan(_straight_plan((0.02, 0.0)), (0.02, 0.0, np.pi / 2))
    command = planner.compute((0.0, 0.0, 0.0), (0.0, 0.0), _local_costmap())
    assert command.v == 0.0 and command.w == pytest.approx(0.9)   # min_vel_theta at once, as the original
    assert not command.reached


@pytest.mark.parametrize("error, w0, expected", [
    (np.pi / 2, 0.0, 0.9),     # from a standstill: min_vel_theta, above one period's 0.32 rad/s
    (1.5, 1.0, 1.32),          # |error| capped by one period's acceleration from |w0|
    (3.0, 1.82, 1.82),         # max_vel_theta
    (0.2, 1.5, 1.131),         # no faster than stops at the goal yaw: sqrt(2 x 3.2 x 0.2)
    (0.05, 0.3, 0.9),          # never below min_vel_theta
])
def test_the_turn_at_the_goal_has_the_latched_stop_rotate_controllers_speed(error, w0, expected):
    assert DwaPlanner(PARAMS, FOOTPRINT).rotate_speed(error, w0) == pytest.approx(expected, abs=1e-3)


def test_a_lethal_cell_in_the_rotation_blocks_it():
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    planner.set_plan(_straight_plan((0.02, 0.0)), (0.02, 0.0, np.pi / 2))
    start, turned = np.array([[[0.0, 0.0, 0.0]]]), np.array([[[0.0, 0.0, 0.5]]])
    for col, row in ((c, r) for c in range(20, 40) for r in range(20, 40)):
        costmap = _local_costmap()
        costmap.add_scan((0.0, 0.0), [costmap.geometry.cell_center(col, row)], [True], clear=False)
        costmap.update()
        if planner.footprint_costs(turned, costmap)[1].any() and not planner.footprint_costs(start, costmap)[1].any():
            break
    else:
        raise AssertionError("no cell is swept by the turn only")
    assert not planner.compute((0.0, 0.0, 0.0), (0.0, 0.0), costmap).valid


def test_a_robot_facing_across_its_plan_does_not_back_away_from_it():
    """The forward point lies ahead in the direction of travel, so backing away from where the plan goes does not
    score as aligned with it (with the point always ahead of the heading, a robot facing north above a plan going
    west backed away south, the replanned path followed it, and it reversed for 18 s in turtlebot3_world)."""
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    goal = (-1.2, 0.0, np.pi)
    planner.set_plan(_straight_plan(goal), goal)
    command = planner.compute((0.0, 0.0, np.pi / 2), (0.0, 0.0), _local_costmap())
    end = command.trajectory[-1]
    assert np.hypot(end[0] - goal[0], end[1] - goal[1]) < 1.2


def test_footprint_costs_are_the_outline_and_centre_cells_of_each_pose():
    """The planner's one lookup of every point against a pose-by-pose reference: the outline's and centre's cells
    (off the costmap: no information, a collision)."""
    rng = np.random.default_rng(11)
    costmap = _local_costmap(rng.uniform(-1.4, 1.4, size=(30, 2)))
    planner = DwaPlanner(PARAMS, FOOTPRINT)
    poses = np.column_stack((rng.uniform(-1.8, 1.8, 60), rng.uniform(-1.8, 1.8, 60), rng.uniform(-4, 4, 60)))
    highest, collides = planner.footprint_costs(poses.reshape(6, 10, 3), costmap)
    g = costmap.geometry
    for pose, cost, hit in zip(poses, highest.ravel(), collides.ravel()):
        outline = FOOTPRINT.outline(0.1)
        c, s = np.cos(pose[2]), np.sin(pose[2])
        points = np.vstack((pose[:2], pose[:2] + outline @ np.array([[c, s], [-s, c]])))
        cols, rows = g.world_to_cell(points[:, 0], points[:, 1])
        values = [int(costmap.costs[r, cc]) if g.contains(cc, r) else 255 for cc, r in zip(cols, rows)]
        assert cost == max(values)
        assert hit == (values[0] >= INSCRIBED or max(values[1:]) >= 254)
