"""OccupancyGrid values mapped back to costmap_2d's cell codes, as explore_lite's costmap client maps /map.

0 -> 0 (free), 99 -> 253 (inscribed), 100 -> 254 (lethal), -1 -> 255 (no information), and 1-98 linearly onto
1-252 by 1 + 251 * (v - 1) / 97 in integer arithmetic. Values outside -1..100 (which no map server sends) go
through the same formula on their unsigned byte and wrap, as in the original's lookup table.
"""

import numpy as np

FREE_SPACE = 0
INSCRIBED_INFLATED_OBSTACLE = 253
LETHAL_OBSTACLE = 254
NO_INFORMATION = 255


def _translation_table():
    values = np.arange(256, dtype=np.int64)
    table = ((1 + (251 * (values - 1)) // 97) & 0xFF).astype(np.uint8)
    table[0] = FREE_SPACE
    table[99] = INSCRIBED_INFLATED_OBSTACLE
    table[100] = LETHAL_OBSTACLE
    table[255] = NO_INFORMATION   # -1 as an unsigned byte
    return table


TRANSLATION_TABLE = _translation_table()


def costmap_codes(occupancy):
    """uint8 costmap codes of an array of OccupancyGrid values (int8 or ints in -128..127), same shape."""
    return TRANSLATION_TABLE[np.asarray(occupancy).astype(np.int8).view(np.uint8)]
