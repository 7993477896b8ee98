"""Line-follower benchmark for scripts/bench (figures, never asserted): week6_vision's line_follower.py on
tuos_simulations' line_following track, as tests/integration/week6_vision/test_line_follower.py runs it (10x real
time, a 160x120 camera at 10 frames per sim second). Reports the lap time in sim seconds (the 19.59 m line at the
follower's 0.1 m/s takes 196 s, plus the coast over its end) and the robot's mean and largest distance to the
line's centre.

    source scripts/env.sh && python3 tests/bench/line_follower_bench.py
"""
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster, wait_for_topic  # noqa: E402  (needs the sys.path entry above)
from roslab.line_track import follow_the_line  # noqa: E402

LAUNCH_ARGS = ("gui:=false", "real_time_factor:=10", "camera_width:=160", "camera_height:=120", "camera_rate:=10")


def run():
    """[(name, value, unit, target, comparison)] rows; comparison is ">=" or "<=" against target."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix="line_follower_bench_")))
    master.env["TURTLEBOT3_MODEL"] = "waffle"
    try:
        master.roslaunch("tuos_simulations", "line_following.launch", *LAUNCH_ARGS)
        wait_for_topic(master.uri, "/odom", timeout_s=60)
        probe = master.probe()
        probe.subscribe("/odom", "nav_msgs/Odometry")
        probe.subscribe("/rosout_agg", "rosgraph_msgs/Log")
        lap = follow_the_line(master, probe)
    finally:
        master.shutdown()
    return [("line follower lap of line_following (sim time)", lap.lap_s, "s", 210.0, "<="),
            ("line follower mean distance to the line", lap.mean_distance_m * 100, "cm", 5.0, "<="),
            ("line follower largest distance to the line", lap.max_distance_m * 100, "cm", 10.0, "<=")]


if __name__ == "__main__":
    from report import print_table
    print_table(run())
