"""Where a grid's cells are in the world, as nav_msgs/MapMetaData defines it.

Cell (col, row) covers x in [origin_x + col*res, origin_x + (col+1)*res), likewise y; data are row-major from
(0, 0) at the origin corner (x fastest, y up), so the flat index is row * width + col. origin_yaw is kept for
map files that set it (map_server reads it, map_saver writes it); the cell maths assume it is 0, as every map
gmapping and the TurtleBot3 courses make.
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class MapGeometry:
    """Resolution in m/cell, size in cells, origin (the lower-left corner of cell (0, 0)) in m and rad."""

    resolution: float
    width: int
    height: int
    origin_x: float
    origin_y: float
    origin_yaw: float = 0.0

    def world_to_cell(self, x, y):
        """(col, row) integer arrays (or ints) of the cells holding the points; may lie outside the grid."""
        col = np.floor((np.asarray(x, dtype=float) - self.origin_x) / self.resolution).astype(int)
        row = np.floor((np.asarray(y, dtype=float) - self.origin_y) / self.resolution).astype(int)
        return col, row

    def cell_center(self, col, row):
        """(x, y) in m of the cells' centres."""
        x = self.origin_x + (np.asarray(col, dtype=float) + 0.5) * self.resolution
        y = self.origin_y + (np.asarray(row, dtype=float) + 0.5) * self.resolution
        return x, y

    def contains(self, col, row):
        """Boolean (array): the cells lie inside the grid."""
        col, row = np.asarray(col), np.asarray(row)
        return (col >= 0) & (col < self.width) & (row >= 0) & (row < self.height)
