"""Ctrl-C in the action server's terminal during a sweep: the robot stops (tb3_sim would otherwise hold the
last turn command forever) and the server prints no traceback."""
import signal

from roslab import wait_until

STOP_WITHIN_SIM_S = 1.0


def test_ctrl_c_mid_sweep_stops_the_robot(sweeper):
    goal = sweeper.send(180.0, 10)
    sweeper.wait_for_feedback(goal, 1)
    stopped_at = sweeper.probe.now()
    sweeper.server.signal(signal.SIGINT)
    sweeper.server.popen.wait(timeout=30)
    odom = sweeper.odom_after(stopped_at + STOP_WITHIN_SIM_S + 0.5)
    assert sweeper.is_still(odom), odom["twist"]
    wait_until(lambda: "camera_sweep_action_server" in sweeper.server.output(), 5, "the server's output")
    output = sweeper.server.output()
    assert "Traceback" not in output, output[-4000:]   # whole, so that a rare thread traceback can be read
