"""explore_lite's frontier search on a grid of costmap codes, step for step as frontier_search.cpp does it.

- A frontier cell is an unknown cell (NO_INFORMATION) with a free 4-neighbour.
- The search starts at the free cell nearest the robot's cell (breadth-first over 8-neighbours; the robot's cell
  itself if none is free, with a warning) and spreads breadth-first over 4-neighbours whose code is not higher
  than the current cell's. Each new frontier cell it meets seeds a frontier, grown breadth-first over
  8-neighbours through further frontier cells.
- A frontier's size counts its seed plus the cells added; its points, centroid sum and distance skip the seed,
  and the centroid is that sum divided by the size (so it is pulled slightly towards the origin: a quirk of the
  original kept on purpose, since goals are sent to it). min_distance (m) is the distance from the robot's cell
  centre to the nearest added cell centre, and `middle` is that cell.
- Frontiers with size * resolution < min_frontier_size (m) are dropped; the rest get
  cost = potential_scale * min_distance * resolution - gain_scale * size * resolution (the distance is already
  in metres and is scaled by the resolution again, as in the original) and come sorted by cost, lowest first.
Cells are visited in the original's neighbour order (left, right, up, down, then the diagonals), so the same
map gives the same frontiers in the same order.
"""

from collections import deque
from dataclasses import dataclass, field

import numpy as np

from lab_nav.costmap.values import FREE, NO_INFORMATION

OUT_OF_BOUNDS = "Robot out of costmap bounds, cannot search for frontiers"
NO_CLEAR_CELL = "Could not find nearby clear cell to start search"


@dataclass
class Frontier:
    """One frontier; positions are (x, y) cell centres in m in the costmap's frame."""

    initial: tuple
    size: int = 1
    min_distance: float = float("inf")
    middle: tuple = (0.0, 0.0)
    centroid: tuple = (0.0, 0.0)
    cost: float = 0.0
    points: list = field(default_factory=list)


@dataclass
class SearchResult:
    """The frontiers (sorted by cost) and the warning or error the original would log (or None)."""

    frontiers: list
    message: str = None


class FrontierSearch:
    """Searches a grid of costmap codes (uint8, (height, width), row 0 at the origin) laid out by `geometry`
    (a MapGeometry) with explore_lite's potential_scale, gain_scale and min_frontier_size (m)."""

    def __init__(self, codes, geometry, potential_scale, gain_scale, min_frontier_size):
        self._codes = np.asarray(codes, dtype=np.uint8).tobytes()   # bytes: fast int indexing in the searches
        self._geometry = geometry
        self._width, self._height = geometry.width, geometry.height
        self._potential_scale = potential_scale
        self._gain_scale = gain_scale
        self._min_frontier_size = min_frontier_size

    def _nhood4(self, index):
        x, y = index % self._width, index // self._width
        cells = []
        if x > 0:
            cells.append(index - 1)
        if x < self._width - 1:
            cells.append(index + 1)
        if y > 0:
            cells.append(index - self._width)
        if y < self._height - 1:
            cells.append(index + self._width)
        return cells

    def _nhood8(self, index):
        x, y = index % self._width, index // self._width
        cells = self._nhood4(index)
        for dx, dy, allowed in ((-1, -1, x > 0 and y > 0), (1, -1, x < self._width - 1 and y > 0),
                                (-1, 1, x > 0 and y < self._height - 1),
                                (1, 1, x < self._width - 1 and y < self._height - 1)):
            if allowed:
                cells.append(index + dx + dy * self._width)
        return cells

    def _centre(self, index):
        x, y = self._geometry.cell_center(index % self._width, index // self._width)
        return float(x), float(y)

    def _nearest_free(self, start):
        """The free cell nearest `start` (breadth-first over 8-neighbours), or None."""
        visited = {start}
        queue = deque([start])
        while queue:
            index = queue.popleft()
            if self._codes[index] == FREE:
                return index
            for neighbour in self._nhood8(index):
                if neighbour not in visited:
                    visited.add(neighbour)
                    queue.append(neighbour)
        return None

    def _is_new_frontier_cell(self, index, frontier_flag):
        codes = self._codes
        if codes[index] != NO_INFORMATION or frontier_flag[index]:
            return False
        return any(codes[neighbour] == FREE for neighbour in self._nhood4(index))

    def _build_frontier(self, seed, reference, frontier_flag):
        frontier = Frontier(initial=self._centre(seed))
        reference_x, reference_y = self._centre(reference)
        sum_x = sum_y = 0.0
        queue = deque([seed])
        while queue:
            index = queue.popleft()
            for neighbour in self._nhood8(index):
                if not self._is_new_frontier_cell(neighbour, frontier_flag):
                    continue
                frontier_flag[neighbour] = True
                x, y = self._centre(neighbour)
                frontier.points.append((x, y))
                frontier.size += 1
                sum_x, sum_y = sum_x + x, sum_y + y
                distance = ((reference_x - x) ** 2 + (reference_y - y) ** 2) ** 0.5
                if distance < frontier.min_distance:
                    frontier.min_distance, frontier.middle = distance, (x, y)
                queue.append(neighbour)
        frontier.centroid = (sum_x / frontier.size, sum_y / frontier.size)
        return frontier

    def cost(self, frontier):
        resolution = self._geometry.resolution
        return (self._potential_scale * frontier.min_distance * resolution
                - self._gain_scale * frontier.size * resolution)

    def search_from(self, x, y):
        """SearchResult of the frontiers seen from the robot at (x, y) m in the costmap's frame."""
        col, row = self._geometry.world_to_cell(x, y)
        if not self._geometry.contains(col, row):
            return SearchResult([], OUT_OF_BOUNDS)
        position = int(row) * self._width + int(col)
        start = self._nearest_free(position)
        message = None
        if start is None:
            start, message = position, NO_CLEAR_CELL
        frontier_flag = bytearray(len(self._codes))
        visited = bytearray(len(self._codes))
        visited[start] = True
        queue = deque([start])
        frontiers = []
        codes = self._codes
        while queue:
            index = queue.popleft()
            for neighbour in self._nhood4(index):
                if codes[neighbour] <= codes[index] and not visited[neighbour]:
                    visited[neighbour] = True
                    queue.append(neighbour)
                elif codes[neighbour] == NO_INFORMATION and self._is_new_frontier_cell(neighbour, frontier_flag):
                    frontier_flag[neighbour] = True
                    frontier = self._build_frontier(neighbour, position, frontier_flag)
                    if frontier.size * self._geometry.resolution >= self._min_frontier_size:
                        frontiers.append(frontier)
        for frontier in frontiers:
            frontier.cost = self.cost(frontier)
        frontiers.sort(key=lambda frontier: frontier.cost)
        return SearchResult(frontiers, message)
