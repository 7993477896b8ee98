"""The inflation layer's costs: how near each cell's centre is to the nearest lethal cell's centre.

cost(d) = 254 at a lethal cell, 253 for d <= inscribed radius, floor(252 * exp(-cost_scaling_factor *
(d - inscribed radius))) for d <= inflation_radius, else 0 (d in m between cell centres), as costmap_2d's
InflationLayer computes it. Distances come from one Euclidean distance transform over the lethal cells' bounding
box grown by the inflation radius: cells outside it are farther than the radius from every lethal cell.
"""
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

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

    def costs(self, lethal, resolution):
        """uint8 inflation costs of a grid whose True cells in the boolean array `lethal` are obstacles."""
        out = np.zeros(lethal.shape, dtype=np.uint8)
        rows, cols = np.nonzero(lethal)
        if rows.size == 0:
            return out
        margin = int(np.ceil(self.inflation_radius / resolution)) + 1
        r0, r1 = max(rows.min() - margin, 0), min(rows.max() + margin + 1, lethal.shape[0])
        c0, c1 = max(cols.min() - margin, 0), min(cols.max() + margin + 1, lethal.shape[1])
        distance = ndimage.distance_transform_edt(~lethal[r0:r1, c0:c1]) * resolution
        out[r0:r1, c0:c1] = self.cost_at(distance)
        return out


def apply(master, inflated):
    """The master grid with inflation added as costmap_2d does: the larger cost wins, except that an unknown
    (255) cell only takes an inflated cost of at least INSCRIBED."""
    unknown = master == NO_INFORMATION
    out = np.maximum(master, inflated)
    out[unknown] = np.where(inflated[unknown] >= INSCRIBED, inflated[unknown], NO_INFORMATION)
    return out
