"""/gazebo/model_states at MODEL_STATES_RATE_HZ = 100 Hz of sim time while subscribed: world poses and
world-frame twists of every model, in Gazebo's order (see core.world). Gazebo publishes on every 1 ms world
update; 100 Hz is plenty for course code and keeps the message path cheap."""

from gazebo_msgs.msg import ModelStates

from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

MODEL_STATES_RATE_HZ = 100.0


class ModelStatesOutput(Output):
    rate_hz = MODEL_STATES_RATE_HZ
    lazy = True

    def __init__(self):
        super().__init__()
        self.topics = (Topic("~model_states", ModelStates, messages.model_states_message),)

    def read(self, world, now_s, wanted):
        return world.model_states()
