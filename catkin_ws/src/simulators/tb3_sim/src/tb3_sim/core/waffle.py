"""TurtleBot3 Waffle constants (spec §1), as data.

Frames: every planar coordinate here is in `base_footprint` (x ahead, y left, z up, origin on the floor
under the wheel axle centre) unless the name says otherwise. Values come from `turtlebot3_waffle.urdf.xacro`
and the Gazebo diff-drive configuration, not from the legacy `model.sdf` (spec §4).
"""

WAFFLE_MODEL_NAME = "turtlebot3_waffle"

# Collision box of base_link (0.266 x 0.266 x 0.094 m) expressed in base_footprint.
WAFFLE_BODY_X_MIN_M = -0.197
WAFFLE_BODY_X_MAX_M = 0.069
WAFFLE_BODY_HALF_WIDTH_M = 0.133
WAFFLE_BODY_TOP_M = 0.104

# The drive plugin's values; the URDF joints are 0.288 apart but Gazebo integrates with 0.287.
WAFFLE_WHEEL_SEPARATION_M = 0.287
WAFFLE_WHEEL_RADIUS_M = 0.033
WAFFLE_WHEEL_WIDTH_M = 0.018
WAFFLE_WHEEL_CENTRE_Y_M = 0.144

# Sum of the URDF inertials (base 1.3729, wheels 2 x 0.0285, casters 2 x 0.005, LDS 0.114).
WAFFLE_MASS_KG = 1.55

# LiDAR (base_scan) origin: 6.4 cm behind the axle, 0.132 m above the floor.
WAFFLE_SCAN_OFFSET_X_M = -0.064
WAFFLE_SCAN_HEIGHT_M = 0.132

# The RealSense R200's camera_rgb_frame (where Gazebo's depth camera sensor sits, so the RGB and depth images
# share one viewpoint) in base_footprint: base_link 0.010 up + camera_link (0.064, -0.065, 0.094) + (0.005,
# 0.018, 0.013). The optical frame turns the same origin to z ahead, x right, y down (REP 103).
WAFFLE_CAMERA_X_M = 0.069
WAFFLE_CAMERA_Y_M = -0.047
WAFFLE_CAMERA_HEIGHT_M = 0.117
WAFFLE_CAMERA_OPTICAL_FRAME = "camera_rgb_optical_frame"

WHEEL_JOINT_NAMES = ("wheel_left_joint", "wheel_right_joint")

# Vendor limits, used only by an optional clamp and by tests; the Gazebo plugin does not clamp.
WAFFLE_MAX_LINEAR_MPS = 0.26
WAFFLE_MAX_ANGULAR_RADPS = 1.82

# Fixed joints of the URDF for the static TF tree (robot_state_publisher is not in Debian):
# (parent, child, (x, y, z) in m, (roll, pitch, yaw) in rad).
WAFFLE_STATIC_TRANSFORMS = (
    ("base_footprint", "base_link", (0.0, 0.0, 0.010), (0.0, 0.0, 0.0)),
    ("base_link", "base_scan", (-0.064, 0.0, 0.122), (0.0, 0.0, 0.0)),
    ("base_link", "imu_link", (0.0, 0.0, 0.068), (0.0, 0.0, 0.0)),
    ("base_link", "camera_link", (0.064, -0.065, 0.094), (0.0, 0.0, 0.0)),
    ("camera_link", "camera_rgb_frame", (0.005, 0.018, 0.013), (0.0, 0.0, 0.0)),
    ("camera_rgb_frame", "camera_rgb_optical_frame", (0.0, 0.0, 0.0), (-1.57, 0.0, -1.57)),
    ("camera_link", "camera_depth_frame", (0.005, 0.028, 0.013), (0.0, 0.0, 0.0)),
    ("camera_depth_frame", "camera_depth_optical_frame", (0.0, 0.0, 0.0), (-1.57, 0.0, -1.57)),
    ("base_link", "caster_back_left_link", (-0.177, 0.064, -0.004), (-1.57, 0.0, 0.0)),
    ("base_link", "caster_back_right_link", (-0.177, -0.064, -0.004), (-1.57, 0.0, 0.0)),
)


def waffle_footprint():
    """Convex outlines of the robot's collision shapes in base_footprint, metres.

    Returns the base box and the two wheels (which stick out to y = ±0.153), each as a tuple of CCW
    (x, y) vertices. The casters are inside the base box and add nothing in 2D.
    """
    x0, x1, h = WAFFLE_BODY_X_MIN_M, WAFFLE_BODY_X_MAX_M, WAFFLE_BODY_HALF_WIDTH_M
    base = ((x0, -h), (x1, -h), (x1, h), (x0, h))
    r = WAFFLE_WHEEL_RADIUS_M
    y_in = WAFFLE_WHEEL_CENTRE_Y_M - WAFFLE_WHEEL_WIDTH_M / 2
    y_out = WAFFLE_WHEEL_CENTRE_Y_M + WAFFLE_WHEEL_WIDTH_M / 2
    left = ((-r, y_in), (r, y_in), (r, y_out), (-r, y_out))
    right = ((-r, -y_out), (r, -y_out), (r, -y_in), (-r, -y_in))
    return base, left, right
