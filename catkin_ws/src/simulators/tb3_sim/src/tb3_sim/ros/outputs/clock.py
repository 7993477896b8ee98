"""/clock: the simulated time at `rate_hz` of sim time (the node's ~clock_rate, 100 Hz by default: every other
5 ms physics step), as gazebo_ros publishes it with `pub_clock_frequency` set; 0 means after every physics step,
as Gazebo publishes it without. Not lazy: every node on /use_sim_time needs it.

Why not every step by default: every node on /use_sim_time (robot_state_publisher, rviz, each rostopic, every
student node) subscribes to /clock, and a message per step to each of them was half of the simulator's time when
running faster than real time. At 100 Hz, rospy.Rate and rospy.sleep in client nodes still wake on time for loops
up to 100 Hz (the ticks fall on whole 10 ms of sim time, where such loops' deadlines fall), and finer sleeps end
on the next tick.
"""

from rosgraph_msgs.msg import Clock

from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic


class ClockOutput(Output):
    """Remembers its last tick, for the loop's pacing: it waits for wall time only after a tick (see ticked)."""

    lazy = False

    def __init__(self, rate_hz):
        self.rate_hz = rate_hz
        super().__init__()
        self.topics = (Topic("/clock", Clock, messages.clock_message),)
        self._last_tick_s = None

    def read(self, world, now_s, wanted):
        self._last_tick_s = now_s
        return now_s

    def reset(self, now_s):
        super().reset(now_s)
        self._last_tick_s = None

    def ticked(self, now_s):
        """True if /clock went out for the step that reached `now_s`.

        The loop holds the real-time factor only at these steps: a node on /use_sim_time sees time only through
        /clock, so it cannot tell when, between two ticks, a message went out. One wake-up per tick instead of
        one per physics step (a wake-up costs about 80 us of CPU on a shared 2-core machine) took the
        simulator's CPU at real time from about 8.2 to 6.8 % of a core.
        """
        return self._last_tick_s == now_s
