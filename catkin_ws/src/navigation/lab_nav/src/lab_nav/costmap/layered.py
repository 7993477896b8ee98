"""A layered costmap as move_base's global and local costmaps build it without a `plugins` list.

Layers, by name: `static_layer` (the map: -1 -> 255, 100 -> 254, else 0; global costmap only), `obstacle_layer`
(laser hits within obstacle_range marked 254, cells along each ray up to raytrace_range cleared to 0, the robot's
footprint cleared; its untouched cells are 0, as track_unknown_space false makes them) and `inflation_layer`.
The master grid is the static layer, then the obstacle layer by maximum (which also overwrites 255 with the
obstacle layer's 0: the published turtlebot3 costmaps have no unknown cells), then inflation around every 254
cell. A rolling window (the local costmap) keeps its obstacle marks in place in the world when it moves.

As costmap_2d does with its layers' update bounds, an update recomputes only what changed: the layers' inputs
since the last update record the box of cells they touched, the update compares the combined grid there with the
last one and re-inflates only around the lethal cells that appeared or went (a scan that marks what the map
already has changes nothing and costs one comparison of its window). A new map, a move of the rolling window,
reset and clear_outside recompute the whole grid. `costs` is replaced, never written in place, so a reader holding
the previous array (a planner, a publisher) keeps a consistent snapshot; `version` counts the changes.

Grids are (height, width) uint8 arrays indexed [row, col]; positions are metres in the costmap's global frame.
"""
from dataclasses import dataclass

import numpy as np

from ..maps.geometry import MapGeometry
from . import cell_box
from . import inflation as inflation_layer
from .footprint import Footprint
from .inflation import Inflation
from .raytrace import cells_along
from .values import FREE, LETHAL, NO_INFORMATION, from_map

OUTLINE_SAMPLES_PER_CELL = 2
"""Points per cell length along the footprint's outline when clearing under it: every half cell visits the cells
its rasterised edges cross, in one numpy pass (a ray trace per edge took 1.8 ms a call, 18 % of move_base's busy
samples at factor 10; this about 0.4 ms, the centres-only clearing 0.34 ms)."""

STATIC_LAYER = "static_layer"
OBSTACLE_LAYER = "obstacle_layer"
INFLATION_LAYER = "inflation_layer"


@dataclass(frozen=True)
class CostmapParams:
    """The costmap_common_params keys that shape the grid (turtlebot3 waffle values as defaults)."""

    footprint: Footprint
    inflation_radius: float = 1.0
    cost_scaling_factor: float = 3.0
    obstacle_range: float = 3.0
    raytrace_range: float = 3.5

    @property
    def inflation(self):
        return Inflation(self.footprint.inscribed_radius, self.inflation_radius, self.cost_scaling_factor)


_WHOLE = "whole grid"


class LayeredCostmap:
    """The master grid of one costmap and its layers. `layers` names them, in order."""

    def __init__(self, geometry, params, static=True):
        self.params = params
        self.geometry = geometry
        self.layers = ((STATIC_LAYER,) if static else ()) + (OBSTACLE_LAYER, INFLATION_LAYER)
        self._inflation = params.inflation
        self._static = None
        self._obstacles = np.zeros((geometry.height, geometry.width), dtype=np.uint8)
        self._master = self._obstacles.copy()
        self._inflated = self._obstacles.copy()
        self.costs = np.zeros_like(self._obstacles)
        self.version = 0
        self._dirty = _WHOLE
        self._framed = None
        self._footprint_cells = None   # ((x, y, yaw, geometry), (cols, rows)) of the last clear_footprint

    def _touched(self, box):
        """Record that the layers may have changed in `box` (a cell_box; _WHOLE for the whole grid)."""
        if self._dirty is not _WHOLE:
            self._dirty = _WHOLE if box is _WHOLE else cell_box.union(self._dirty, box)

    # --- layer inputs -------------------------------------------------------------------------------------
    def set_map(self, geometry, occupancy):
        """Give the static layer a map (int8 data, row-major); a map of another geometry resizes the costmap."""
        if STATIC_LAYER not in self.layers:
            raise ValueError("this costmap has no static layer")
        data = np.asarray(occupancy).reshape(geometry.height, geometry.width)
        if geometry != self.geometry:
            self.geometry = geometry
            self._obstacles = np.zeros((geometry.height, geometry.width), dtype=np.uint8)
        self._static = from_map(data)
        self._touched(_WHOLE)

    def move_to(self, x, y):
        """Centre a rolling window on (x, y): the origin snaps to whole cells; marks keep their world place."""
        g = self.geometry
        col = int(np.floor(x / g.resolution)) - g.width // 2
        row = int(np.floor(y / g.resolution)) - g.height // 2
        new = MapGeometry(g.resolution, g.width, g.height, col * g.resolution, row * g.resolution)
        if new == g:
            return
        shift_c = int(round((new.origin_x - g.origin_x) / g.resolution))
        shift_r = int(round((new.origin_y - g.origin_y) / g.resolution))
        moved = np.zeros_like(self._obstacles)
        h, w = moved.shape
        src_r = slice(max(shift_r, 0), min(h + shift_r, h))
        src_c = slice(max(shift_c, 0), min(w + shift_c, w))
        dst_r = slice(max(-shift_r, 0), max(-shift_r, 0) + (src_r.stop - src_r.start))
        dst_c = slice(max(-shift_c, 0), max(-shift_c, 0) + (src_c.stop - src_c.start))
        if src_r.stop > src_r.start and src_c.stop > src_c.start:
            moved[dst_r, dst_c] = self._obstacles[src_r, src_c]
        self._obstacles = moved
        self.geometry = new
        self._touched(_WHOLE)

    def add_scan(self, sensor_xy, ends_xy, hit, clear=True):
        """Clear along each ray (cut to raytrace_range; unless clear is False) and mark the hits within
        obstacle_range.

        ends_xy (N, 2): the finite readings' end points; hit (N,) bool: the reading is an obstacle (not a
        max-range reading). Non-finite readings must be left out by the caller: they neither mark nor clear.
        """
        ends = np.asarray(ends_xy, dtype=float).reshape(-1, 2)
        origin = np.asarray(sensor_xy, dtype=float)
        offsets = ends - origin
        lengths = np.linalg.norm(offsets, axis=1)
        scale = np.minimum(1.0, self.params.raytrace_range / np.maximum(lengths, 1e-9))
        if clear:
            cols, rows = cells_along(self.geometry, origin, origin + offsets * scale[:, None])
            self._obstacles[rows, cols] = FREE
            self._touched(cell_box.of_cells(rows, cols))
        marking = np.asarray(hit, bool) & (lengths < self.params.obstacle_range)
        cols, rows = self.geometry.world_to_cell(ends[marking, 0], ends[marking, 1])
        inside = self.geometry.contains(cols, rows)
        self._obstacles[rows[inside], cols[inside]] = LETHAL
        self._touched(cell_box.of_cells(rows[inside], cols[inside]))

    def clear_footprint(self, x, y, yaw):
        """Free the obstacle layer's cells under the footprint at (x, y, yaw): those whose centres lie inside it
        and those its outline passes through (costmap_2d fills the polygon's rasterised outline and interior).
        Without the outline's cells a laser mark on a cell the outline crosses, but whose centre lies just
        outside, stayed lethal under a robot touching an obstacle, so every trajectory from there collided and
        the robot stood pressed against a pillar through every later goal.

        The cells of the last pose are kept: a standing robot's pose repeats exactly at every update, and finding
        the cells was a third of a standing move_base's costmap updates (py-spy)."""
        key = (x, y, yaw, self.geometry)
        if self._footprint_cells is None or self._footprint_cells[0] != key:
            self._footprint_cells = (key, self._footprint_cells_at(x, y, yaw))
        cols, rows = self._footprint_cells[1]
        self._obstacles[rows, cols] = FREE
        self._touched(cell_box.of_cells(rows, cols))

    def _footprint_cells_at(self, x, y, yaw):
        """(cols, rows) of the cells clear_footprint frees at (x, y, yaw)."""
        footprint = self.params.footprint
        inside_cols, inside_rows = self.cells_inside(footprint.placed(x, y, yaw))
        outline = footprint.placed(x, y, yaw, footprint.outline(self.geometry.resolution / OUTLINE_SAMPLES_PER_CELL))
        outline_cols, outline_rows = self.geometry.world_to_cell(outline[:, 0], outline[:, 1])
        on_grid = self.geometry.contains(outline_cols, outline_rows)
        return (np.concatenate((inside_cols, outline_cols[on_grid])),
                np.concatenate((inside_rows, outline_rows[on_grid])))

    def cells_inside(self, polygon):
        """(cols, rows) of the in-grid cells whose centres lie inside a convex polygon (K, 2) in m."""
        g = self.geometry
        lo_c, lo_r = g.world_to_cell(*polygon.min(axis=0))
        hi_c, hi_r = g.world_to_cell(*polygon.max(axis=0))
        cc, rr = np.meshgrid(np.arange(max(lo_c, 0), min(hi_c, g.width - 1) + 1),
                             np.arange(max(lo_r, 0), min(hi_r, g.height - 1) + 1))
        cc, rr = cc.ravel(), rr.ravel()
        px, py = g.cell_center(cc, rr)
        edges = np.roll(polygon, -1, axis=0) - polygon
        cross = edges[:, 0, None] * (py - polygon[:, 1, None]) - edges[:, 1, None] * (px - polygon[:, 0, None])
        inside = np.all(cross >= 0, axis=0) | np.all(cross <= 0, axis=0)
        return cc[inside], rr[inside]

    def reset(self):
        """Erase every obstacle mark (clear_costmaps); the static layer keeps its map."""
        self._obstacles[:] = FREE
        self._touched(_WHOLE)

    def clear_outside(self, x, y, size, layer_names):
        """clear_costmap_recovery: reset the named layers' cells outside a size x size m square centred on
        (x, y). Only the obstacle layer can be cleared; any other name, e.g. the recovery default `obstacles`,
        clears nothing (so with turtlebot3's layer names the recoveries clear nothing, as in the original)."""
        if OBSTACLE_LAYER not in layer_names:
            return
        g = self.geometry
        px, py = g.cell_center(np.arange(g.width), np.arange(g.height))
        keep = (np.abs(py - y)[:, None] <= size / 2) & (np.abs(px - x)[None, :] <= size / 2)
        self._obstacles[~keep] = FREE
        self._touched(_WHOLE)

    # --- the master grid ----------------------------------------------------------------------------------
    def update(self):
        """Recompute the master grid where the layers changed since the last update; returns it."""
        dirty, self._dirty = self._dirty, None
        if dirty is _WHOLE:
            self._master = self._combined()
            self._inflated = self._inflation.costs(self._master == LETHAL, self.geometry.resolution)
            self.costs = inflation_layer.apply(self._master, self._inflated)
            self.version += 1
        elif dirty is not None:
            self._update_within(dirty)
        return self.costs

    def _combined(self, box=None):
        """The static and obstacle layers combined (before inflation), in `box` (the whole grid when None)."""
        index = cell_box.slices(box) if box is not None else (slice(None), slice(None))
        obstacles = self._obstacles[index]
        if self._static is None:
            return obstacles.copy()
        master = np.maximum(self._static[index], obstacles)
        unknown = self._static[index] == NO_INFORMATION
        master[unknown] = obstacles[unknown]
        return master

    def _update_within(self, box):
        old, new = self._master[cell_box.slices(box)], self._combined(box)
        changed = cell_box.of_mask(old != new, box)
        if changed is None:
            return
        lethal_changed = cell_box.of_mask((old == LETHAL) != (new == LETHAL), box)
        self._master[cell_box.slices(box)] = new
        if lethal_changed is not None:
            around = cell_box.grown(lethal_changed, self._inflation.margin_cells(self.geometry.resolution),
                                    self._master.shape)
            self._inflated[cell_box.slices(around)] = self._inflation.costs(
                self._master == LETHAL, self.geometry.resolution, around)
            changed = cell_box.union(changed, around)
        costs = self.costs.copy()
        index = cell_box.slices(changed)
        costs[index] = inflation_layer.apply(self._master[index], self._inflated[index])
        self.costs = costs
        self.version += 1

    def cost_at(self, x, y):
        """Master cost (uint8 array) at world points; NO_INFORMATION outside the grid."""
        g = self.geometry
        return self.cost_at_cells((np.asarray(x, dtype=float) - g.origin_x) / g.resolution,
                                  (np.asarray(y, dtype=float) - g.origin_y) / g.resolution)

    def cost_at_cells(self, col, row):
        """Master cost at points given in cells from the origin corner (col = (x - origin_x) / resolution, row
        likewise; fractional), NO_INFORMATION outside the grid.

        One lookup in the grid framed by a border of NO_INFORMATION cells: indices are clipped onto the border,
        so a point anywhere outside reads 255 without a mask (the local planner looks up ~10^5 points a cycle).
        The clip comes before the truncation to int: on the values it leaves (>= 0) truncation is floor, and
        every point left of or below the grid lands on the border.
        """
        g = self.geometry
        if self._framed is None or self._framed[0] is not self.costs:
            framed = np.full((g.height + 2, g.width + 2), NO_INFORMATION, dtype=np.uint8)
            framed[1:-1, 1:-1] = self.costs
            self._framed = (self.costs, framed.ravel())
        col, row = np.asarray(col), np.asarray(row)
        col = np.clip(col + col.dtype.type(1), 0, g.width + 1).astype(np.intp)
        row = np.clip(row + row.dtype.type(1), 0, g.height + 1).astype(np.intp)
        return self._framed[1][row * (g.width + 2) + col]

def changed_box(old, new):
    """(col, row, width, height) of the smallest box holding every cell that differs, or None when none does."""
    if old is None or old.shape != new.shape:
        return (0, 0, new.shape[1], new.shape[0])
    rows, cols = np.nonzero(old != new)
    if rows.size == 0:
        return None
    return (int(cols.min()), int(rows.min()), int(cols.max() - cols.min() + 1), int(rows.max() - rows.min() + 1))
