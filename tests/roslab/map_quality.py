"""How well an occupancy grid matches a tb3_sim world's true walls (for the SLAM tests and benchmarks).

precision: the fraction of the map's occupied cells whose centre lies within `tolerance_m` of a true wall surface
(a wall, pillar or furniture side that reaches the scan plane).
recall: the fraction of the wall length within `reach_m` of the route that the map marks occupied. That length is
what a LiDAR at the route's poses can see within reach_m (walls hidden behind others cannot be mapped from this
route): rays are cast every RAY_STEP_RAD from each pose with tb3_sim's own ray caster, their hits are gathered into
CELL_M pieces of wall, and a piece counts as marked when an occupied cell's centre lies within tolerance_m of it.
"""
import math

import numpy as np
from scipy.spatial import cKDTree

from tb3_sim.core.lidar import cast_rays
from tb3_sim.core.obstacles import static_obstacles
from tb3_sim.core.shapes import Circle, Polygon, visible_at
from tb3_sim.core.world_file import load_world

SCAN_PLANE_M = 0.132
RAY_STEP_RAD = math.radians(0.5)
CELL_M = 0.05


def world_walls(world_path):
    """The static shapes of the tb3_sim world file at `world_path` that the scan plane meets."""
    shapes = load_world(world_path).static_shapes
    return tuple(shape for shape in shapes if visible_at(shape, SCAN_PLANE_M))


def wall_distance(shapes, xs, ys):
    """Distance (m) from each point to the nearest wall surface (inside a shape counts as its distance to the
    outline)."""
    points = np.column_stack((xs, ys))
    best = np.full(len(points), np.inf)
    for shape in shapes:
        if isinstance(shape, Circle):
            d = np.abs(np.hypot(*(points - shape.center).T) - shape.radius)
        else:
            outline = np.asarray(shape.points if isinstance(shape, Polygon) else (shape.start, shape.end))
            a, b = outline, np.roll(outline, -1, axis=0)
            e = b - a
            t = np.clip(((points[:, None] - a) * e).sum(-1) / (e * e).sum(-1), 0.0, 1.0)
            d = np.linalg.norm(a + t[..., None] * e - points[:, None], axis=-1).min(axis=1)
        np.minimum(best, d, out=best)
    return best


def occupied_points(values, geometry):
    """(x, y) arrays of the centres of the cells marked 100."""
    rows, cols = np.nonzero(np.asarray(values) == 100)
    return geometry.cell_center(cols, rows)


def visible_wall_pieces(shapes, laser_positions, reach_m):
    """(x, y) centres of the CELL_M pieces of wall seen within reach_m from any of `laser_positions`."""
    obstacles = static_obstacles(shapes)
    angles = np.arange(0.0, 2.0 * math.pi, RAY_STEP_RAD)
    hits = []
    for x, y in laser_positions:
        ranges = cast_rays((x, y), angles, obstacles, 0.0, reach_m)
        seen = np.isfinite(ranges)
        hits.append(np.column_stack((x + ranges[seen] * np.cos(angles[seen]), y + ranges[seen] * np.sin(angles[seen]))))
    hits = np.concatenate(hits) if hits else np.zeros((0, 2))
    pieces = np.unique(np.floor(hits / CELL_M).astype(np.int64), axis=0)
    return (pieces[:, 0] + 0.5) * CELL_M, (pieces[:, 1] + 0.5) * CELL_M


def precision(values, geometry, shapes, tolerance_m):
    xs, ys = occupied_points(values, geometry)
    return float(np.mean(wall_distance(shapes, xs, ys) <= tolerance_m)) if len(xs) else 0.0


def recall(values, geometry, shapes, laser_positions, reach_m, tolerance_m):
    wall_x, wall_y = visible_wall_pieces(shapes, laser_positions, reach_m)
    occupied_x, occupied_y = occupied_points(values, geometry)
    if not len(wall_x) or not len(occupied_x):
        return 0.0
    distance, _ = cKDTree(np.column_stack((occupied_x, occupied_y))).query(np.column_stack((wall_x, wall_y)))
    return float(np.mean(distance <= tolerance_m))
