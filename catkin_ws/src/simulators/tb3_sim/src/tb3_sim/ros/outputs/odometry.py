"""A robot's odom, /tf (odom -> base_footprint) and joint_states at 30 Hz of sim time: the diff-drive plugin's
updateRate. The pose is the true one (as Gazebo's, odometrySource world) or, with an odometry error configured
(core.odometry_error), a drifting one; the twist is always the true one. Not lazy, as the plugin publishes whether
or not anyone listens; a message is built only for a topic with subscribers. Frames: `odom` -> `base_footprint`
with the robot's tf_prefix (see messages, robot_naming)."""

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
    """`robot` (a core.robot.Robot) named by `naming` (a RobotNaming)."""

    rate_hz = DRIVE_UPDATE_RATE_HZ
    lazy = False

    def __init__(self, robot, naming, drift=None):
        """`drift`: a core.odometry_error.DriftingOdometry, or None for the true pose."""
        super().__init__()
        self.robot = robot
        self.drift = drift
        frames = (naming.frame(messages.ODOM_FRAME), naming.frame(messages.BASE_FRAME))
        self.frame_ids = frames
        self.topics = (
            Topic(naming.topic("odom"), Odometry,
                  lambda r: messages.odometry_message(r.time_s, r.pose, r.twist_body, *frames)),
            Topic("/tf", TFMessage, lambda r: messages.odom_tf_message(r.time_s, r.pose, *frames)),
            Topic(naming.topic("joint_states"), JointState,
                  lambda r: messages.joint_state_message(r.time_s, r.wheel_angles)),
        )

    def read(self, world, now_s, wanted):
        robot = self.robot
        pose = robot.pose if self.drift is None else self.drift.pose(robot.pose)
        return DriveReading(now_s, pose, robot.twist_body, robot.drive.wheel_angles)

    def reset(self, now_s):
        super().reset(now_s)
        if self.drift is not None:
            self.drift.restart()

    def forget_motion(self):
        if self.drift is not None:
            self.drift.jumped()
