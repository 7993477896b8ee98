"""The robot's heading from /odom and how far it has turned, unwrapped (plain Python, no rospy).

Yaw is about +z of the odom frame, anticlockwise positive, in radians. /odom's yaw jumps from +pi to -pi when
the robot turns through "backwards"; HeadingTracker adds up the wrapped differences instead, so a sweep through
that direction (or several turns) is measured correctly.
"""
import math


def yaw_from_quaternion(x, y, z, w):
    """The yaw (radians, in [-pi, pi]) of an orientation quaternion (x, y, z, w)."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def wrap_angle(radians):
    """`radians` wrapped into (-pi, pi]."""
    wrapped = math.atan2(math.sin(radians), math.cos(radians))
    return math.pi if wrapped == -math.pi else wrapped


class HeadingTracker:
    """The angle turned since a starting yaw: feed it every new yaw; consecutive yaws must differ by less than
    pi (half a turn), which /odom at 30 Hz guarantees for any speed a TurtleBot3 can reach."""

    def __init__(self, start_yaw):
        self._last_yaw = start_yaw
        self.turned_rad = 0.0

    def update(self, yaw):
        """Account for the new yaw (radians); returns the total turned so far in degrees, anticlockwise
        positive."""
        self.turned_rad += wrap_angle(yaw - self._last_yaw)
        self._last_yaw = yaw
        return self.turned_deg

    @property
    def turned_deg(self):
        return math.degrees(self.turned_rad)
