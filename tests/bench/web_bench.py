"""lab_web benchmarks for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/web_bench.py [seconds]

Starts a private roscore, tb3_sim at real time through the Week 4 demo (week4_demo.launch, headless, the
Waffle's 1920x1080 camera as a student has it), lab_web's server (rosrun lab_web web_server on a free port) and
ONE headless Chromium page (roslab.browser.HeadlessBrowser) connected to it. The probe publishes one /cmd_vel
turning the robot slowly (tb3_sim keeps the last command), so every state frame carries something new. Then,
over ~20 s of wall time:
- CPU of the lab_web server process (user + system, all threads) as % of one core (target <= 5 %);
- state-to-page latency, the page's `labView.latenciesMs` (Date.now() when a frame is handled minus the frame's
  stamp_ms, the wall time the newest /odom or /scan reached the server): median and 95th percentile (<= 100 ms);
- state frames per second the page handled (`labView.frames` over the window; target >= 20, the server sends
  at most 25);
- then a 384 x 384 map (gmapping's size for the course arenas at 0.05 m: a free room with walls in unknown space)
  published every 2 s as gmapping does, over MAP_MEASURE_S: the map frame's size (base64 PNG), map frames per
  second the page drew, and the server's CPU with the map panel following /tf as well;
- then the camera shown on the page ("Show camera" ticked) over CAMERA_MEASURE_S: tb3_sim's real-time factor
  (sim seconds over wall seconds, target >= 0.97 at factor 1), the simulator's CPU (rendering and JPEG-encoding
  1920x1080 frames while lab_web takes its snapshots) and the server's CPU (a snapshot of the compressed images
  every 0.5 s, decoded at a quarter size), and the thumbnails per second the page showed;
- then, on a master of its own, navigation at real time (turtlebot3_world, map_server, amcl, move_base:
  tests/integration/navigation/stack.py) with the page showing the map, both costmaps, both plans, the particle
  cloud, amcl's pose and the goal while the robot drives to NAV_GOAL: the server's CPU over NAV_MEASURE_S (target
  <= 10 % of a core) and the state-to-page latency's 95th percentile.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import contextlib
import sys
import tempfile
import time
from pathlib import Path

import numpy

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation.stack import start_navigation, turtlebot3_world_cells  # noqa: E402

from roslab import RosMaster, free_port, http_status, nav_goals, wait_for_service, wait_for_topic, wait_until  # noqa: E402
from roslab.browser import HeadlessBrowser  # noqa: E402
from roslab.graph import node_pid  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402

MEASURE_S = 20.0
SETTLE_S = 3.0
"""Wall seconds after the page connected and the robot started turning, before measuring (start-up excluded)."""
TURN_RAD_S = 0.3
CPU_TARGET_PERCENT = 5.0
LATENCY_TARGET_MS = 100.0
FPS_TARGET = 20.0
MAP_MEASURE_S = 10.0
MAP_CELLS = 384
MAP_PERIOD_S = 2.0
CAMERA_MEASURE_S = 15.0
CAMERA_SETTLE_S = 3.0
RTF_TARGET = 0.97
DEMO = ("week4_services", "week4_demo.launch", "gui:=false")
NAV_GOAL = (0.5, 1.8)
"""turtlebot3_world point (m, map frame) the robot drives to from the spawn point, round the pillars."""
NAV_MEASURE_S = 15.0


@contextlib.contextmanager
def master_and_browser(prefix):
    """A private roscore (RosMaster in a temporary folder named with `prefix`) and a headless Chromium: yields
    (master, browser); the browser is quit and every process on the master ended afterwards."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix=prefix)))
    try:
        browser = HeadlessBrowser()
        try:
            yield master, browser
        finally:
            browser.quit()
    finally:
        master.shutdown()


def start_web_server(master):
    """rosrun lab_web web_server on a free port against `master`; returns the page's URL once it serves."""
    port = free_port()
    server = master.rosrun("lab_web", "web_server", "_port:={}".format(port))
    base = "http://127.0.0.1:{}/".format(port)
    wait_until(lambda: http_status(base + "static/app.js") == 200 or not server.running(), 30, "lab_web to serve")
    if not server.running():
        raise RuntimeError("lab_web's web_server exited:\n" + server.output())
    return base


def open_page(browser, url, ready):
    """Load `url` and wait until the page's `ready` JavaScript expression is true."""
    browser.driver.get(url)
    wait_until(lambda: browser.script("return typeof labView !== 'undefined' && !!({});".format(ready)), 30,
               "the page: " + ready)


def measure_with_page(duration_s=MEASURE_S):
    """{"cpu": % of a core, "p50": ms, "p95": ms, "fps": frames/s, "samples": latencies} with the demo, the
    server and one connected page, the robot turning at TURN_RAD_S."""
    with master_and_browser("web_bench_") as (master, browser):
        master.roslaunch(*DEMO)
        wait_for_service(master.uri, "/gazebo/get_world_properties", 60)
        wait_for_topic(master.uri, "/odom", 60)
        open_page(browser, start_web_server(master), "labView.connected && labView.robot")
        probe = master.probe()
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {"angular": {"z": TURN_RAD_S}})
        time.sleep(SETTLE_S)
        pid = node_pid(master.uri, "/lab_web")
        browser.script("labView.latenciesMs.length = 0;")
        frames_start = browser.script("return labView.frames;")
        simulator_pid = node_pid(master.uri, "/gazebo")
        sim_start, sim_cpu_start = probe.now(), cpu_seconds(simulator_pid)
        cpu_start, wall_start = cpu_seconds(pid), time.monotonic()
        time.sleep(duration_s)
        cpu_used = cpu_seconds(pid) - cpu_start
        sim_end, sim_cpu_end = probe.now(), cpu_seconds(simulator_pid)
        frames_end = browser.script("return labView.frames;")
        latencies = browser.script("return labView.latenciesMs.slice();")
        wall = time.monotonic() - wall_start
        if not latencies:
            raise RuntimeError("the page recorded no latencies in {:.0f} s".format(wall))
        result = {"cpu": 100.0 * cpu_used / wall, "p50": float(numpy.percentile(latencies, 50)),
                  "p95": float(numpy.percentile(latencies, 95)), "fps": (frames_end - frames_start) / wall,
                  "samples": len(latencies), "rtf": (sim_end - sim_start) / wall,
                  "sim_cpu": 100.0 * (sim_cpu_end - sim_cpu_start) / wall}
        result.update(measure_map(probe, browser, pid))
        result.update(measure_camera(probe, browser, pid, simulator_pid))
        return result


def slam_like_map():
    """A 384 x 384 OccupancyGrid as a dict: unknown, a free 6 x 6 m room at the centre, 5 cm walls round it."""
    cells = numpy.full((MAP_CELLS, MAP_CELLS), -1, dtype=numpy.int8)
    low, high = MAP_CELLS // 2 - 60, MAP_CELLS // 2 + 60
    cells[low:high, low:high] = 0
    cells[low:high, [low, high - 1]] = 100
    cells[[low, high - 1], low:high] = 100
    return {"header": {"frame_id": "map"}, "info": {"resolution": 0.05, "width": MAP_CELLS, "height": MAP_CELLS,
                                                    "origin": {"position": {"x": -9.6, "y": -9.6},
                                                               "orientation": {"w": 1.0}}},
            "data": cells.ravel().tolist()}


def measure_map(probe, browser, pid):
    """{"map_bytes", "map_rate", "map_cpu"} while a 384 x 384 map comes every MAP_PERIOD_S."""
    grid = slam_like_map()
    maps_start = browser.script("return labView.maps || 0;")
    cpu_start, wall_start = cpu_seconds(pid), time.monotonic()
    while time.monotonic() - wall_start < MAP_MEASURE_S:
        sent = time.monotonic()
        probe.publish("/map", "nav_msgs/OccupancyGrid", grid)
        time.sleep(max(0.0, MAP_PERIOD_S - (time.monotonic() - sent)))
    wall = time.monotonic() - wall_start
    return {"map_bytes": browser.script("return labView.mapBytes || 0;"),
            "map_rate": (browser.script("return labView.maps;") - maps_start) / wall,
            "map_cpu": 100.0 * (cpu_seconds(pid) - cpu_start) / wall}


def measure_camera(probe, browser, pid, simulator_pid):
    """{"camera_rtf", "camera_sim_cpu", "camera_cpu", "camera_rate"} while the page shows the camera."""
    browser.script("""
        window.cameraShown = 0;
        new MutationObserver(() => { window.cameraShown += 1; })
          .observe(document.getElementById('camera-img'), {attributes: true, attributeFilter: ['src']});
        document.getElementById('camera-toggle').click();""")
    wait_until(lambda: browser.script("return window.cameraShown > 0;"), 30, "the first camera thumbnail")
    time.sleep(CAMERA_SETTLE_S)
    shown_start = browser.script("return window.cameraShown;")
    sim_start, cpu_start, sim_cpu_start = probe.now(), cpu_seconds(pid), cpu_seconds(simulator_pid)
    wall_start = time.monotonic()
    time.sleep(CAMERA_MEASURE_S)
    sim, cpu, sim_cpu = probe.now(), cpu_seconds(pid), cpu_seconds(simulator_pid)
    wall = time.monotonic() - wall_start
    shown = browser.script("return window.cameraShown;") - shown_start
    browser.script("document.getElementById('camera-toggle').click();")
    return {"camera_rtf": (sim - sim_start) / wall, "camera_sim_cpu": 100.0 * (sim_cpu - sim_cpu_start) / wall,
            "camera_cpu": 100.0 * (cpu - cpu_start) / wall, "camera_rate": shown / wall}


@contextlib.contextmanager
def navigation_page(factor=1.0):
    """Navigation in turtlebot3_world at `factor` with lab_web's page open and showing the map, the robot driving to
    NAV_GOAL: yields (browser, probe, lab_web's pid); everything is ended afterwards."""
    with master_and_browser("web_navigation_") as (master, browser):
        probe = start_navigation(master, master.workdir, turtlebot3_world_cells(), factor, ())
        open_page(browser, start_web_server(master), "labView.connected && labView.robot && labView.maps > 0")
        nav_goals.send_goal(probe, *NAV_GOAL)
        wait_until(lambda: browser.script("return !!(labView.nav && labView.nav.plans.global);"), 60,
                   "the page to draw move_base's plan")
        yield browser, probe, node_pid(master.uri, "/lab_web")


def measure_navigation():
    """{"nav_cpu": % of a core, "nav_p95": ms} with navigation at real time and the page showing it."""
    with navigation_page() as (browser, _probe, pid):
        browser.script("labView.latenciesMs.length = 0;")
        cpu_start, wall_start = cpu_seconds(pid), time.monotonic()
        time.sleep(NAV_MEASURE_S)
        cpu = cpu_seconds(pid) - cpu_start
        latencies = browser.script("return labView.latenciesMs.slice();")
        return {"nav_cpu": 100.0 * cpu / (time.monotonic() - wall_start),
                "nav_p95": float(numpy.percentile(latencies, 95))}


def run(duration_s=MEASURE_S):
    """scripts/bench rows: lab_web with tb3_sim (Week 4 demo) at real time and one connected headless page."""
    result = measure_with_page(duration_s)
    result.update(measure_navigation())
    return [
        ("lab_web server CPU, tb3_sim at 1x, one page", result["cpu"], "% of a core", CPU_TARGET_PERCENT, "<="),
        ("lab_web state-to-page latency p50", result["p50"], "ms", LATENCY_TARGET_MS, "<="),
        ("lab_web state-to-page latency p95", result["p95"], "ms", LATENCY_TARGET_MS, "<="),
        ("lab_web state frames delivered to the page", result["fps"], "frames/s", FPS_TARGET, ">="),
        ("lab_web map frame, 384x384 map", result["map_bytes"] / 1024.0, "kB", 64.0, "<="),
        ("lab_web map frames drawn, map every 2 s", result["map_rate"], "frames/s", 0.9 / MAP_PERIOD_S, ">="),
        ("lab_web server CPU with the map and /tf", result["map_cpu"], "% of a core", 10.0, "<="),
        ("tb3_sim real-time factor at 1x, camera not shown", result["rtf"], "x", RTF_TARGET, ">="),
        ("tb3_sim CPU, camera not shown", result["sim_cpu"], "% of a core", 100.0, "<="),
        ("tb3_sim real-time factor at 1x, camera shown", result["camera_rtf"], "x", RTF_TARGET, ">="),
        ("tb3_sim CPU, 1920x1080 camera shown", result["camera_sim_cpu"], "% of a core", 100.0, "<="),
        ("lab_web server CPU, camera shown", result["camera_cpu"], "% of a core", 10.0, "<="),
        ("lab_web camera thumbnails shown", result["camera_rate"], "frames/s", 1.5, ">="),
        ("lab_web server CPU, navigation displays at 1x", result["nav_cpu"], "% of a core", 10.0, "<="),
        ("lab_web state-to-page latency p95, navigation", result["nav_p95"], "ms", LATENCY_TARGET_MS, "<="),
    ]


if __name__ == "__main__":
    from report import print_table
    print_table(run(float(sys.argv[1]) if len(sys.argv) > 1 else MEASURE_S))
