"""Service load benchmark for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/load_bench.py

On a private roscore, tb3_sim runs turtlebot3_world at real time next to the tutorial's add_two_int servers
(see roslab.load). For add_two_int (Python, then the C++ server for comparison) and /gazebo/get_model_state,
20 client threads with a persistent connection each make 100 calls, all at once. Reported per service: p50
and p99 call latency, failed calls, the /odom and /scan rates while the load ran (from their header stamps,
in sim time, as tests/integration/lab/test_load.py checks them), and the simulator's real-time factor meanwhile
(sim seconds of /odom stamps per wall second of their arrival: at 1.0 those rates held in wall time too).
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster  # noqa: E402  (needs the sys.path entry above)
from roslab.load import CALLS, CLIENTS, EXPECTED_RATES_HZ, LOADS, LoadGraph  # noqa: E402

LATENCY_TARGETS_MS = {"add_two_int": (100.0, 300.0), "add_two_int_cpp": (10.0, 100.0),
                      "get_model_state": (10.0, 100.0)}
"""(p50, p99) targets. The Python add_two_int server logs every call as the tutorial does, about 5 ms of
work per call even without load, so 20 clients queue behind each other; the C++ server and tb3_sim's
get_model_state take well under a millisecond."""

RATE_TARGET_SHARE = 0.9
"""A topic keeps its rate at >= 90 % of its nominal rate (30 Hz /odom, 5 Hz /scan); the simulator keeps real
time at a factor >= 0.9."""


def rows_for(name, run):
    """scripts/bench rows for one LoadRun of the load `name`."""
    p50_target, p99_target = LATENCY_TARGETS_MS[name]
    load = "{} under {} clients x {} calls".format(name, CLIENTS, CALLS)
    rows = [("{} p50 latency".format(load), run.percentile_ms(50), "ms", p50_target, "<="),
            ("{} p99 latency".format(load), run.percentile_ms(99), "ms", p99_target, "<="),
            ("{} failed calls".format(load), float(len(run.failures)), "calls", 0.0, "<=")]
    for topic, nominal_hz in EXPECTED_RATES_HZ.items():
        rows.append(("{} rate during the {} load (sim time)".format(topic, name), run.topics[topic]["stamps_hz"],
                     "Hz", RATE_TARGET_SHARE * nominal_hz, ">="))
    rows.append(("real-time factor during the {} load".format(name), run.topics["/odom"]["real_time_factor"],
                 "x", RATE_TARGET_SHARE, ">="))
    return rows


def run():
    """[(name, value, unit, target, comparison)] rows; comparison is ">=" or "<=" against target."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix="load_bench_")))
    os.environ["ROS_MASTER_URI"] = master.uri   # for the rospy.ServiceProxy clients of this process
    try:
        graph = LoadGraph(master)
        return [row for name in sorted(LOADS) for row in rows_for(name, graph.hammer(LOADS[name]))]
    finally:
        master.shutdown()


if __name__ == "__main__":
    from report import print_table
    print_table(run())
