"""CPU use of an idle turtlesim_node (one turtle, nothing moving), for scripts/bench; never a test.

Each measurement starts a private roscore on a free port and one turtlesim_node, headless or with its
window under Debian's xvfb-run, waits for it to settle, then reads the node process's user + system
CPU time from /proc over the measuring window. The target is at most 3% of one core (the original C++
node measured 0.8%). Run from a ROS terminal (source scripts/env.sh):

    python3 tests/bench/turtlesim_cpu.py [seconds]
"""
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster, wait_for_topic  # noqa: E402  (needs the sys.path entry above)

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


def _cpu_seconds(pid):
    """User + system CPU seconds used so far by process `pid` (all its threads)."""
    fields = Path("/proc/{}/stat".format(pid)).read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _node_pid(session_id):
    """PID of the turtlesim_node process in session `session_id` (rosrun may sit under xvfb-run)."""
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            command = (entry / "cmdline").read_bytes()
        except OSError:
            continue
        if int(stat[3]) == session_id and b"turtlesim_node" in command and b"python" in command:
            return int(entry.name)
    raise RuntimeError("no turtlesim_node process in session {}".format(session_id))


def idle_cpu_percent(mode, duration_s=20.0):
    """Percent of one core an idle turtlesim_node uses over `duration_s` wall seconds in `mode`
    (a key of COMMANDS)."""
    with tempfile.TemporaryDirectory(prefix="turtlesim-bench-") as workdir:
        master = RosMaster(Path(workdir))
        try:
            process = master.start(COMMANDS[mode], "turtlesim_node")
            wait_for_topic(master.uri, "/turtle1/pose", timeout_s=30)
            time.sleep(SETTLE_S)
            pid = _node_pid(process.pid)
            start_cpu, start_wall = _cpu_seconds(pid), time.monotonic()
            time.sleep(duration_s)
            used = _cpu_seconds(pid) - start_cpu
            return 100.0 * used / (time.monotonic() - start_wall)
        finally:
            master.shutdown()


def bench_idle_cpu(duration_s=20.0):
    """[(mode, percent of one core)] for every mode of COMMANDS."""
    return [(mode, idle_cpu_percent(mode, duration_s)) for mode in COMMANDS]


def main(argv):
    duration_s = float(argv[1]) if len(argv) > 1 else 20.0
    print("turtlesim_node idle CPU over {:.0f} s (target <= {:.1f}% of one core)".format(
        duration_s, TARGET_PERCENT))
    for mode, percent in bench_idle_cpu(duration_s):
        verdict = "ok" if percent <= TARGET_PERCENT else "OVER TARGET"
        print("  {:<20} {:5.2f}%  {}".format(mode, percent, verdict))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
