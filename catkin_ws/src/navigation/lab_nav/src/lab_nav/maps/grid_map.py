"""An occupancy grid as nav_msgs/OccupancyGrid carries it: geometry plus int8 cells, row 0 at the origin (y up)."""

from dataclasses import dataclass

import numpy as np

from lab_nav.maps.geometry import MapGeometry

FREE = 0
OCCUPIED = 100
UNKNOWN = -1


@dataclass(frozen=True)
class GridMap:
    """`cells` is an int8 array of shape (height, width): cells[row, col], row 0 at origin_y, as
    `np.array(msg.data).reshape(height, width)` gives it; values 0 free, 100 occupied, -1 unknown, 1-99 in between."""

    geometry: MapGeometry
    cells: np.ndarray

    def __post_init__(self):
        if self.cells.shape != (self.geometry.height, self.geometry.width):
            raise ValueError("cells have shape {}, the geometry says {} x {} (height x width)".format(
                self.cells.shape, self.geometry.height, self.geometry.width))
