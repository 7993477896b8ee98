"""CPU use of an idle turtlesim_node (one turtle, nothing moving), for scripts/bench; never a test.

Each measurement starts a private roscore on a free port and one turtlesim_node, headless or with its
window under Debian's xvfb-run, waits for it to settle, then reads the node process's user + system
CPU time from /proc over the measuring window. The target is at most 3% of one core (the original C++
node measured 0.8%). Run from a ROS terminal (source scripts/env.sh):

    python3 tests/bench/turtlesim_cpu.py [seconds]
"""
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster, wait_for_topic  # noqa: E402  (needs the sys.path entry above)
from roslab.graph import node_pid  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402

TARGET_PERCENT = 3.0
"""Target: idle CPU at most this share of one core."""

SETTLE_S = 3.0
"""Wall seconds after the first pose before measuring (start-up work excluded)."""

COMMANDS = {
    "headless": ["rosrun", "turtlesim", "turtlesim_node", "_headless:=true"],
    "window (xvfb-run)": ["env", "-u", "QT_QPA_PLATFORM", "xvfb-run", "-a", "-s", "-screen 0 640x480x24",
                          "rosrun", "turtlesim", "turtlesim_node"],
}
"""Mode name -> command line of the node (the window's without QT_QPA_PLATFORM, so Qt uses the X display)."""


def idle_cpu_percent(mode, duration_s=20.0):
    """Percent of one core an idle turtlesim_node uses over `duration_s` wall seconds in `mode`
    (a key of COMMANDS)."""
    with tempfile.TemporaryDirectory(prefix="turtlesim-bench-") as workdir:
        master = RosMaster(Path(workdir))
        try:
            master.start(COMMANDS[mode], "turtlesim_node")
            wait_for_topic(master.uri, "/turtle1/pose", timeout_s=30)
            time.sleep(SETTLE_S)
            pid = node_pid(master.uri, "/turtlesim")
            start_cpu, start_wall = cpu_seconds(pid), time.monotonic()
            time.sleep(duration_s)
            used = cpu_seconds(pid) - start_cpu
            return 100.0 * used / (time.monotonic() - start_wall)
        finally:
            master.shutdown()


def run(duration_s=20.0):
    """scripts/bench rows: idle CPU of turtlesim_node in every mode of COMMANDS."""
    return [("turtlesim_node idle CPU, {}, one turtle".format(mode), idle_cpu_percent(mode, duration_s),
             "% of a core", TARGET_PERCENT, "<=") for mode in COMMANDS]


if __name__ == "__main__":
    from report import print_table
    print_table(run(float(sys.argv[1]) if len(sys.argv) > 1 else 20.0))
