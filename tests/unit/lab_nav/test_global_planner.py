"""The navfn-style planner: cheapest path within the costmap's cost, blocked cells and border, tolerance."""
import heapq
import itertools

import numpy as np
import pytest

from lab_nav.costmap.values import INSCRIBED, LETHAL, NO_INFORMATION
from lab_nav.planning import global_planner
from lab_nav.planning.global_planner import path_cost, plan, traversal_costs


def _reference_cost(costs, start, goal):
    """A plain Dijkstra, written independently, over the same step costs."""
    enter = traversal_costs(costs)
    enter[start[1], start[0]] = global_planner.NEUTRAL_COST
    best = {start: 0.0}
    queue = [(0.0, start)]
    while queue:
        d, (c, r) = heapq.heappop(queue)
        if (c, r) == goal:
            return d
        if d > best[(c, r)]:
            continue
        for dc, dr in itertools.product((-1, 0, 1), repeat=2):
            n = (c + dc, r + dr)
            if (dc or dr) and 0 <= n[0] < costs.shape[1] and 0 <= n[1] < costs.shape[0] \
                    and np.isfinite(enter[n[1], n[0]]):
                nd = d + np.hypot(dc, dr) * enter[n[1], n[0]]
                if nd < best.get(n, np.inf):
                    best[n] = nd
                    heapq.heappush(queue, (nd, n))
    return None


@pytest.mark.parametrize("seed", range(5))
def test_the_path_is_the_cheapest_within_the_costmaps_cost(seed):
    rng = np.random.default_rng(seed)
    costs = rng.choice([0, 0, 0, 40, 120, 252, LETHAL], size=(30, 40)).astype(np.uint8)
    costs[5, 5] = costs[25, 33] = 0
    path = plan(costs, (5, 5), (33, 25), 0.05)
    reference = _reference_cost(costs, (5, 5), (33, 25))
    if reference is None:
        assert path is None
        return
    assert path[0] == (5, 5) and path[-1] == (33, 25)
    assert all(max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1 for a, b in zip(path, path[1:]))
    assert path_cost(costs, path) == pytest.approx(reference)


def test_inscribed_and_lethal_cells_and_the_border_are_blocked():
    costs = np.zeros((20, 20), np.uint8)
    costs[:, 10] = INSCRIBED
    costs[0, :] = 0
    assert plan(costs, (5, 10), (15, 10), 0.05) is None   # the only gap would be the border row
    costs[10, 10] = 252
    path = plan(costs, (5, 10), (15, 10), 0.05)
    assert (10, 10) in path and all(costs[r, c] < INSCRIBED for c, r in path)
    costs[10, 10] = LETHAL
    assert plan(costs, (5, 10), (10, 10), 0.05) is None


def test_the_start_cell_is_cleared_and_unknown_space_is_allowed_by_default():
    costs = np.full((20, 20), NO_INFORMATION, np.uint8)
    costs[5, 5] = INSCRIBED
    assert plan(costs, (5, 5), (15, 15), 0.05) is not None
    assert plan(costs, (5, 5), (15, 15), 0.05, allow_unknown=False) is None


def test_a_path_leaves_the_window_when_it_must():
    costs = np.zeros((200, 200), np.uint8)
    costs[10:190, 100] = LETHAL
    path = plan(costs, (90, 100), (110, 100), 0.05)
    rows = [r for _, r in path]
    assert min(rows) < 10 or max(rows) >= 190


def test_tolerance_ends_the_path_near_an_unreachable_goal():
    costs = np.zeros((40, 40), np.uint8)
    costs[18:23, 18:23] = LETHAL
    assert plan(costs, (5, 5), (20, 20), 0.05) is None
    path = plan(costs, (5, 5), (20, 20), 0.05, tolerance_cells=6)
    end = path[-1]
    assert costs[end[1], end[0]] == 0 and max(abs(end[0] - 20), abs(end[1] - 20)) <= 6


def test_a_goal_in_a_blocked_cell_fails_without_a_search(monkeypatch):
    costs = np.zeros((40, 40), np.uint8)
    costs[18:23, 18:23] = LETHAL
    costs[17, 20] = INSCRIBED

    def no_search(*_args):
        raise AssertionError("searched")
    monkeypatch.setattr(global_planner, "_search", no_search)
    assert plan(costs, (5, 5), (20, 20), 0.05) is None
    assert plan(costs, (5, 5), (20, 17), 0.05) is None


def _count_searches(monkeypatch):
    searches = []
    real = global_planner._search

    def counted(*args, **kwargs):
        searches.append(args[3])
        return real(*args, **kwargs)
    monkeypatch.setattr(global_planner, "_search", counted)
    return searches


def test_replanning_on_the_same_costmap_and_goal_walks_the_kept_potential(monkeypatch):
    rng = np.random.default_rng(7)
    costs = rng.choice([0, 0, 0, 40, 120, LETHAL], size=(120, 120)).astype(np.uint8)
    costs[10, 10] = costs[100, 100] = 0
    searches = _count_searches(monkeypatch)
    navfn = global_planner.Navfn()
    first = navfn.plan(costs, (10, 10), (100, 100), 0.05)
    later = first[len(first) // 2]
    again = navfn.plan(costs, later, (100, 100), 0.05)
    assert len(searches) == 1
    assert path_cost(costs, again) == pytest.approx(_reference_cost(costs, later, (100, 100)))
    changed = costs.copy()
    navfn.plan(changed, later, (100, 100), 0.05)   # a new costmap array: a new search
    navfn.plan(changed, later, (10, 10), 0.05)     # a new goal: a new search
    assert len(searches) == 3


def test_a_start_beyond_the_kept_window_widens_it():
    costs = np.zeros((300, 300), np.uint8)
    navfn = global_planner.Navfn()
    navfn.plan(costs, (150, 150), (160, 150), 0.05)
    window = navfn._kept[3]
    path = navfn.plan(costs, (150, 20), (160, 150), 0.05)
    assert path[0] == (150, 20) and path[-1] == (160, 150)
    assert path_cost(costs, path) == pytest.approx(_reference_cost(costs, (150, 20), (160, 150)))
    widened = navfn._kept[3]
    assert widened[0] < window[0] and widened[1:] == window[1:]
