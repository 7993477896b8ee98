"""Client nodes keep time on the simulator's /clock (100 Hz of sim time): a course-style `rospy.Rate` loop and a
`rospy.sleep` loop at 10 Hz and at 100 Hz, with the simulator at real time (wake-ups on their deadlines, a few at
most one clock tick late) and unpaced (wake-ups never early, on whole clock ticks, and the loop runs to its end)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from roslab import RosProcess, wait_for_topic

CLIENT = Path(__file__).resolve().parents[2] / "roslab" / "client_loop.py"
DURATION_S = 3.0
CLOCK_TICK_S = 0.01


@pytest.fixture(scope="module", params=[pytest.param(1, marks=[pytest.mark.realtime, pytest.mark.solo]), 0],
                ids=["real_time", "unpaced"])
def factor(request, ros_master, tmp_path_factory):
    sim = RosProcess(["roslaunch", "--wait", "tb3_sim", "tb3_sim.launch", "gui:=false",
                      f"real_time_factor:={request.param}"], ros_master.env,
                     tmp_path_factory.mktemp("sim") / "tb3_sim.log")
    wait_for_topic(ros_master.uri, "/clock")
    yield request.param
    sim.stop()


def client_wakes(ros_master, hz, mode):
    """(start, wake-up times) in sim seconds of a client loop run for DURATION_S."""
    args = [sys.executable, str(CLIENT), str(hz), str(DURATION_S)] + (["--sleep"] if mode == "sleep" else [])
    result = subprocess.run(args, env=ros_master.env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    report = json.loads(result.stdout.strip().splitlines()[-1])
    return report["start"], report["wakes"]


@pytest.mark.parametrize("mode", ["rate", "sleep"])
@pytest.mark.parametrize("hz", [10, 100])
def test_client_loops_wake_on_time(ros_master, factor, hz, mode):
    start, wakes = client_wakes(ros_master, hz, mode)
    period = 1.0 / hz
    intervals = [b - a for a, b in zip([start] + wakes[:-1], wakes)]
    assert wakes[-1] >= start + DURATION_S, "the loop ran to its end"
    assert all(round(t / CLOCK_TICK_S, 6).is_integer() for t in wakes), "wake-ups fall on /clock ticks"
    if factor == 1:
        # On time: never before its deadline, and at most one /clock tick after it (a client that gets the CPU
        # late on a loaded machine sees the next tick first). A Rate keeps its schedule, so it also makes every
        # one of its iterations; a sleep loop restarts its wait from each late wake-up.
        if mode == "rate":
            assert len(wakes) == round(DURATION_S * hz)
            lateness = [wake - (start + period * i) for i, wake in enumerate(wakes, start=1)]
        else:
            lateness = [interval - period for interval in intervals]
        assert all(-1e-6 <= late <= CLOCK_TICK_S + 1e-6 for late in lateness), lateness
        assert sum(late > 1e-6 for late in lateness) <= len(lateness) // 10, "late wake-ups are the exception"
    else:
        # Unpaced, sim time outruns the client: it wakes late and fewer times (a Rate catches up with shorter
        # waits, as rospy's does), but never more often than its rate allows and a sleep never ends early.
        assert len(wakes) <= round(DURATION_S * hz) + 1
        if mode == "sleep":
            assert min(intervals) >= period - 1e-6
