"""The three TurtleBot3 models (Burger, Waffle, Waffle Pi) as data: one table, `TURTLEBOT3_MODELS`.

Frames: every planar coordinate here is in `base_footprint` (x ahead, y left, z up, origin on the floor under
the wheel axle centre) unless the name says otherwise. Values come from ROBOTIS's noetic
`turtlebot3_<model>.urdf.xacro` (links, joints, collision boxes, inertials) and `turtlebot3_<model>.gazebo.xacro`
(the drive plugin's wheel separation and diameter, the sensors), not from the legacy `model.sdf` files.
The velocity limits are the vendor's (turtlebot3_teleop's); Gazebo's drive plugin does not clamp to them.
"""

from dataclasses import dataclass
from typing import Optional, Tuple

# The drive plugin's joints, the same in every model.
WHEEL_JOINT_NAMES = ("wheel_left_joint", "wheel_right_joint")
# Gazebo's wheel diameter of every model is 0.066 m.
WHEEL_RADIUS_M = 0.033
WHEEL_WIDTH_M = 0.018
# The LDS-01 sits on base_scan in every model; only its mount differs.
SCAN_FRAME = "base_scan"
# The LDS-01's collision cylinder (r 0.055 m, 0.0315 m tall, 1.5 cm ahead of base_scan and 6.5 mm below it): what
# another robot's LiDAR sees of it, since it is the highest part of every model.
LDS_RADIUS_M = 0.055
LDS_X_OFFSET_M = 0.015
LDS_TOP_ABOVE_SCAN_M = 0.0093
CAMERA_OPTICAL_FRAME = "camera_rgb_optical_frame"
# An optical frame turns its parent to z ahead, x right, y down (REP 103), as the URDFs write it.
OPTICAL_RPY = (-1.57, 0.0, -1.57)
BASE_JOINT_Z_M = 0.010


@dataclass(frozen=True)
class CameraSpec:
    """A camera as its Gazebo sensor declares it: the viewpoint (camera_rgb_frame in base_footprint), the image
    size, horizontal field of view, rate, clip planes and the plugin's hackBaseline; `depth_range_m` is the
    (min, max) band a depth camera publishes (None: an RGB-only camera, no depth topics)."""

    x_m: float
    y_m: float
    height_m: float
    width_px: int
    height_px: int
    hfov_rad: float
    rate_hz: float
    hack_baseline_m: float
    depth_range_m: Optional[Tuple[float, float]]
    clip_near_m: float = 0.03
    clip_far_m: float = 100.0


@dataclass(frozen=True)
class TurtleBot3Model:
    """One TurtleBot3 model: its name (`TURTLEBOT3_MODEL`: burger, waffle, waffle_pi), the base collision box in
    base_footprint (x from body_x_min_m to body_x_max_m, y within ±body_half_width_m, top at body_top_m), the
    wheels' y (centre), the drive plugin's wheel separation, the summed URDF inertials, the LiDAR mount
    (base_scan's x and height above the floor), the camera (None for the Burger), the vendor velocity limits and
    the URDF's fixed joints (parent, child, (x, y, z) m, (roll, pitch, yaw) rad) for /tf_static."""

    name: str
    body_x_min_m: float
    body_x_max_m: float
    body_half_width_m: float
    body_top_m: float
    wheel_centre_y_m: float
    wheel_separation_m: float
    mass_kg: float
    scan_x_m: float
    scan_height_m: float
    max_linear_mps: float
    max_angular_radps: float
    static_transforms: Tuple
    camera: Optional[CameraSpec] = None

    @property
    def robot_name(self):
        """The URDF's robot name and Gazebo's model name in the original launch files: turtlebot3_<model>."""
        return f"turtlebot3_{self.name}"

    @property
    def wheel_radius_m(self):
        return WHEEL_RADIUS_M

    def footprint(self):
        """Convex outlines of the collision shapes in base_footprint: the base box and the two wheels (which
        stick out beside it), each a tuple of CCW (x, y) vertices. Casters lie inside the base box."""
        x0, x1, h = self.body_x_min_m, self.body_x_max_m, self.body_half_width_m
        base = ((x0, -h), (x1, -h), (x1, h), (x0, h))
        r = WHEEL_RADIUS_M
        y_in = self.wheel_centre_y_m - WHEEL_WIDTH_M / 2
        y_out = self.wheel_centre_y_m + WHEEL_WIDTH_M / 2
        left = ((-r, y_in), (r, y_in), (r, y_out), (-r, y_out))
        right = ((-r, -y_out), (r, -y_out), (r, -y_in), (-r, -y_in))
        return base, left, right


def _transforms(scan_xyz, imu_xyz, casters, camera=()):
    """The fixed joints below base_link: LiDAR, IMU, casters and camera frames (base_link is 1 cm up)."""
    return ((("base_footprint", "base_link", (0.0, 0.0, BASE_JOINT_Z_M), (0.0, 0.0, 0.0)),
             ("base_link", SCAN_FRAME, scan_xyz, (0.0, 0.0, 0.0)),
             ("base_link", "imu_link", imu_xyz, (0.0, 0.0, 0.0)))
            + tuple(camera)
            + tuple(("base_link", name, xyz, (-1.57, 0.0, 0.0)) for name, xyz in casters))


# Burger: base box 0.140 x 0.140 x 0.143 m at (-0.032, 0, 0.070) in base_link; wheels at y ±0.080; LiDAR on top
# at (-0.032, 0, 0.172) in base_link; one caster. Mass: base 0.8257 + wheels 2 x 0.0285 + caster 0.005 + LDS
# 0.114 kg.
BURGER = TurtleBot3Model(
    name="burger", body_x_min_m=-0.102, body_x_max_m=0.038, body_half_width_m=0.070, body_top_m=0.1515,
    wheel_centre_y_m=0.080, wheel_separation_m=0.160, mass_kg=1.00, scan_x_m=-0.032, scan_height_m=0.182,
    max_linear_mps=0.22, max_angular_radps=2.84,
    static_transforms=_transforms((-0.032, 0.0, 0.172), (-0.032, 0.0, 0.068),
                                  (("caster_back_link", (-0.081, 0.0, -0.004)),)),
)

# Waffle: base box 0.266 x 0.266 x 0.094 m at (-0.064, 0, 0.047) in base_link; wheels at y ±0.144 (the drive
# plugin integrates with 0.287, the joints are 0.288 apart); LiDAR at (-0.064, 0, 0.122) in base_link, so 6.4 cm
# behind the axle and 0.132 m above the floor. Mass: base 1.3729 + wheels 2 x 0.0285 + casters 2 x 0.005 + LDS
# 0.114 kg. Camera: the RealSense R200 (a depth camera), sensor at camera_rgb_frame: base_link 0.010 up +
# camera_link (0.064, -0.065, 0.094) + (0.005, 0.018, 0.013).
WAFFLE_R200 = CameraSpec(x_m=0.069, y_m=-0.047, height_m=0.117, width_px=1920, height_px=1080, hfov_rad=1.3439,
                         rate_hz=30.0, hack_baseline_m=0.07, depth_range_m=(0.4, 5.0))
WAFFLE = TurtleBot3Model(
    name="waffle", body_x_min_m=-0.197, body_x_max_m=0.069, body_half_width_m=0.133, body_top_m=0.104,
    wheel_centre_y_m=0.144, wheel_separation_m=0.287, mass_kg=1.55, scan_x_m=-0.064, scan_height_m=0.132,
    max_linear_mps=0.26, max_angular_radps=1.82,
    static_transforms=_transforms(
        (-0.064, 0.0, 0.122), (0.0, 0.0, 0.068),
        (("caster_back_left_link", (-0.177, 0.064, -0.004)), ("caster_back_right_link", (-0.177, -0.064, -0.004))),
        camera=(("base_link", "camera_link", (0.064, -0.065, 0.094), (0.0, 0.0, 0.0)),
                ("camera_link", "camera_rgb_frame", (0.005, 0.018, 0.013), (0.0, 0.0, 0.0)),
                ("camera_rgb_frame", CAMERA_OPTICAL_FRAME, (0.0, 0.0, 0.0), OPTICAL_RPY),
                ("camera_link", "camera_depth_frame", (0.005, 0.028, 0.013), (0.0, 0.0, 0.0)),
                ("camera_depth_frame", "camera_depth_optical_frame", (0.0, 0.0, 0.0), OPTICAL_RPY))),
    camera=WAFFLE_R200,
)

# Waffle Pi: the Waffle with a Raspberry Pi camera (RGB only, 640 x 480, 1.085595 rad, 30 Hz) instead of the
# R200: camera_link at (0.073, -0.011, 0.084) in base_link, camera_rgb_frame (0.003, 0.011, 0.009) from it.
WAFFLE_PI_CAMERA = CameraSpec(x_m=0.076, y_m=0.0, height_m=0.103, width_px=640, height_px=480, hfov_rad=1.085595,
                              rate_hz=30.0, hack_baseline_m=0.07, depth_range_m=None)
WAFFLE_PI = TurtleBot3Model(
    name="waffle_pi", body_x_min_m=WAFFLE.body_x_min_m, body_x_max_m=WAFFLE.body_x_max_m,
    body_half_width_m=WAFFLE.body_half_width_m, body_top_m=WAFFLE.body_top_m,
    wheel_centre_y_m=WAFFLE.wheel_centre_y_m, wheel_separation_m=WAFFLE.wheel_separation_m, mass_kg=WAFFLE.mass_kg,
    scan_x_m=WAFFLE.scan_x_m, scan_height_m=WAFFLE.scan_height_m,
    max_linear_mps=WAFFLE.max_linear_mps, max_angular_radps=WAFFLE.max_angular_radps,
    static_transforms=_transforms(
        (-0.064, 0.0, 0.122), (0.0, 0.0, 0.068),
        (("caster_back_left_link", (-0.177, 0.064, -0.004)), ("caster_back_right_link", (-0.177, -0.064, -0.004))),
        camera=(("base_link", "camera_link", (0.073, -0.011, 0.084), (0.0, 0.0, 0.0)),
                ("camera_link", "camera_rgb_frame", (0.003, 0.011, 0.009), (0.0, 0.0, 0.0)),
                ("camera_rgb_frame", CAMERA_OPTICAL_FRAME, (0.0, 0.0, 0.0), OPTICAL_RPY))),
    camera=WAFFLE_PI_CAMERA,
)

TURTLEBOT3_MODELS = {model.name: model for model in (BURGER, WAFFLE, WAFFLE_PI)}
DEFAULT_MODEL = WAFFLE


def model_named(name):
    """The TurtleBot3Model for `name` (burger, waffle, waffle_pi); raises KeyError naming the choices."""
    try:
        return TURTLEBOT3_MODELS[name]
    except KeyError:
        raise KeyError(f"unknown TurtleBot3 model '{name}' (one of {', '.join(TURTLEBOT3_MODELS)})") from None


def model_of_robot_name(robot_name):
    """The model whose URDF robot name (turtlebot3_<model>) is `robot_name`, or None."""
    return next((m for m in TURTLEBOT3_MODELS.values() if m.robot_name == robot_name), None)
