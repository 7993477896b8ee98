"""Where tb3_sim's time goes, for scripts/bench: a cProfile of the simulator's loop (its main thread) at
real_time_factor 0 in turtlebot3_world with /scan and /odom subscribed, summed into a few shares.

    source scripts/env.sh && python3 tests/bench/tb3_sim_profile.py

Each function's own time (cProfile's tottime) counts towards one share, by where the function lives (SHARES):
physics (Box2D and the world, robot and drive), LiDAR ray casting, message building (our conversions and genpy's
constructors), serialization, publishing (rospy's publish path and the socket writes), pacing and waiting, the
output loop (stepping, deciding what is due and who subscribes), and the rest; start-up imports are left out. The
profiler slows Python down, so the shares matter, not the absolute times. Printed as a table and written to
bench-output/tb3_sim_profile.md; `run()` returns no target rows.
"""
import pstats
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster, wait_for_service  # noqa: E402  (needs the sys.path entry above)

PROFILE_S = 10.0
OUTPUT = Path(__file__).resolve().parents[2] / "bench-output" / "tb3_sim_profile.md"
NODE_ARGS = ("__name:=gazebo", "_real_time_factor:=0", "_world:=turtlebot3_world", "_x_pos:=-2.0", "_y_pos:=-0.5",
             "_headless:=true")
STARTUP = "start-up (imports), left out"
# (share, predicate on (file name, function name)), first match wins; builtins have the file name "~".
SHARES = [
    (STARTUP, lambda path, name: path.startswith("<frozen") or any(
        word in name for word in ("create_dynamic", "builtins.compile", "marshal.loads", "builtins.exec"))),
    ("physics (Box2D, world, robot, drive)",
     lambda path, name: "Box2D" in path or "_Box2D" in name
     or any(part in path for part in ("core/world.py", "core/robot.py", "core/diff_drive.py", "core/bodies.py",
                                      "core/model_body.py"))),
    ("LiDAR ray casting (numpy)", lambda path, name: "core/lidar.py" in path or "core/obstacles.py" in path
     or "numpy" in path or "numpy" in name),
    ("serialization", lambda path, name: name in ("serialize", "serialize_message") or "_struct" in name
     or "BytesIO" in name or name.startswith("pack")),
    ("message building", lambda path, name: "ros/messages.py" in path or ("ros/outputs/" in path and
     "publisher.py" not in path) or "genpy" in path or "_msgs/msg" in path or "__new__" in name),
    ("publishing (rospy, sockets)", lambda path, name: "rospy" in path or "sendall" in name or "socket" in name),
    ("pacing and waiting", lambda path, name: "sleep" in name or "threading.py" in path or "acquire" in name
     or "core/pacing.py" in path),
    ("output loop (steps, what is due, who subscribes)",
     lambda path, name: any(part in path for part in ("ros/outputs/publisher.py", "ros/publishers.py",
                                                      "core/schedule.py", "ros/node.py"))
     or any(word in name for word in ("builtins.min", "'extend'", "'append'", "builtins.len"))),
]


def profile_simulator(profile_path):
    """Run the simulator under cProfile for PROFILE_S wall seconds with /scan and /odom subscribed."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix="tb3_profile_")))
    try:
        subprocess.run(["rosparam", "set", "/use_sim_time", "true"], env=master.env, check=True)
        node = subprocess.check_output(["catkin_find", "tb3_sim", "tb3_sim_node"], env=master.env,
                                       text=True).split()[0]
        sim = master.start([sys.executable, "-m", "cProfile", "-o", str(profile_path), node, *NODE_ARGS],
                           "tb3_sim_profiled")
        wait_for_service(master.uri, "/gazebo/get_world_properties", 30)
        probe = master.probe()
        probe.subscribe("/scan", "sensor_msgs/LaserScan")
        probe.subscribe("/odom", "nav_msgs/Odometry")
        time.sleep(PROFILE_S)
        sim.popen.send_signal(signal.SIGINT)
        sim.popen.wait(30)
    finally:
        master.shutdown()


def shares(profile_path):
    """[(share name, seconds)] of the loop's own time, largest first, from a cProfile file."""
    totals = {name: 0.0 for name, _ in SHARES}
    totals["other"] = 0.0
    for (path, _line, name), (_calls, _primitive, own_s, _cumulative, _callers) in \
            pstats.Stats(str(profile_path)).stats.items():
        share = next((label for label, matches in SHARES if matches(path, name)), "other")
        totals[share] += own_s
    return sorted(totals.items(), key=lambda item: -item[1])


def table(rows):
    rows = [(name, seconds) for name, seconds in rows if name != STARTUP]
    total = sum(seconds for _, seconds in rows)
    lines = ["| share of the loop's time | % |", "|---|---|"]
    lines += ["| {} | {:.0f} |".format(name, 100.0 * seconds / total) for name, seconds in rows]
    return "\n".join(lines)


def run():
    with tempfile.TemporaryDirectory() as folder:
        profile_path = Path(folder) / "tb3_sim.prof"
        profile_simulator(profile_path)
        text = table(shares(profile_path))
    print("tb3_sim at real_time_factor 0, /scan and /odom subscribed, under cProfile:\n" + text)
    OUTPUT.parent.mkdir(exist_ok=True)
    OUTPUT.write_text(text + "\n")
    return []


if __name__ == "__main__":
    run()
