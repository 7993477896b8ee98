"""Map file and frontier search benchmarks for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/map_bench.py

On a gmapping-sized map (384 x 384 cells at 0.05 m: a 10 x 10 m free square with a wall across it, unknown
around), the median over REPEATS runs, in milliseconds of one core:
- map_saver's two files for it (PGM bytes and YAML text; target <= 50 ms, the map arrives once);
- map_server's load of the PGM it wrote (YAML, image read, trinary conversion; <= 300 ms, once per start);
- explore_lite's frontier search from the square's centre (<= 1000 ms: a third of explore.launch's 3 s planning
  period).
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from lab_nav.exploration.costmap_codes import costmap_codes
from lab_nav.exploration.frontier_search import FrontierSearch
from lab_nav.maps.geometry import MapGeometry
from lab_nav.maps.map_loader import load_map
from lab_nav.maps.map_saver_files import pgm_bytes, yaml_text

REPEATS = 7
SIZE_CELLS = 384
RESOLUTION_M = 0.05
ORIGIN_M = -10.0
EXPLORE_LAUNCH = {"potential_scale": 3.0, "gain_scale": 1.0, "min_frontier_size": 0.75}


def sample_cells():
    cells = np.full((SIZE_CELLS, SIZE_CELLS), -1, np.int8)
    cells[92:292, 92:292] = 0
    cells[150:155, 100:250] = 100
    return cells


def median_ms(work):
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return 1000.0 * statistics.median(times)


def run():
    cells = sample_cells()
    geometry = MapGeometry(RESOLUTION_M, SIZE_CELLS, SIZE_CELLS, ORIGIN_M, ORIGIN_M)
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        (folder / "map.pgm").write_bytes(pgm_bytes(cells, RESOLUTION_M))
        (folder / "map.yaml").write_text(yaml_text("map.pgm", RESOLUTION_M, ORIGIN_M, ORIGIN_M, 0.0))
        save_ms = median_ms(lambda: (pgm_bytes(cells, RESOLUTION_M),
                                     yaml_text("map.pgm", RESOLUTION_M, ORIGIN_M, ORIGIN_M, 0.0)))
        load_ms = median_ms(lambda: load_map(str(folder / "map.yaml")))
    codes = costmap_codes(cells)
    search_ms = median_ms(lambda: FrontierSearch(codes, geometry, **EXPLORE_LAUNCH).search_from(0.0, 0.0))
    return [("map_saver files, 384x384 map", save_ms, "ms", 50, "<="),
            ("map_server load, 384x384 PGM", load_ms, "ms", 300, "<="),
            ("explore frontier search, 384x384 map", search_ms, "ms", 1000, "<=")]


if __name__ == "__main__":
    from report import print_table
    print_table(run())
    sys.exit(0)
