"""Where the TurtleBot3 Waffle's camera sees the floor: which image rows show a stretch of floor ahead, and which
column lies on the robot's centre line there. The line follower crops those rows and steers that column onto
the line, so its gains mean the same at any camera resolution.

The camera is level, `CAMERA_HEIGHT_M` above the floor, with focal length f = width / (2 tan(hfov / 2)) px and
the optical axis at row (height + 1) / 2 (Gazebo's camera_info). A floor point d metres ahead of the camera
appears f * CAMERA_HEIGHT_M / d rows below that axis. The camera sits `CAMERA_RIGHT_OF_CENTRE_M` to the right of
the robot's centre, so the centre line runs that far left of the optical axis: f * 0.047 / d columns left of
it, 7 % of the width at 0.4 m. A follower that centres the line in the image instead runs 4.7 cm beside it.
"""
import math

# turtlebot3_waffle.urdf.xacro: camera_rgb_frame = base_link (0.010 up) + camera_link (0.064, -0.065, 0.094)
# + (0.005, 0.018, 0.013); the R200's horizontal_fov.
CAMERA_HEIGHT_M = 0.117
CAMERA_RIGHT_OF_CENTRE_M = 0.047
WAFFLE_HFOV_RAD = 1.3439


def focal_length_px(width, hfov_rad=WAFFLE_HFOV_RAD):
    return width / (2.0 * math.tan(hfov_rad / 2.0))


def floor_rows(width, height, near_m, far_m):
    """(first row, end row) of the image rows that show the floor from `far_m` to `near_m` ahead of the camera,
    for slicing image[first:end]; clipped to the image."""
    f, axis_row = focal_length_px(width), (height + 1) / 2.0
    first = axis_row + f * CAMERA_HEIGHT_M / far_m
    end = axis_row + f * CAMERA_HEIGHT_M / near_m
    return min(int(round(first)), height - 1), min(int(round(end)) + 1, height)


def centre_line_column(width, distance_m):
    """The image column where the robot's centre line meets the floor `distance_m` ahead of the camera."""
    return (width + 1) / 2.0 - focal_length_px(width) * CAMERA_RIGHT_OF_CENTRE_M / distance_m
