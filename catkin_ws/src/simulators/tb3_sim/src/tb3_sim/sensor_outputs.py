"""What the simulator publishes after each physics step, and when (simulated time), as Gazebo does.

- /clock: every physics step (200 Hz of sim time at 5 ms steps);
- /odom, /tf (odom -> base_footprint) and /joint_states: 30 Hz, the diff-drive plugin's updateRate;
- /scan: 5 Hz, the LDS-01 sensor's update_rate, only while subscribed (Gazebo's sensor is lazy too);
- /imu: IMU_RATE_HZ = 100 Hz, only while subscribed;
- /gazebo/model_states: MODEL_STATES_RATE_HZ = 100 Hz, only while subscribed.

Gazebo publishes /imu and /gazebo/model_states on every 1 ms world update (1 kHz); 100 Hz keeps them smooth
for course code while leaving the Python message path cheap enough for faster-than-real-time runs.
No rospy here: publishers are injected (anything with `publish(msg)` and `get_num_connections()`).
"""

from typing import Any, NamedTuple

from tb3_sim import ros_messages
from tb3_sim.diff_drive import DRIVE_UPDATE_RATE_HZ
from tb3_sim.imu import Imu
from tb3_sim.lidar import LIDAR_UPDATE_RATE_HZ
from tb3_sim.schedule import PeriodicSchedule

IMU_RATE_HZ = 100.0
MODEL_STATES_RATE_HZ = 100.0


class Publishers(NamedTuple):
    """One publisher per output topic."""

    clock: Any
    odom: Any
    tf: Any
    joint_states: Any
    scan: Any
    imu: Any
    model_states: Any


class SensorOutputs:
    """Turns world state into (publisher, message) pairs at each topic's rate; remembers the latest scan."""

    def __init__(self, publishers):
        self.publishers = publishers
        self._imu = Imu()
        self._odom_schedule = PeriodicSchedule(DRIVE_UPDATE_RATE_HZ)
        self._scan_schedule = PeriodicSchedule(LIDAR_UPDATE_RATE_HZ)
        self._imu_schedule = PeriodicSchedule(IMU_RATE_HZ)
        self._model_states_schedule = PeriodicSchedule(MODEL_STATES_RATE_HZ)
        self.latest_scan = None

    def restart(self, now_s):
        """Start every schedule afresh at `now_s` and forget sensor history (after a reset or a teleport)."""
        for schedule in (self._odom_schedule, self._scan_schedule, self._imu_schedule,
                         self._model_states_schedule):
            schedule.reset(now_s)
        self._imu.reset()
        self.latest_scan = None

    def forget_motion(self):
        """Forget the IMU's previous velocity, so a teleport does not show up as an acceleration spike."""
        self._imu.reset()

    def recent_scan(self, now_s):
        """The latest published scan if it is at most two scan periods old at `now_s`, else None."""
        latest = self.latest_scan
        if latest is not None and 0.0 <= now_s - latest.time_s <= 2.0 / LIDAR_UPDATE_RATE_HZ:
            return latest
        return None

    def scan_for_view(self, world):
        """The recent published scan, or a fresh one (which draws from the LiDAR's noise stream, as a published
        scan would) when nobody subscribes to /scan."""
        return self.recent_scan(world.time_s) or world.scan()

    def collect(self, world):
        """Messages due now that the world has stepped to `world.time_s`, as [(publisher, message)]."""
        now_s = world.time_s
        pubs = self.publishers
        due = [(pubs.clock, ros_messages.clock_message(now_s))]
        robot = world.robot
        if self._odom_schedule.due(now_s):
            pose = robot.pose
            due.append((pubs.odom, ros_messages.odometry_message(now_s, pose, robot.twist_body)))
            due.append((pubs.tf, ros_messages.odom_tf_message(now_s, pose)))
            due.append((pubs.joint_states, ros_messages.joint_state_message(now_s, robot.drive.wheel_angles)))
        if self._scan_schedule.due(now_s) and pubs.scan.get_num_connections():
            self.latest_scan = world.scan()
            due.append((pubs.scan, ros_messages.scan_message(self.latest_scan)))
        if self._imu_schedule.due(now_s):
            reading = self._imu.read(now_s, robot.pose, robot.twist_world)
            if pubs.imu.get_num_connections():
                due.append((pubs.imu, ros_messages.imu_message(reading)))
        if self._model_states_schedule.due(now_s) and pubs.model_states.get_num_connections():
            due.append((pubs.model_states, ros_messages.model_states_message(world.model_states())))
        return due
