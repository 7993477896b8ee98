"""A map of a tb3_sim world drawn from its world file, laid out as gmapping's and map_saver's maps are.

384 x 384 cells of 0.05 m with origin (-10, -10): a cell is occupied (100) where a static shape covers any
part of it, free (0) where the robot's spawn point reaches it through unoccupied cells (the arena's inside),
unknown (-1) elsewhere, as a map saved after driving around would look. Written with map_saver's own file
writer, so map_server reads it as it reads a saved map.
"""
from pathlib import Path

import numpy as np
from scipy import ndimage

from lab_nav.maps.geometry import MapGeometry
from lab_nav.maps.map_saver_files import pgm_bytes, yaml_text
from tb3_sim.core.shapes import Circle, Polygon, Segment
from tb3_sim.core.world_file import load_world, shipped_world_path

GEOMETRY = MapGeometry(0.05, 384, 384, -10.0, -10.0)
COVER_M = GEOMETRY.resolution * np.sqrt(0.5)   # a shape this close to a cell's centre overlaps the cell


def _segment_distance(px, py, a, b):
    ax, ay = a
    ex, ey = b[0] - ax, b[1] - ay
    t = np.clip(((px - ax) * ex + (py - ay) * ey) / max(ex * ex + ey * ey, 1e-12), 0.0, 1.0)
    return np.hypot(ax + t * ex - px, ay + t * ey - py)


def _distance(shape, px, py):
    if isinstance(shape, Circle):
        return np.maximum(np.hypot(px - shape.center[0], py - shape.center[1]) - shape.radius, 0.0)
    points = shape.points if isinstance(shape, Polygon) else (shape.start, shape.end)
    edges = list(zip(points, points[1:] + points[:1])) if len(points) > 2 else [tuple(points)]
    distance = np.min([_segment_distance(px, py, a, b) for a, b in edges], axis=0)
    if len(points) > 2:
        cross = np.array([(b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]) for a, b in edges])
        inside = np.all(cross >= 0, axis=0) | np.all(cross <= 0, axis=0)
        distance = np.where(inside, 0.0, distance)
    return distance


def occupied_cells(shapes, geometry=GEOMETRY):
    cols, rows = np.meshgrid(np.arange(geometry.width), np.arange(geometry.height))
    px, py = geometry.cell_center(cols, rows)
    occupied = np.zeros(px.shape, bool)
    for shape in shapes:
        if isinstance(shape, (Circle, Polygon, Segment)):
            occupied |= _distance(shape, px, py) <= COVER_M
    return occupied


def world_cells(world_name, inside_point, geometry=GEOMETRY, world_path=None):
    """int8 cells (height, width) of the map of tb3_sim's world `world_name` (or of the world file at
    `world_path`); inside_point (x, y) lies in the free space to keep."""
    occupied = occupied_cells(load_world(world_path or shipped_world_path(world_name)).static_shapes, geometry)
    regions, _ = ndimage.label(~occupied)
    col, row = (int(v) for v in geometry.world_to_cell(*inside_point))
    cells = np.full(occupied.shape, -1, np.int8)
    cells[regions == regions[row, col]] = 0
    cells[occupied] = 100
    return cells


def write_map(directory, name, cells, geometry=GEOMETRY):
    """NAME.pgm and NAME.yaml in `directory`, as `map_saver -f NAME` writes them there; returns the yaml path."""
    directory = Path(directory)
    (directory / f"{name}.pgm").write_bytes(pgm_bytes(cells, geometry.resolution))
    (directory / f"{name}.yaml").write_text(yaml_text(f"{name}.pgm", geometry.resolution, geometry.origin_x,
                                                      geometry.origin_y, 0.0))
    return directory / f"{name}.yaml"
