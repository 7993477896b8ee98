"""A navfn-style global planner: Dijkstra over the costmap between the start cell and the goal cell.

Each step into a cell costs its length in cells (1 or sqrt 2, 8-connected) times the cell's traversal cost
NEUTRAL_COST + COST_FACTOR * cost (navfn's 50 and 0.8), so a path keeps away from inflated walls when that is
cheap. Cells >= 253 (inscribed or lethal) are blocked, the costmap's border cells are blocked, unknown cells (255)
cost as much as the dearest passable cell when allow_unknown is true (navfn's default) and are blocked
otherwise; the start cell is always left (navfn clears it first). The search runs in a window around start and
goal first (WINDOW_MARGIN_M beyond their bounding box) and on the whole costmap only when the window holds no
path: on a 384 x 384 map that keeps a plan to a few milliseconds at move_base's 5 Hz. A goal in a blocked cell
(with no tolerance) fails at once: searching the whole map for it took 0.4 s on a loaded machine, on every
planning attempt of a goal inside an obstacle, in move_base's control loop.

As navfn does, the search spreads from the goal (the cost of every cell's cheapest path to the goal, its
"potential") and the path walks down it from the start. `Navfn` keeps that potential while the costmap array and
the goal stay the same, so replanning at planner_frequency from the robot's new cell costs a walk, not a search;
a search covers the union of the windows asked for so far for the goal (the robot going round an obstacle beyond
the first window widens it once). A path to a reachable cell near an unreachable goal (make_plan's tolerance)
needs the reachable cells around the start, so that search spreads from the start.
"""
import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from ..costmap import cell_box
from ..costmap.values import INSCRIBED, MAX_INFLATED, NO_INFORMATION

NEUTRAL_COST = 50.0
COST_FACTOR = 0.8
UNKNOWN_COST = NEUTRAL_COST + COST_FACTOR * MAX_INFLATED
WINDOW_MARGIN_M = 2.0

_STEPS = ((1, 0, 1.0), (-1, 0, 1.0), (0, 1, 1.0), (0, -1, 1.0),
          (1, 1, np.sqrt(2)), (1, -1, np.sqrt(2)), (-1, 1, np.sqrt(2)), (-1, -1, np.sqrt(2)))


def traversal_costs(costs, allow_unknown=True, window=None):
    """float array: the cost of entering each cell of the window (r0, r1, c0, c1; the whole grid when None),
    np.inf where blocked (>= 253, unknown if not allowed, the grid's border)."""
    costs = np.asarray(costs)
    h, w = costs.shape
    r0, r1, c0, c1 = window or (0, h, 0, w)
    sub = costs[r0:r1, c0:c1]
    out = NEUTRAL_COST + COST_FACTOR * sub.astype(float)
    out[sub >= INSCRIBED] = np.inf
    if allow_unknown:
        out[sub == NO_INFORMATION] = UNKNOWN_COST
    for edge, at_border in (((0, slice(None)), r0 == 0), ((-1, slice(None)), r1 == h),
                            ((slice(None), 0), c0 == 0), ((slice(None), -1), c1 == w)):
        if at_border:
            out[edge] = np.inf
    return out


def _graph(enter, towards_source):
    """The window's cells as a CSR graph with eight edges per cell. With towards_source false an edge costs entering
    its target (a search from the start); with it true an edge runs against the step it stands for and costs
    entering its source (a search from the goal). An edge that cannot be taken is a self-loop instead, so the matrix
    is built straight in CSR form without sorting."""
    h, w = enter.shape
    padded = np.full((h + 2, w + 2), np.inf)
    padded[1:-1, 1:-1] = enter
    inside = np.zeros((h + 2, w + 2), bool)
    inside[1:-1, 1:-1] = True
    index = np.arange(h * w).reshape(h, w)
    targets = np.empty((h, w, len(_STEPS)), dtype=np.int64)
    weights = np.empty((h, w, len(_STEPS)))
    for k, (dc, dr, length) in enumerate(_STEPS):
        neighbour = (slice(1 + dr, h + 1 + dr), slice(1 + dc, w + 1 + dc))
        if towards_source:
            cost = enter * length
            ok = np.isfinite(cost) & inside[neighbour]
        else:
            cost = padded[neighbour] * length
            ok = np.isfinite(cost)
        targets[..., k] = np.where(ok, index + dr * w + dc, index)
        weights[..., k] = np.where(ok, cost, 1.0)
    return csr_matrix((weights.ravel(), targets.ravel(), np.arange(0, h * w * len(_STEPS) + 1, len(_STEPS))),
                      shape=(h * w, h * w))


def _search(costs, allow_unknown, source, window, towards_source=False):
    """Dijkstra from source (col, row) over the window (r0, r1, c0, c1): distances (window-shaped) and
    predecessors over the window's cells (flat indices)."""
    r0, _, c0, _ = window
    enter = traversal_costs(costs, allow_unknown, window)
    if not towards_source:
        enter[source[1] - r0, source[0] - c0] = NEUTRAL_COST
    dist, pred = dijkstra(_graph(enter, towards_source), directed=True,
                          indices=(source[1] - r0) * enter.shape[1] + source[0] - c0, return_predecessors=True)
    return dist.reshape(enter.shape), pred


def _window(shape, cells, margin):
    cols = [c for c, _ in cells]
    rows = [r for _, r in cells]
    return (max(min(rows) - margin, 0), min(max(rows) + margin + 1, shape[0]),
            max(min(cols) - margin, 0), min(max(cols) + margin + 1, shape[1]))


def _usable(shape, start, goal):
    h, w = shape
    return 0 <= start[0] < w and 0 <= start[1] < h and 0 <= goal[0] < w and 0 <= goal[1] < h


def _blocked(costs, cell, allow_unknown):
    window = (cell[1], cell[1] + 1, cell[0], cell[0] + 1)
    if cell[1] in (0, costs.shape[0] - 1) or cell[0] in (0, costs.shape[1] - 1):
        return True
    return not np.isfinite(traversal_costs(costs, allow_unknown, window)[0, 0])


class Navfn:
    """The planner with the goal's potential kept between plans (see the module's docstring)."""

    def __init__(self):
        self._kept = None   # (costs array, goal, allow_unknown, window, dist, pred)

    def plan(self, costs, start, goal, resolution, allow_unknown=True, tolerance_cells=0):
        """The cheapest 8-connected cell path [(col, row), ...] from start to goal, or None when there is none.

        With tolerance_cells > 0 and the goal cell unreachable, the path ends at the reachable cell within that
        many cells of the goal (every third cell, as move_base's make_plan searches) nearest to it.
        """
        costs = np.asarray(costs)
        if not _usable(costs.shape, start, goal):
            return None
        if tolerance_cells > 0:
            return _plan_from_start(costs, start, goal, resolution, allow_unknown, tolerance_cells)
        if goal != start and _blocked(costs, goal, allow_unknown):
            return None
        margin = int(np.ceil(WINDOW_MARGIN_M / resolution))
        h, w = costs.shape
        for window in (_window(costs.shape, (start, goal), margin), (0, h, 0, w)):
            window, dist, pred = self._potential(costs, goal, allow_unknown, window)
            if np.isfinite(dist[start[1] - window[0], start[0] - window[2]]):
                return _walk(pred, start, window)
        return None

    def _potential(self, costs, goal, allow_unknown, window):
        """(window searched, distances, predecessors) of a search from the goal covering `window`."""
        kept = self._kept
        if kept is not None and kept[0] is costs and kept[1] == goal and kept[2] == allow_unknown:
            if cell_box.union(kept[3], window) == kept[3]:
                return kept[3:]
            window = cell_box.union(kept[3], window)
        dist, pred = _search(costs, allow_unknown, goal, window, towards_source=True)
        self._kept = (costs, goal, allow_unknown, window, dist, pred)
        return window, dist, pred


def plan(costs, start, goal, resolution, allow_unknown=True, tolerance_cells=0):
    """Navfn.plan without a kept potential: one plan on a costmap."""
    return Navfn().plan(costs, start, goal, resolution, allow_unknown, tolerance_cells)


def _plan_from_start(costs, start, goal, resolution, allow_unknown, tolerance_cells):
    margin = int(np.ceil(WINDOW_MARGIN_M / resolution)) + tolerance_cells
    h, w = costs.shape
    for window in (_window(costs.shape, (start, goal), margin), (0, h, 0, w)):
        dist, pred = _search(costs, allow_unknown, start, window)
        end = _reached_goal(dist, goal, window, tolerance_cells)
        if end is not None:
            return _walk(pred, end, window)[::-1]
    return None


def _reached_goal(dist, goal, window, tolerance_cells):
    r0, r1, c0, c1 = window
    candidates = [(0, 0)] + sorted(((dc, dr) for dc in range(-tolerance_cells, tolerance_cells + 1, 3)
                                    for dr in range(-tolerance_cells, tolerance_cells + 1, 3) if dc or dr),
                                   key=lambda d: d[0] ** 2 + d[1] ** 2)
    for dc, dr in candidates:
        col, row = goal[0] + dc, goal[1] + dr
        if r0 <= row < r1 and c0 <= col < c1 and np.isfinite(dist[row - r0, col - c0]):
            return col, row
    return None


def _walk(pred, cell, window):
    """The cells from `cell` along the predecessors to the search's source, in the grid's (col, row)."""
    r0, _, c0, c1 = window
    width = c1 - c0
    node = (cell[1] - r0) * width + cell[0] - c0
    cells = []
    while node >= 0:
        row, col = divmod(int(node), width)
        cells.append((col + c0, row + r0))
        node = pred[node]
    return cells


def path_cost(costs, cells, allow_unknown=True):
    """The planner's cost of a cell path (the sum of step length x entry cost), for tests and benchmarks."""
    enter = traversal_costs(costs, allow_unknown)
    total = 0.0
    for (c0, r0), (c1, r1) in zip(cells, cells[1:]):
        total += np.hypot(c1 - c0, r1 - r0) * enter[r1, c1]
    return total
