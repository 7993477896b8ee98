"""What a test sees of a simulated TurtleBot3 through the probe: its /odom pose and its /scan, as plain data.

Messages come from the probe as dicts (see probe_node.py); these helpers turn them into the numbers tests
assert on: (x, y, yaw) from /odom, and the LiDAR distance straight ahead.
"""
import math
import statistics

FRONT_HALF_WIDTH_BEAMS = 3


def pose_of(odom):
    """(x, y, yaw) in metres and radians from an /odom message dict."""
    position, q = odom["pose"]["pose"]["position"], odom["pose"]["pose"]["orientation"]
    yaw = math.atan2(2.0 * (q["w"] * q["z"] + q["x"] * q["y"]), 1.0 - 2.0 * (q["y"] ** 2 + q["z"] ** 2))
    return position["x"], position["y"], yaw


def front_distance(scan):
    """Median LiDAR reading of the beams within +-3 indices of straight ahead (index 0), finite ones only."""
    ranges = [float(r) for r in scan["ranges"]]
    front = ranges[-FRONT_HALF_WIDTH_BEAMS:] + ranges[:FRONT_HALF_WIDTH_BEAMS + 1]
    finite = [r for r in front if math.isfinite(r)]
    return statistics.median(finite) if finite else math.inf


def angle_between(yaw_from, yaw_to):
    """Signed turn from one heading to another, wrapped into (-pi, pi]."""
    return math.atan2(math.sin(yaw_to - yaw_from), math.cos(yaw_to - yaw_from))


class RobotView:
    """The latest /odom and /scan of the simulated robot, read through a probe that subscribes to both."""

    def __init__(self, probe):
        self.probe = probe
        probe.subscribe("/odom", "nav_msgs/Odometry")
        probe.subscribe("/scan", "sensor_msgs/LaserScan")

    def pose(self, timeout_s=20.0):
        """The robot's (x, y, yaw) from the next /odom message."""
        self.probe.take("/odom")
        return pose_of(self.probe.wait_for_message("/odom", timeout_s))

    def settled_pose(self, timeout_s=20.0, still=1e-3):
        """(x, y, yaw) once /odom reports the robot has stopped (|v| and |w| below `still`)."""
        def stopped(odom):
            twist = odom["twist"]["twist"]
            return abs(twist["linear"]["x"]) < still and abs(twist["angular"]["z"]) < still
        self.probe.take("/odom")
        return pose_of(self.probe.wait_for_message("/odom", timeout_s, predicate=stopped))

    def front_distance(self, timeout_s=20.0, sweeps=1):
        """LiDAR distance straight ahead: the median over the next `sweeps` full sweeps. For a robot standing
        still, more sweeps average out the LiDAR's noise (sigma 0.01 m: one sweep's 7-beam median reads with
        a spread of about 4.5 mm, 5 sweeps' about 2 mm)."""
        self.probe.take("/scan")
        return statistics.median([front_distance(self.probe.wait_for_message("/scan", timeout_s))
                                  for _ in range(sweeps)])
