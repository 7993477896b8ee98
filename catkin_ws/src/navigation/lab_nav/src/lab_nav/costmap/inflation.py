"""The inflation layer's costs: how near each cell's centre is to the nearest lethal cell's centre.

cost(d) = 254 at a lethal cell, 253 for d <= inscribed radius, floor(252 * exp(-cost_scaling_factor *
(d - inscribed radius))) for d <= inflation_radius, else 0 (d in m between cell centres), as costmap_2d's
InflationLayer computes it. Distances come from one Euclidean distance transform over the lethal cells' bounding
box grown by the inflation radius: cells outside it are farther than the radius from every lethal cell. A part of
the grid (a box) needs only the lethal cells within the radius of it, so a costmap update that changed a few cells
recomputes their neighbourhood only, as costmap_2d's inflation layer does within its update bounds.
"""
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from . import cell_box
from .values import FREE, INSCRIBED, LETHAL, MAX_INFLATED, NO_INFORMATION


@dataclass(frozen=True)
class Inflation:
    """inscribed_radius and inflation_radius in m, cost_scaling_factor in 1/m (turtlebot3: 1.0 and 3.0)."""

    inscribed_radius: float
    inflation_radius: float = 1.0
    cost_scaling_factor: float = 3.0

    def cost_at(self, distance):
        """The inflated cost (uint8 array) of cells `distance` m from the nearest lethal cell's centre."""
        d = np.asarray(distance, dtype=float)
        cost = np.floor(MAX_INFLATED * np.exp(-self.cost_scaling_factor * (d - self.inscribed_radius)))
        cost = np.where(d > self.inflation_radius, FREE, cost)
        cost = np.where(d <= self.inscribed_radius, INSCRIBED, cost)
        return np.where(d <= 0.0, LETHAL, cost).astype(np.uint8)

    def margin_cells(self, resolution):
        """How many cells around a changed lethal cell its inflation can reach (the radius, and one cell more)."""
        return int(np.ceil(self.inflation_radius / resolution)) + 1

    def costs(self, lethal, resolution, box=None):
        """uint8 inflation costs of the cells in `box` (cell_box; the whole grid when None) of a grid whose True
        cells in the boolean array `lethal` are obstacles."""
        shape = lethal.shape
        box = box or (0, shape[0], 0, shape[1])
        out = np.zeros((box[1] - box[0], box[3] - box[2]), dtype=np.uint8)
        margin = self.margin_cells(resolution)
        near = cell_box.grown(box, margin, shape)
        rows, cols = np.nonzero(lethal[cell_box.slices(near)])
        if rows.size == 0:
            return out
        reach = cell_box.grown(cell_box.of_cells(rows + near[0], cols + near[2]), margin, shape)
        region = cell_box.intersection(reach, near)
        inner = cell_box.intersection(region, box)
        if inner is None:
            return out
        distance = ndimage.distance_transform_edt(~lethal[cell_box.slices(region)]) * resolution
        out[cell_box.slices(inner, box)] = self.cost_at(distance[cell_box.slices(inner, region)])
        return out


def apply(master, inflated):
    """The master grid with inflation added as costmap_2d does: the larger cost wins, except that an unknown
    (255) cell only takes an inflated cost of at least INSCRIBED."""
    unknown = master == NO_INFORMATION
    out = np.maximum(master, inflated)
    out[unknown] = np.where(inflated[unknown] >= INSCRIBED, inflated[unknown], NO_INFORMATION)
    return out
