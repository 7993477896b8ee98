"""Conversions between the core's plain values and ROS messages (message classes only; no rospy, no node).

Frames and conventions are Gazebo's for the TurtleBot3 (the frame names below, with a robot's tf_prefix if it has
one: see robot_naming):
- /odom: frame `odom`, child `base_footprint`, pose = true world pose, twist in the body frame, pose
  covariance diagonal [1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3], twist covariance all zero;
- /tf: odom -> base_footprint with the same stamp as /odom;
- /joint_states: the two wheel joints, positions only (velocity and effort empty);
- /scan: frame `base_scan`, Gazebo's angles, +inf for no return, 360 zero intensities;
- /imu: frame `base_footprint` (Gazebo's URDF->SDF conversion merges imu_link away), world yaw,
  yaw rate, acceleration without gravity, all covariances zero (the plugin's noise is 0).
Every stamp is simulated time in seconds, converted exactly at nanosecond resolution.
"""

import math

import genpy
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Pose, Quaternion, TransformStamped, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu, JointState, LaserScan
from tf2_msgs.msg import TFMessage

from tb3_sim.core.geometry import Pose2D, Twist2D, quaternion_to_yaw, yaw_to_quaternion
from tb3_sim.core.turtlebot3 import SCAN_FRAME, WHEEL_JOINT_NAMES

ODOM_FRAME = "odom"
BASE_FRAME = "base_footprint"
IMU_FRAME = BASE_FRAME
ODOM_POSE_COVARIANCE_DIAGONAL = (1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3)
NANOSECONDS_PER_SECOND = 1_000_000_000


def stamp(time_s):
    """`time_s` seconds as a ROS time, rounded to the nearest nanosecond (5 ms steps stay exact).

    Built without genpy.Time's constructor, whose type checks and normalisation cost more than the rest of a
    /clock message (sent after every physics step): the seconds and nanoseconds here are already canonical.
    """
    result = genpy.Time.__new__(genpy.Time)
    result.secs, result.nsecs = divmod(round(time_s * NANOSECONDS_PER_SECOND), NANOSECONDS_PER_SECOND)
    return result


def clock_message(time_s):
    return Clock(clock=stamp(time_s))


def quaternion_message(yaw):
    return Quaternion(*yaw_to_quaternion(yaw))


def pose_message(pose):
    """A geometry_msgs/Pose at z = 0 from a Pose2D."""
    message = Pose()
    message.position.x, message.position.y = pose.x, pose.y
    message.orientation = quaternion_message(pose.yaw)
    return message


def pose_from_message(message):
    """The Pose2D of a geometry_msgs/Pose (z, roll and pitch dropped). An all-zero quaternion means yaw 0,
    as Gazebo normalises (0, 0, 0, 0) to the identity."""
    q = message.orientation
    return Pose2D(message.position.x, message.position.y, quaternion_to_yaw(q.x, q.y, q.z, q.w))


def twist_message(twist):
    """A geometry_msgs/Twist from a Twist2D (same frame)."""
    message = Twist()
    message.linear.x, message.linear.y, message.angular.z = twist.vx, twist.vy, twist.wz
    return message


def twist_from_message(message):
    return Twist2D(message.linear.x, message.linear.y, message.angular.z)


def odometry_message(time_s, pose, twist_body, odom_frame=ODOM_FRAME, base_frame=BASE_FRAME):
    """/odom: world pose of base_footprint and its body-frame twist at `time_s`."""
    message = Odometry()
    message.header.stamp = stamp(time_s)
    message.header.frame_id = odom_frame
    message.child_frame_id = base_frame
    message.pose.pose = pose_message(pose)
    covariance = [0.0] * 36
    for i, value in enumerate(ODOM_POSE_COVARIANCE_DIAGONAL):
        covariance[7 * i] = value
    message.pose.covariance = covariance
    message.twist.twist = twist_message(twist_body)
    return message


def odom_tf_message(time_s, pose, odom_frame=ODOM_FRAME, base_frame=BASE_FRAME):
    """/tf: odom -> base_footprint at `time_s`."""
    transform = TransformStamped()
    transform.header.stamp = stamp(time_s)
    transform.header.frame_id = odom_frame
    transform.child_frame_id = base_frame
    transform.transform.translation.x, transform.transform.translation.y = pose.x, pose.y
    transform.transform.rotation = quaternion_message(pose.yaw)
    return TFMessage(transforms=[transform])


def static_tf_message(time_s, transforms):
    """/tf_static: fixed joints given as (parent, child, (x, y, z), (roll, pitch, yaw)) tuples."""
    stamped = []
    for parent, child, (x, y, z), (roll, pitch, yaw) in transforms:
        transform = TransformStamped()
        transform.header.stamp = stamp(time_s)
        transform.header.frame_id = parent
        transform.child_frame_id = child
        transform.transform.translation.x, transform.transform.translation.y = x, y
        transform.transform.translation.z = z
        transform.transform.rotation = Quaternion(*rpy_to_quaternion(roll, pitch, yaw))
        stamped.append(transform)
    return TFMessage(transforms=stamped)


def rpy_to_quaternion(roll, pitch, yaw):
    """Quaternion (x, y, z, w) of fixed-axis roll, pitch, yaw in rad (URDF's `rpy`)."""
    cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def joint_state_message(time_s, wheel_angles):
    """/joint_states: (left, right) wheel angles in rad; velocity and effort empty, as Gazebo publishes."""
    message = JointState()
    message.header.stamp = stamp(time_s)
    message.name = list(WHEEL_JOINT_NAMES)
    message.position = list(wheel_angles)
    return message


def scan_message(scan, frame_id=SCAN_FRAME):
    """/scan from a lidar.ScanResult, stamped at its measurement time."""
    message = LaserScan()
    message.header.stamp = stamp(scan.time_s)
    message.header.frame_id = frame_id
    message.angle_min, message.angle_max = scan.angle_min, scan.angle_max
    message.angle_increment = scan.angle_increment
    message.time_increment, message.scan_time = scan.time_increment, scan.scan_time
    message.range_min, message.range_max = scan.range_min, scan.range_max
    message.ranges = scan.ranges.tolist()
    message.intensities = [0.0] * len(message.ranges)
    return message


def imu_message(reading, frame_id=IMU_FRAME):
    """/imu from an imu.ImuReading."""
    message = Imu()
    message.header.stamp = stamp(reading.time_s)
    message.header.frame_id = frame_id
    message.orientation = quaternion_message(reading.yaw)
    message.angular_velocity.z = reading.yaw_rate
    message.linear_acceleration.x, message.linear_acceleration.y = reading.accel_x, reading.accel_y
    return message


def model_states_message(states):
    """/gazebo/model_states from [(name, world.ModelState)]: world poses and world-frame twists."""
    message = ModelStates()
    for name, state in states:
        message.name.append(name)
        message.pose.append(pose_message(state.pose))
        message.twist.append(twist_message(state.twist))
    return message
