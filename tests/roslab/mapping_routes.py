"""The SLAM tests' and benchmarks' scripted drives: a route per world and the steering law that follows it.

Steering turns in place towards the next waypoint, then drives at DRIVE_MPS while correcting the heading.
"""
import math
from dataclasses import dataclass
from pathlib import Path

import rospkg

DRIVE_MPS = 0.22
TURN_GAIN = 2.5
MAX_TURN_RADPS = 1.2
ALIGNED_RAD = 0.15
REACHED_M = 0.06


@dataclass(frozen=True)
class MappingRoute:
    """A world to map and the drive through it: the launch file that starts the world as a course starts it
    ((package, file)), the robot's model name it spawns ({model}: $TURTLEBOT3_MODEL), its tb3_sim world file
    ((package, path in it)), the launch file's spawn pose (x, y, yaw) and the waypoints (x, y) to drive through, in
    the world frame (m)."""

    launch: tuple
    robot: str
    world_file: tuple
    spawn: tuple
    waypoints: tuple

    def robot_name(self, model):
        return self.robot.format(model=model)

    def world_path(self):
        package, path = self.world_file
        return Path(rospkg.RosPack().get_path(package)) / path


# Around the pillars of turtlebot3_world; around the table of the house's first room (turtlebot3_house.launch
# names the robot plain `turtlebot3`, as the original does); in tuos_simulations'
# nav_world (COM2009 Part 3's SLAM arena), a loop round the centre wall past every inner wall, at least 0.3 m from
# any wall.
ROUTES = {
    "turtlebot3_world": MappingRoute(
        ("turtlebot3_gazebo", "turtlebot3_world.launch"), "turtlebot3_{model}",
        ("tb3_sim", "worlds/turtlebot3_world.yaml"), (-2.0, -0.5, 0.0),
        ((-1.65, -0.5), (-1.65, -1.6), (1.65, -1.6), (1.65, 1.6), (-1.65, 1.6), (-1.65, -0.4))),
    "turtlebot3_house": MappingRoute(
        ("turtlebot3_gazebo", "turtlebot3_house.launch"), "turtlebot3", ("tb3_sim", "worlds/turtlebot3_house.yaml"),
        (-3.0, 1.0, 0.0),
        ((-1.0, 1.0), (-1.0, 4.2), (-4.2, 4.2), (-4.2, 1.0), (-3.0, 1.0))),
    "nav_world": MappingRoute(
        ("tuos_simulations", "nav_world.launch"), "turtlebot3_{model}", ("tuos_simulations", "worlds/navigation.yaml"),
        (0.5, -0.04, 0.0),
        ((0.65, -0.04), (0.65, -1.05), (-0.65, -1.05), (-0.65, 0.1), (-1.75, 0.1), (-1.75, 1.95), (-0.3, 1.95),
         (-0.3, 0.85), (1.9, 0.85), (1.9, -0.2), (0.65, -0.2))),
}


def steer(pose, waypoint):
    """(linear m/s, angular rad/s) from `pose` (x, y, yaw) towards `waypoint` (x, y); None once it is reached."""
    x, y, yaw = pose
    distance = math.hypot(waypoint[0] - x, waypoint[1] - y)
    if distance < REACHED_M:
        return None
    error = math.remainder(math.atan2(waypoint[1] - y, waypoint[0] - x) - yaw, 2.0 * math.pi)
    linear = min(DRIVE_MPS, distance) if abs(error) < ALIGNED_RAD else 0.0
    return linear, max(-MAX_TURN_RADPS, min(MAX_TURN_RADPS, TURN_GAIN * error))
