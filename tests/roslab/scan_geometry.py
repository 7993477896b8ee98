"""Where a noise-free LiDAR beam meets walls and pillars given by their numbers: the expected /scan reading of a
world written independently of the simulator's world file.

Shapes are the Gazebo primitives as a world's SDF gives them, seen from above: `Rect(center, size, yaw)` (a box:
centre (x, y), x/y size in m, yaw in rad) and `Disc(center, radius)` (a cylinder). Angles in rad in the world
frame."""
import math
from typing import NamedTuple, Tuple

TURTLEBOT3_SCAN_X_M = -0.064        # base_scan sits 6.4 cm behind base_footprint
ANGLE_INCREMENT_RAD = 6.28319 / 359  # 360 beams over Gazebo's [0, 6.28319] rad
RANGE_MAX_M = 3.5                    # a hit at 3.5 m or more reads inf


class Rect(NamedTuple):
    center: Tuple[float, float]
    size: Tuple[float, float]
    yaw: float = 0.0


class Disc(NamedTuple):
    center: Tuple[float, float]
    radius: float


def scan_origin(x, y, yaw):
    """base_scan's (x, y) for a TurtleBot3 standing at (x, y) facing `yaw`."""
    return x + TURTLEBOT3_SCAN_X_M * math.cos(yaw), y + TURTLEBOT3_SCAN_X_M * math.sin(yaw)


def beam_index(robot_yaw, world_angle):
    """The beam that points nearest to `world_angle` for a robot facing `robot_yaw`."""
    return round(((world_angle - robot_yaw) % (2 * math.pi)) / ANGLE_INCREMENT_RAD) % 360


def beam_angle(robot_yaw, beam):
    """The world-frame direction of `beam`."""
    return robot_yaw + beam * ANGLE_INCREMENT_RAD


def ray_distance(origin, angle, shape):
    """Distance from `origin` along `angle` to the first point of `shape`, or inf if the ray misses it."""
    dx, dy = math.cos(angle), math.sin(angle)
    if isinstance(shape, Disc):
        vx, vy = shape.center[0] - origin[0], shape.center[1] - origin[1]
        along, miss = vx * dx + vy * dy, vx * dy - vy * dx
        if abs(miss) > shape.radius or along <= 0:
            return math.inf
        return along - math.sqrt(shape.radius ** 2 - miss ** 2)
    # The ray in the box's frame, then the slab method.
    cos_yaw, sin_yaw = math.cos(shape.yaw), math.sin(shape.yaw)
    px, py = origin[0] - shape.center[0], origin[1] - shape.center[1]
    local_origin = (px * cos_yaw + py * sin_yaw, -px * sin_yaw + py * cos_yaw)
    local_direction = (dx * cos_yaw + dy * sin_yaw, -dx * sin_yaw + dy * cos_yaw)
    near, far = 0.0, math.inf
    for start, step, half in zip(local_origin, local_direction, (shape.size[0] / 2, shape.size[1] / 2)):
        if abs(step) < 1e-12:
            if abs(start) > half:
                return math.inf
            continue
        t0, t1 = sorted(((-half - start) / step, (half - start) / step))
        near, far = max(near, t0), min(far, t1)
    return near if near <= far else math.inf


def expected_range(origin, angle, shapes):
    """The noise-free reading of a beam from `origin` along `angle` among `shapes`: the nearest hit, inf beyond
    the LiDAR's range."""
    distance = min((ray_distance(origin, angle, shape) for shape in shapes), default=math.inf)
    return distance if distance < RANGE_MAX_M else math.inf
