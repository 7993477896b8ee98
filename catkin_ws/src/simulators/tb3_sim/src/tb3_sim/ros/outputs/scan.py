"""A robot's scan: the LDS-01 at 5 Hz of sim time (its update_rate), lazy like Gazebo's ray sensor, in frame
base_scan with the robot's tf_prefix (see core.lidar for Gazebo's conventions). Keeps the latest sweep for the
views, so a window or a snapshot shows what was published instead of casting extra sweeps."""

from sensor_msgs.msg import LaserScan

from tb3_sim.core.lidar import LIDAR_UPDATE_RATE_HZ
from tb3_sim.core.turtlebot3 import SCAN_FRAME
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

# A view shows the latest published sweep while it is at most this many scan periods old.
RECENT_SCAN_PERIODS = 2.0


class ScanOutput(Output):
    """`robot`'s LiDAR, named by `naming` (a RobotNaming); `lidar` is a core.lidar.Lidar (seeded noise, optionally
    seeing low objects)."""

    rate_hz = LIDAR_UPDATE_RATE_HZ
    lazy = True

    def __init__(self, robot, naming, lidar):
        super().__init__()
        self.robot = robot
        self.lidar = lidar
        self.latest = None
        frame_id = naming.frame(SCAN_FRAME)
        self.frame_ids = (frame_id,)
        self.topics = (Topic(naming.topic("scan"), LaserScan, lambda scan: messages.scan_message(scan, frame_id)),)

    def read(self, world, now_s, wanted):
        self.latest = self.lidar.read(world, self.robot, now_s)
        return self.latest

    def reset(self, now_s):
        super().reset(now_s)
        self.lidar.reset()
        self.latest = None

    def recent(self, now_s):
        """The latest published sweep if it is at most RECENT_SCAN_PERIODS periods old at `now_s`, else None."""
        latest = self.latest
        if latest is not None and 0.0 <= now_s - latest.time_s <= RECENT_SCAN_PERIODS / self.rate_hz:
            return latest
        return None

    def for_view(self, world):
        """The recent published sweep, or a fresh one when nobody subscribes to /scan (it draws from the noise
        stream as a published sweep would)."""
        return self.recent(world.time_s) or self.lidar.read(world, self.robot, world.time_s)
