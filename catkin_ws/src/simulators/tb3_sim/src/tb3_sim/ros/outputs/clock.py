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
    lazy = False

    def __init__(self, rate_hz):
        self.rate_hz = rate_hz
        super().__init__()
        self.topics = (Topic("/clock", Clock, messages.clock_message),)

    def read(self, world, now_s, wanted):
        return now_s
