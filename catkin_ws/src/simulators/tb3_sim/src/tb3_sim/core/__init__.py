"""The simulation core: world, bodies, robot and drive, sensors, world files and model XML. No rospy here:
unit-tested without a master, and usable from tools and views."""

from tb3_sim.core.diff_drive import DiffDrive, validate_command
from tb3_sim.core.errors import (
                                 DuplicateModelError,
                                 InvalidCommandError,
                                 OverlapError,
                                 ProtectedModelError,
                                 SimError,
                                 UnknownModelError,
                                 WorldFileError,
)
from tb3_sim.core.geometry import Pose2D, Twist2D, quaternion_to_yaw, wrap_angle, yaw_to_quaternion
from tb3_sim.core.imu import Imu, ImuReading
from tb3_sim.core.lidar import Lidar, ScanResult
from tb3_sim.core.schedule import PeriodicSchedule
from tb3_sim.core.shapes import Box, Circle, Cylinder, Polygon, Segment
from tb3_sim.core.world import ModelState, World
from tb3_sim.core.world_file import ModelSpec, WorldDescription, load_world, parse_world, shipped_world_path

__all__ = [
    "Box", "Circle", "Cylinder", "DiffDrive", "DuplicateModelError", "Imu", "ImuReading", "InvalidCommandError",
    "Lidar", "ModelSpec", "ModelState", "OverlapError", "PeriodicSchedule", "Polygon", "Pose2D",
    "ProtectedModelError", "ScanResult", "Segment", "SimError", "Twist2D", "UnknownModelError", "World",
    "WorldDescription", "WorldFileError", "load_world", "parse_world", "quaternion_to_yaw", "shipped_world_path",
    "validate_command", "wrap_angle", "yaw_to_quaternion",
]
