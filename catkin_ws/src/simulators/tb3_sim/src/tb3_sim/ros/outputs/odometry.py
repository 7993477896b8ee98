"""/odom, /tf (odom -> base_footprint) and /joint_states at 30 Hz of sim time: the diff-drive plugin's
updateRate. Not lazy, as the plugin publishes whether or not anyone listens; a message is built only for a topic
with subscribers. Frames: `odom` -> `base_footprint` (see messages)."""

from typing import NamedTuple, Tuple

from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage

from tb3_sim.core.diff_drive import DRIVE_UPDATE_RATE_HZ
from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic


class DriveReading(NamedTuple):
    """Ground-truth pose of base_footprint (world = odom frame), its body-frame twist, the wheel angles (rad)."""

    time_s: float
    pose: Pose2D
    twist_body: Twist2D
    wheel_angles: Tuple[float, float]


class OdometryOutput(Output):
    rate_hz = DRIVE_UPDATE_RATE_HZ
    lazy = False
    frame_ids = (messages.ODOM_FRAME, messages.BASE_FRAME)

    def __init__(self):
        super().__init__()
        self.topics = (
            Topic("odom", Odometry, lambda r: messages.odometry_message(r.time_s, r.pose, r.twist_body)),
            Topic("/tf", TFMessage, lambda r: messages.odom_tf_message(r.time_s, r.pose)),
            Topic("joint_states", JointState, lambda r: messages.joint_state_message(r.time_s, r.wheel_angles)),
        )

    def read(self, world, now_s, wanted):
        robot = world.robot
        return DriveReading(now_s, robot.pose, robot.twist_body, robot.drive.wheel_angles)
