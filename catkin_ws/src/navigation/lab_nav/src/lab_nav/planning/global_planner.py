"""A navfn-style global planner: Dijkstra over the costmap from the start cell to the goal cell.

Each step into a cell costs its length in cells (1 or sqrt 2, 8-connected) times the cell's traversal cost
NEUTRAL_COST + COST_FACTOR * cost (navfn's 50 and 0.8), so a path keeps away from inflated walls when that is
cheap. Cells >= 253 (inscribed or lethal) are blocked, the costmap's border cells are blocked, unknown cells (255)
cost as much as the dearest passable cell when allow_unknown is true (navfn's default) and are blocked
otherwise; the start cell is always left (navfn clears it first). The search runs in a window around start and
goal first (WINDOW_MARGIN_M beyond their bounding box) and on the whole costmap only when the window holds no
path: on a 384 x 384 map that keeps a plan to a few milliseconds at move_base's 5 Hz. A goal in a blocked cell
(with no tolerance) fails at once: searching the whole map for it took 0.4 s on a loaded machine, on every
planning attempt of a goal inside an obstacle, in move_base's control loop.
"""
import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from ..costmap.values import INSCRIBED, MAX_INFLATED, NO_INFORMATION

NEUTRAL_COST = 50.0
COST_FACTOR = 0.8
UNKNOWN_COST = NEUTRAL_COST + COST_FACTOR * MAX_INFLATED
WINDOW_MARGIN_M = 2.0

_STEPS = ((1, 0, 1.0), (-1, 0, 1.0), (0, 1, 1.0), (0, -1, 1.0),
          (1, 1, np.sqrt(2)), (1, -1, np.sqrt(2)), (-1, 1, np.sqrt(2)), (-1, -1, np.sqrt(2)))


def traversal_costs(costs, allow_unknown=True):
    """float array: the cost of entering each cell, np.inf where blocked (>= 253, unknown if not allowed,
    the border)."""
    costs = np.asarray(costs)
    out = NEUTRAL_COST + COST_FACTOR * costs.astype(float)
    out[costs >= INSCRIBED] = np.inf
    if allow_unknown:
        out[costs == NO_INFORMATION] = UNKNOWN_COST
    out[0, :] = out[-1, :] = out[:, 0] = out[:, -1] = np.inf
    return out


def _search(enter, start, window):
    """Dijkstra from start (col, row) over the window (r0, r1, c0, c1) of the entry-cost grid: distances and
    predecessors over the window's cells (flat indices).

    The graph has eight edges per cell; an edge into a blocked or outside cell is a self-loop instead, so the
    matrix is built straight in CSR form without sorting.
    """
    r0, r1, c0, c1 = window
    sub = enter[r0:r1, c0:c1].copy()
    sub[start[1] - r0, start[0] - c0] = NEUTRAL_COST
    h, w = sub.shape
    padded = np.full((h + 2, w + 2), np.inf)
    padded[1:-1, 1:-1] = sub
    index = np.arange(h * w).reshape(h, w)
    targets = np.empty((h, w, len(_STEPS)), dtype=np.int64)
    weights = np.empty((h, w, len(_STEPS)))
    for k, (dc, dr, length) in enumerate(_STEPS):
        cost = padded[1 + dr:h + 1 + dr, 1 + dc:w + 1 + dc] * length
        ok = np.isfinite(cost)
        targets[..., k] = np.where(ok, index + dr * w + dc, index)
        weights[..., k] = np.where(ok, cost, 1.0)
    graph = csr_matrix((weights.ravel(), targets.ravel(), np.arange(0, h * w * len(_STEPS) + 1, len(_STEPS))),
                       shape=(h * w, h * w))
    dist, pred = dijkstra(graph, directed=True, indices=(start[1] - r0) * w + start[0] - c0,
                          return_predecessors=True)
    return dist.reshape(h, w), pred


def _window(shape, cells, margin):
    cols = [c for c, _ in cells]
    rows = [r for _, r in cells]
    return (max(min(rows) - margin, 0), min(max(rows) + margin + 1, shape[0]),
            max(min(cols) - margin, 0), min(max(cols) + margin + 1, shape[1]))


def plan(costs, start, goal, resolution, allow_unknown=True, tolerance_cells=0):
    """The cheapest 8-connected cell path [(col, row), ...] from start to goal, or None when there is none.

    With tolerance_cells > 0 and the goal cell unreachable, the path ends at the reachable cell within that
    many cells of the goal (every third cell, as move_base's make_plan searches) nearest to it.
    """
    enter = traversal_costs(costs, allow_unknown)
    h, w = enter.shape
    if not (0 <= start[0] < w and 0 <= start[1] < h and 0 <= goal[0] < w and 0 <= goal[1] < h):
        return None
    if tolerance_cells == 0 and goal != start and not np.isfinite(enter[goal[1], goal[0]]):
        return None
    margin = int(np.ceil(WINDOW_MARGIN_M / resolution)) + tolerance_cells
    for window in (_window(enter.shape, (start, goal), margin), (0, h, 0, w)):
        dist, pred = _search(enter, start, window)
        end = _reached_goal(dist, goal, window, tolerance_cells)
        if end is not None:
            return _backtrack(pred, end, window, dist.shape[1])
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


def _backtrack(pred, end, window, width):
    r0, _, c0, _ = window
    node = (end[1] - r0) * width + end[0] - c0
    cells = []
    while node >= 0:
        row, col = divmod(int(node), width)
        cells.append((col + c0, row + r0))
        node = pred[node]
    return cells[::-1]


def path_cost(costs, cells, allow_unknown=True):
    """The planner's cost of a cell path (the sum of step length x entry cost), for tests and benchmarks."""
    enter = traversal_costs(costs, allow_unknown)
    total = 0.0
    for (c0, r0), (c1, r1) in zip(cells, cells[1:]):
        total += np.hypot(c1 - c0, r1 - r0) * enter[r1, c1]
    return total
