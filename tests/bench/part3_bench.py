"""COM2009 Part 3 end to end for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/part3_bench.py [navigation_factor [mapping_factor]]

tests/integration/navigation/part3.py's sequence in nav_world: SLAM with a scripted drive at MAPPING_FACTOR,
`rosrun map_server map_saver -f`, the course's navigation.launch at NAVIGATION_FACTOR, and `rostopic pub
/move_base_simple/goal` to zones A-D. Measures the zones reached (move_base's "Goal reached." with the robot inside
the zone's circle; target all four) and the whole sequence's wall time (target 90 s), with its mapping and
navigation parts.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import part3  # noqa: E402

from roslab import RosMaster  # noqa: E402

NAVIGATION_FACTOR = 1
MAPPING_FACTOR = 8
WALL_TARGET_S = 90.0


def run(navigation_factor=NAVIGATION_FACTOR, mapping_factor=MAPPING_FACTOR):
    master = RosMaster(Path(tempfile.mkdtemp(prefix="part3_bench_")))
    os.environ["ROS_MASTER_URI"] = master.uri   # this process asks the simulator for the robot's true pose
    try:
        zones, wall = part3.run_sequence(master, master.workdir, mapping_factor, navigation_factor)
    finally:
        master.shutdown()
    print(f"    logs: {master.workdir}", flush=True)
    factors = f"mapping at factor {mapping_factor}, navigation at {navigation_factor}"
    return [
        ("Part 3 sequence: zones A-D reached", sum(map(part3.reached, zones.values())), "", len(part3.ZONES), ">="),
        (f"Part 3 sequence wall time ({factors})", wall["total"], "s", WALL_TARGET_S, "<="),
        (f"Part 3 sequence: SLAM, drive and map_saver (factor {mapping_factor})", wall["mapping"], "s",
         WALL_TARGET_S, "<="),
        (f"Part 3 sequence: navigation.launch and the four goals (factor {navigation_factor})", wall["navigation"],
         "s", WALL_TARGET_S, "<="),
    ]


if __name__ == "__main__":
    for row in run(*(int(arg) for arg in sys.argv[1:3])):
        print(row)
