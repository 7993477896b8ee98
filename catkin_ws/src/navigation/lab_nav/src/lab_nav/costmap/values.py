"""The uint8 cost values of costmap_2d and their translation into OccupancyGrid data.

0 free; 1-252 inflated cost that falls with the distance to the nearest lethal cell; 253 inscribed (the robot's
centre here puts an obstacle inside its inscribed circle); 254 lethal (an obstacle in this cell); 255 no
information. Published grids carry 0 -> 0, 1-252 -> 1 + 97 * (c - 1) div 251 (1-98), 253 -> 99, 254 -> 100 and
255 -> -1, as costmap_2d's publisher translates them.
"""
import numpy as np

FREE = 0
MAX_INFLATED = 252
INSCRIBED = 253
LETHAL = 254
NO_INFORMATION = 255

OCCUPIED_MAP_VALUE = 100
"""Map cells at or above this (static layer's lethal_cost_threshold) become LETHAL."""


def _translation_table():
    table = np.zeros(256, dtype=np.int8)
    costs = np.arange(1, MAX_INFLATED + 1)
    table[1:MAX_INFLATED + 1] = 1 + (97 * (costs - 1)) // 251
    table[INSCRIBED] = 99
    table[LETHAL] = 100
    table[NO_INFORMATION] = -1
    return table


COST_TO_OCCUPANCY = _translation_table()


def to_occupancy(costs):
    """int8 array of OccupancyGrid values for a uint8 cost array (same shape)."""
    return COST_TO_OCCUPANCY[np.asarray(costs, dtype=np.uint8)]


def from_map(occupancy):
    """The static layer's uint8 costs of map data (int8 -1/0..100): >= 100 lethal, -1 no information, else free.

    The trinary translation costmap_2d's static layer makes with trinary_costmap true (the default): map values
    1-99 are free, only 100 is an obstacle.
    """
    data = np.asarray(occupancy).astype(np.int16)
    costs = np.full(data.shape, FREE, dtype=np.uint8)
    costs[data < 0] = NO_INFORMATION
    costs[data >= OCCUPIED_MAP_VALUE] = LETHAL
    return costs
