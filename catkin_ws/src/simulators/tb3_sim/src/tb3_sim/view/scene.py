"""What a view draws, copied out of the world between two physics steps (so drawing never races physics).

A `Scene` is immutable plain data in the world frame (metres, radians). `Trail` records where a robot has been,
`Trails` does so for every robot, for the view only.
"""

import math
from collections import deque
from dataclasses import dataclass
from typing import Optional, Tuple

import numpy as np

from tb3_sim.core.floor import Floor
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import ScanResult, beam_angles

# Trail: a point every 1 cm at most, 5000 points (50 m of driving); a jump of more than 0.5 m between two
# points (a teleport or a reset) starts a new stroke instead of drawing a line across the world.
TRAIL_SPACING_M = 0.01
TRAIL_MAX_POINTS = 5000
TRAIL_JUMP_M = 0.5


class Trail:
    """The robot's recent path as strokes (sequences of (x, y) points), oldest points dropped first."""

    def __init__(self, spacing_m=TRAIL_SPACING_M, max_points=TRAIL_MAX_POINTS, jump_m=TRAIL_JUMP_M):
        self.spacing_m = spacing_m
        self.max_points = max_points
        self.jump_m = jump_m
        self.clear()

    def clear(self):
        self._strokes = deque([deque()])   # deques: dropping the oldest point is O(1) once the trail is full
        self._count = 0

    def add(self, x, y):
        """Record the robot at (x, y) if it has moved at least `spacing_m` since the last point."""
        stroke = self._strokes[-1]
        if stroke:
            distance = math.hypot(x - stroke[-1][0], y - stroke[-1][1])
            if distance < self.spacing_m:
                return
            if distance > self.jump_m:
                stroke = deque()
                self._strokes.append(stroke)
        stroke.append((x, y))
        self._count += 1
        if self._count > self.max_points:
            self._strokes[0].popleft()
            self._count -= 1
            if not self._strokes[0] and len(self._strokes) > 1:
                self._strokes.popleft()

    def strokes(self):
        """The strokes as tuples of points, oldest first."""
        return tuple(tuple(stroke) for stroke in self._strokes if stroke)


class Trails:
    """A Trail per robot, by robot name."""

    def __init__(self):
        self._trails = {}

    def add(self, robots):
        """Record every robot of `robots` (core.robot.Robot objects) where it is now."""
        for robot in robots:
            trail = self._trails.get(robot.name)
            if trail is None:
                trail = self._trails[robot.name] = Trail()
            trail.add(*robot.pose[:2])

    def strokes(self, name):
        """The strokes of the robot `name` (none if it has no trail yet)."""
        trail = self._trails.get(name)
        return trail.strokes() if trail is not None else ()

    def clear(self):
        self._trails.clear()


@dataclass(frozen=True)
class ModelView:
    """A box or cylinder model to draw: `shape` (shapes.Box or shapes.Cylinder) at `pose`, its colour `rgb` (None:
    the view's model colour)."""

    name: str
    shape: object
    pose: Pose2D
    static: bool
    rgb: Optional[Tuple[int, int, int]] = None


@dataclass(frozen=True)
class RobotView:
    """A robot to draw: its name, pose, outlines (in base_footprint) and trail strokes."""

    name: str
    pose: Pose2D
    outlines: Tuple
    trail: Tuple


@dataclass(frozen=True)
class Scene:
    """Everything a top-down view needs: static shapes (shapes.Segment/Polygon/Circle), models, robots, the
    first robot's latest scan with its origin (or None), and the world's floor layer (a floor.Floor, or None)."""

    static_shapes: Tuple
    models: Tuple[ModelView, ...]
    robots: Tuple[RobotView, ...]
    scan: Optional[ScanResult] = None
    scan_origin: Optional[Pose2D] = None
    floor: Optional[Floor] = None

    def scan_hits(self):
        """(N, 2) world points where the scan's beams hit something (finite ranges only)."""
        if self.scan is None:
            return np.zeros((0, 2))
        ranges = self.scan.ranges.astype(float)
        angles = beam_angles() + self.scan_origin.yaw
        finite = np.isfinite(ranges)
        return np.column_stack((self.scan_origin.x + ranges[finite] * np.cos(angles[finite]),
                                self.scan_origin.y + ranges[finite] * np.sin(angles[finite])))


def model_views(world):
    """The world's models as ModelViews, poses as of now (call with the world locked)."""
    return tuple(ModelView(m.name, m.spec.shape, m.pose, m.spec.static, m.spec.rgb) for m in world.models())


def scene_of(world, trails, scan=None):
    """A Scene of `world` now (call with the world locked); `trails` a Trails; `scan` is the first robot's latest
    ScanResult or None."""
    robots = tuple(RobotView(r.name, r.pose, r.model.footprint(), trails.strokes(r.name)) for r in world.robots())
    return Scene(static_shapes=world.description.static_shapes, models=model_views(world), robots=robots, scan=scan,
                 scan_origin=world.robot.scan_pose() if scan is not None else None, floor=world.description.floor)
