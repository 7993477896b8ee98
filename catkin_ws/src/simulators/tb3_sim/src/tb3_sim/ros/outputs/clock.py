"""/clock: the simulated time after every physics step (5 ms of sim time), as Gazebo publishes it without
`pub_clock_frequency`. Not lazy: every node on /use_sim_time needs it."""

from rosgraph_msgs.msg import Clock

from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic


class ClockOutput(Output):
    rate_hz = 0.0
    lazy = False

    def __init__(self):
        super().__init__()
        self.topics = (Topic("/clock", Clock, messages.clock_message),)

    def read(self, world, now_s, wanted):
        return now_s
