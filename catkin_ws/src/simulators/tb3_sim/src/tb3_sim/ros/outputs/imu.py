"""/imu at IMU_RATE_HZ = 100 Hz of sim time, in frame base_footprint (see messages).

Gazebo's IMU plugin publishes on every 1 ms world update while subscribed; 100 Hz keeps it smooth for course code
while leaving the Python message path cheap enough for faster-than-real-time runs. The reading runs at every
period even with no subscriber (not lazy), so its finite-difference acceleration never spans a gap; the message
is built only while someone subscribes.
"""

from sensor_msgs.msg import Imu as ImuMessage

from tb3_sim.core.imu import Imu
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

IMU_RATE_HZ = 100.0


class ImuOutput(Output):
    rate_hz = IMU_RATE_HZ
    lazy = False
    frame_ids = (messages.IMU_FRAME,)

    def __init__(self):
        super().__init__()
        self.imu = Imu()
        self.topics = (Topic("imu", ImuMessage, messages.imu_message),)

    def read(self, world, now_s, wanted):
        robot = world.robot
        return self.imu.read(now_s, robot.pose, robot.twist_world)

    def reset(self, now_s):
        super().reset(now_s)
        self.imu.reset()

    def forget_motion(self):
        """A jump must not show up as an acceleration spike."""
        self.imu.reset()
