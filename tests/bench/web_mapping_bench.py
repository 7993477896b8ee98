"""lab_web through a whole mapping session, for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/web_mapping_bench.py [real_time_factor] [sim_seconds]

Starts a private roscore, turtlebot3_world.launch (headless) at `real_time_factor` (default 10, the highest at
which gmapping keeps every map update: slam_bench), turtlebot3_slam.launch (gmapping, no rviz), lab_web's server
and ONE headless Chromium page, then drives the SLAM tests' route (tests/integration/turtlebot3_slam/route_driver.py)
and lets the session run to SESSION_SIM_S of sim time (10 minutes) with the page open. Every SAMPLE_S of wall time
the page's JavaScript heap is measured after a garbage collection (Chrome DevTools' Performance.getMetrics,
JSHeapUsedSize). Rows:
- the page's heap at the first map and at the end, and its growth from the first quarter's median to the last
  quarter's (target <= 2 MB: flat, a page that kept every map or trail would grow by tens of MB);
- the session's real-time factor (map frames drawn are printed as it runs);
- the cells where the map the page draws (labView.mapPng) differs from /map drawn by the server's own palette
  (lab_web.occupancy: target 0), once the session is paused.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import base64
import statistics
import subprocess
import sys
import time
from pathlib import Path

import cv2
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from web_bench import master_and_browser, open_page, start_web_server  # noqa: E402

from lab_web import occupancy  # noqa: E402
from roslab import wait_for_param, wait_for_service, wait_until  # noqa: E402
from roslab.mapping_routes import ROUTES  # noqa: E402

REAL_TIME_FACTOR = 10.0
SESSION_SIM_S = 600.0
SAMPLE_S = 5.0
PAUSED_SETTLE_S = 3.0
"""Wall seconds after pausing for gmapping's last map to reach the page."""
HEAP_GROWTH_TARGET_MB = 2.0
WORLD = "turtlebot3_world"
DRIVER = Path(__file__).resolve().parents[1] / "integration" / "turtlebot3_slam" / "route_driver.py"
MB = 1024.0 * 1024.0


def drawn_map(browser):
    """The page's map as an (H, W, 3) RGB array, row 0 the lowest y (as /map's data)."""
    return png_pixels(browser.script("return labView.mapPng();").split(",", 1)[1])


def served_map(grid):
    """/map (a probe dict) drawn with lab_web's palette, as the page should show it."""
    info = grid["info"]
    return png_pixels(occupancy.grid_png(grid["data"], info["width"], info["height"]))


def png_pixels(base64_png):
    bgr = cv2.imdecode(np.frombuffer(base64.b64decode(base64_png), np.uint8), cv2.IMREAD_COLOR)
    return cv2.cvtColor(bgr, cv2.COLOR_BGR2RGB)


def differing_cells(master, probe, browser):
    """Cells where the page's map differs from /map once the session is paused (/gazebo/pause_physics stops the
    clock, so gmapping publishes no newer map meanwhile); the probe subscribes only then: /map is latched."""
    subprocess.run(["rosservice", "call", "/gazebo/pause_physics"], env=master.env, check=True,
                   stdout=subprocess.DEVNULL, timeout=30)
    time.sleep(PAUSED_SETTLE_S)
    probe.subscribe("/map", "nav_msgs/OccupancyGrid")
    served = served_map(probe.wait_for_message("/map", 30))
    drawn = drawn_map(browser)
    return served.size // 3 if drawn.shape != served.shape else int(np.any(drawn != served, axis=2).sum())


def measure(factor=REAL_TIME_FACTOR, session_sim_s=SESSION_SIM_S):
    with master_and_browser("web_mapping_bench_") as (master, browser):
        route = ROUTES[WORLD]
        master.roslaunch(*route.launch, "gui:=false", "real_time_factor:={:g}".format(factor))
        wait_for_service(master.uri, "/gazebo/get_model_state", 60)
        wait_for_param(master.uri, "/use_sim_time")
        master.roslaunch("turtlebot3_slam", "turtlebot3_slam.launch", "open_rviz:=false")
        wait_for_service(master.uri, "/dynamic_map", 60)
        url = start_web_server(master)
        open_page(browser, url, "labView.connected && labView.robot && labView.maps > 0")
        probe = master.probe()
        master.start([sys.executable, str(DRIVER), WORLD, str(master.workdir / "route.json")], "driver")
        sim_start, wall_start = probe.now(), time.monotonic()
        maps_start = browser.script("return labView.maps;")
        samples = [browser.js_heap_bytes()]
        while probe.now() - sim_start < session_sim_s:
            time.sleep(SAMPLE_S)
            samples.append(browser.js_heap_bytes())
            print("  sim {:5.0f} s  heap {:5.1f} MB  maps drawn {}".format(
                probe.now() - sim_start, samples[-1] / MB, browser.script("return labView.maps;") - maps_start),
                flush=True)
        wall = time.monotonic() - wall_start
        rtf = (probe.now() - sim_start) / wall
        maps = browser.script("return labView.maps;") - maps_start
        wait_until(lambda: browser.script("return labView.mapPng() !== null;"), 10, "the page's map")
        differing = differing_cells(master, probe, browser)
        quarter = max(1, len(samples) // 4)
        growth = statistics.median(samples[-quarter:]) - statistics.median(samples[:quarter])
        return {"heap_start": samples[0] / MB, "heap_end": samples[-1] / MB, "growth": growth / MB,
                "maps": maps, "rtf": rtf, "differing": differing, "wall": wall}


def run(factor=REAL_TIME_FACTOR, session_sim_s=SESSION_SIM_S):
    """scripts/bench rows: a mapping session in turtlebot3_world with one page open."""
    result = measure(factor, session_sim_s)
    label = "{:g} s of sim time".format(session_sim_s)
    return [
        ("lab_web page heap at the first map", result["heap_start"], "MB", 20.0, "<="),
        ("lab_web page heap after " + label, result["heap_end"], "MB", 20.0, "<="),
        ("lab_web page heap growth over the session", result["growth"], "MB", HEAP_GROWTH_TARGET_MB, "<="),
        ("mapping session's real-time factor", result["rtf"], "x", factor, ">="),
        ("page's final map cells differing from /map", result["differing"], "cells", 0, "<="),
    ]


if __name__ == "__main__":
    from report import print_table
    arguments = [float(value) for value in sys.argv[1:3]]
    print_table(run(*arguments))
