"""A robot's imu at IMU_RATE_HZ = 100 Hz of sim time, in frame base_footprint with the robot's tf_prefix (see
messages).

Gazebo's IMU plugin publishes on every 1 ms world update while subscribed; 100 Hz keeps it smooth for course code
while leaving the Python message path cheap enough for faster-than-real-time runs. Lazy, as Gazebo's plugin: no
reading while nobody subscribes; the first reading after such a gap reports zero acceleration (core.imu), since
the finite difference needs the velocity one period before.
"""

from sensor_msgs.msg import Imu as ImuMessage

from tb3_sim.core.imu import Imu
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

IMU_RATE_HZ = 100.0
# Readings further apart than this (a gap without subscribers) do not difference their velocities.
MAX_READING_GAP_S = 1.5 / IMU_RATE_HZ


class ImuOutput(Output):
    """`robot`'s IMU, named by `naming` (a RobotNaming)."""

    rate_hz = IMU_RATE_HZ
    lazy = True

    def __init__(self, robot, naming):
        super().__init__()
        self.robot = robot
        self.imu = Imu(MAX_READING_GAP_S)
        frame_id = naming.frame(messages.IMU_FRAME)
        self.frame_ids = (frame_id,)
        self.topics = (Topic(naming.topic("imu"), ImuMessage, lambda r: messages.imu_message(r, frame_id)),)

    def read(self, world, now_s, wanted):
        robot = self.robot
        return self.imu.read(now_s, robot.pose, robot.twist_world)

    def reset(self, now_s):
        super().reset(now_s)
        self.imu.reset()

    def forget_motion(self):
        """A jump must not show up as an acceleration spike."""
        self.imu.reset()
