"""A level 2.5D pinhole camera: the TurtleBot3 Waffle's RealSense R200 as Gazebo simulates it, rendered with numpy.

The world is a floor plan: vertical walls (segments) and vertical cylinders (circles), each standing on the floor
up to its own height, plus a floor and a sky. The floor is one flat colour (Gazebo's ground plane) or, for a world
with a floor layer, its texture seen in perspective (`use_floor`, core.floor_texture). The camera is level (no
pitch, no roll) at `mount_height_m` above the floor, looking along `yaw` in the world's x-y plane (x ahead, y left,
z up; yaw CCW from +x, radians).

What Gazebo does and this module copies (turtlebot3_description `turtlebot3_waffle.gazebo.xacro`, sensor
`realsense_R200` of type depth with `libgazebo_ros_openni_kinect.so`; gazebo_ros_pkgs `gazebo_ros_camera_utils.cpp`
and `gazebo_ros_openni_kinect.cpp`):
- 1920 x 1080 R8G8B8 images, horizontal_fov 1.3439 rad, 30 Hz, clip near 0.03 m / far 100 m, frame
  `camera_rgb_optical_frame` (x right, y down, z forward: REP 103's optical convention);
- camera_info when the plugin's `focalLength`, `Cx`, `Cy` are 0 (they are, for the Waffle): focal length
  f = width / (2 tan(hfov / 2)) for both fx and fy, cx = (width + 1) / 2, cy = (height + 1) / 2, distortion model
  plumb_bob with D = (k1, k2, t1, t2, k3) all zero, R the identity, P[3] = -fx * hackBaseline;
- the depth image is 32FC1 in metres, z along the optical axis, NaN outside the plugin's (pointCloudCutoff,
  pointCloudCutoffMax) = (0.4, 5.0) m band for the Waffle (0.4 from the xacro, 5.0 the plugin's default).

Pixel convention, kept exactly by the renderer: pixel (u, v) is column u and row v counted from 0 at the top-left
of the image as the camera sees it, and integer (u, v) is the pixel's centre. camera_info's cx, cy are pixel
indices in that convention, so the optical axis passes through (cx, cy) = (960.5, 540.5) for 1920 x 1080, one
pixel right of and below the image centre (959.5, 539.5). That offset is a quirk of Gazebo's formula: Gazebo's
renderer centres the axis (its own point cloud code uses (width - 1) / 2), so Gazebo's images disagree with its
camera_info by a pixel. Here the image follows camera_info, so a point projected with K lands on the pixel that
shows it.
"""
import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from tb3_sim.core.floor_texture import FloorSampler

# The clip planes of both TurtleBot3 cameras (the sensors' values: core.turtlebot3 lists the rest). The Waffle's
# xacro holds <hackBaseline> twice, 0.07 then 0; sdformat's Get() returns the first element. Its
# gazebo_ros_openni_kinect publishes depth only inside (cutoff, cutoff_max) = (0.4, 5.0) m; NaN elsewhere.
CLIP_NEAR_M = 0.03
CLIP_FAR_M = 100.0

DISTORTION_MODEL = "plumb_bob"
ZERO_DISTORTION = (0.0, 0.0, 0.0, 0.0, 0.0)
IDENTITY_RECTIFICATION = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)

# Lighting of walls and cylinders: one light from the azimuth of Gazebo's default sun (gazebo_models `sun`,
# direction (-0.5, 0.5, -1.0), the way its light travels) over a strong ambient term. A face of colour c with
# horizontal unit normal n is drawn as c * (AMBIENT_SHADE + DIRECTIONAL_SHADE * max(0, n . towards_sun)), so
# faces differ (edges show) but keep 60..100 % of their colour. Gazebo's own numbers (scene ambient 0.4, sun
# diffuse 0.8) leave faces turned from the sun at 40 %, too dark for usual HSV thresholds (V >= 120 for yellow).
SUN_DIRECTION = (-0.5, 0.5, -1.0)
AMBIENT_SHADE = 0.6
DIRECTIONAL_SHADE = 0.4
# Not Gazebo either: a mild dimming with depth so that objects of one colour stay apart; hues do not change.
DEPTH_DIMMING_PER_M = 0.025
MIN_DEPTH_DIMMING = 0.6

_MAX_CHANNEL = 255.0
# Depth image accumulation (see _DepthCanvas): spans whose depth is outside the published band are marked with
# this negative value, and an accumulated value below half a near clip means "no object here".
_OUT_OF_BAND_MARK = -1.0


@dataclass(frozen=True)
class CameraIntrinsics:
    """Image size and horizontal field of view; the pinhole model of sensor_msgs/CameraInfo derived as Gazebo does.

    width, height: pixels (> 0). hfov_rad: horizontal field of view in (0, pi). hack_baseline_m: the plugin's
    hackBaseline, only used for P[3] (0 for a mono camera).
    Convention (see the module docstring): integer pixel indices are pixel centres and (cx, cy) is the pixel index
    of the optical axis, (width + 1) / 2 and (height + 1) / 2 as in gazebo_ros_camera_utils. The renderer projects
    with exactly these numbers.
    """

    width: int
    height: int
    hfov_rad: float
    hack_baseline_m: float = 0.0

    def __post_init__(self):
        if int(self.width) != self.width or int(self.height) != self.height or self.width <= 0 or self.height <= 0:
            raise ValueError(f"image size must be positive whole pixels, got {self.width} x {self.height}")
        if not 0.0 < self.hfov_rad < math.pi:
            raise ValueError(f"horizontal_fov must be in (0, pi) rad, got {self.hfov_rad}")

    @classmethod
    def of(cls, spec, width_px=None, height_px=None):
        """The intrinsics of a turtlebot3.CameraSpec, at another image size if one is given."""
        return cls(width_px or spec.width_px, height_px or spec.height_px, spec.hfov_rad, spec.hack_baseline_m)

    @property
    def fx(self):
        """Focal length in pixels: width / (2 tan(hfov / 2))."""
        return self.width / (2.0 * math.tan(self.hfov_rad / 2.0))

    @property
    def fy(self):
        """Equal to fx: Gazebo's pixels are square."""
        return self.fx

    @property
    def cx(self):
        """Column index of the optical axis: (width + 1) / 2."""
        return (self.width + 1) / 2.0

    @property
    def cy(self):
        """Row index of the optical axis: (height + 1) / 2."""
        return (self.height + 1) / 2.0

    def k(self):
        """CameraInfo K, row-major 3 x 3."""
        return (self.fx, 0.0, self.cx, 0.0, self.fy, self.cy, 0.0, 0.0, 1.0)

    def p(self):
        """CameraInfo P, row-major 3 x 4, with P[3] = -fx * hack_baseline_m."""
        return (self.fx, 0.0, self.cx, -self.fx * self.hack_baseline_m,
                0.0, self.fy, self.cy, 0.0,
                0.0, 0.0, 1.0, 0.0)


@dataclass(frozen=True, eq=False)
class CameraScene:
    """What the camera can see, in world coordinates (metres), as plain arrays.

    segments: (N, 4) x1, y1, x2, y2 of vertical walls (a polygon is its edges); segment_heights: (N,) m > 0;
    segment_colours: (N, 3) uint8 RGB. circles: (M, 3) centre x, y and radius of vertical cylinders;
    circle_heights: (M,); circle_colours: (M, 3). Either kind may be empty. Arrays are converted on construction.
    """

    segments: np.ndarray
    segment_heights: np.ndarray
    segment_colours: np.ndarray
    circles: np.ndarray
    circle_heights: np.ndarray
    circle_colours: np.ndarray

    def __post_init__(self):
        for name, columns, dtype in (("segments", 4, float), ("segment_heights", None, float),
                                     ("segment_colours", 3, np.uint8), ("circles", 3, float),
                                     ("circle_heights", None, float), ("circle_colours", 3, np.uint8)):
            array = np.asarray(getattr(self, name), dtype=dtype)
            if columns is not None:
                array = array.reshape(-1, columns)
            object.__setattr__(self, name, array)
        for shapes, heights, colours in (("segments", "segment_heights", "segment_colours"),
                                         ("circles", "circle_heights", "circle_colours")):
            count = len(getattr(self, shapes))
            if len(getattr(self, heights)) != count or len(getattr(self, colours)) != count:
                raise ValueError(f"{shapes}, {heights} and {colours} must have one row per shape")

    @classmethod
    def empty(cls):
        """No walls, no cylinders: the camera sees floor and sky."""
        return cls(np.empty((0, 4)), np.empty(0), np.empty((0, 3)), np.empty((0, 3)), np.empty(0), np.empty((0, 3)))


class CameraFrame(NamedTuple):
    """rgb: (H, W, 3) uint8, row 0 at the top. depth: (H, W) float32 metres along the optical axis, NaN where there
    is no return; None unless asked for."""

    rgb: np.ndarray
    depth: np.ndarray | None


def project_point(intrinsics, mount_height_m, cam_x, cam_y, cam_yaw, px, py, pz):
    """Pixel (u, v) and depth (m along the optical axis) of world point (px, py, pz) for a level camera at
    (cam_x, cam_y, mount_height_m) looking along cam_yaw. u and v are NaN when the point is not in front
    (depth <= 0). Uses the CameraIntrinsics convention, so it predicts the renderer's pixels."""
    dx, dy = px - cam_x, py - cam_y
    depth = dx * math.cos(cam_yaw) + dy * math.sin(cam_yaw)
    if depth <= 0.0:
        return math.nan, math.nan, depth
    left = -dx * math.sin(cam_yaw) + dy * math.cos(cam_yaw)
    u = intrinsics.cx - intrinsics.fx * left / depth
    v = intrinsics.cy + intrinsics.fy * (mount_height_m - pz) / depth
    return u, v, depth


_OUTWARDS, _INWARDS = 1.0, -1.0


class _View(NamedTuple):
    """The camera's place for one frame, and the horizontal direction towards the sun in the camera's (forward,
    left) frame."""

    x: float
    y: float
    cos_yaw: float
    sin_yaw: float
    sun_fwd: float
    sun_left: float

    @classmethod
    def at(cls, x, y, yaw):
        cos_yaw, sin_yaw = math.cos(yaw), math.sin(yaw)
        norm = math.hypot(SUN_DIRECTION[0], SUN_DIRECTION[1])
        towards_sun_x, towards_sun_y = -SUN_DIRECTION[0] / norm, -SUN_DIRECTION[1] / norm
        return cls(x, y, cos_yaw, sin_yaw, towards_sun_x * cos_yaw + towards_sun_y * sin_yaw,
                   -towards_sun_x * sin_yaw + towards_sun_y * cos_yaw)

    def to_camera(self, px, py):
        """World x, y (arrays) to (forward, left) distances from the camera, metres."""
        dx, dy = px - self.x, py - self.y
        return dx * self.cos_yaw + dy * self.sin_yaw, -dx * self.sin_yaw + dy * self.cos_yaw

    def light(self, normal_fwd, normal_left):
        """Lighting factor of a vertical face with this horizontal unit normal (camera frame)."""
        return AMBIENT_SHADE + DIRECTIONAL_SHADE * np.maximum(
            0.0, normal_fwd * self.sun_fwd + normal_left * self.sun_left)


class _Hits(NamedTuple):
    """Ray hits of one frame: depth (W, K) with inf for a miss, and per hit column k its object's height (K,),
    colour (K, 3) and the lighting factor (W, K) or (K,)."""

    depth: np.ndarray
    height: np.ndarray
    colour: np.ndarray
    light: np.ndarray


class _Spans(NamedTuple):
    """Visible row spans of one frame, one entry per span: image column, first row, end row (exclusive), depth
    along the optical axis (m) and the shaded uint8 RGB colour (n, 3). Spans of one column never overlap."""

    column: np.ndarray
    first: np.ndarray
    end: np.ndarray
    depth: np.ndarray
    rgb: np.ndarray


_NO_SPANS = _Spans(np.empty(0, dtype=np.intp), np.empty(0, dtype=np.intp), np.empty(0, dtype=np.intp), np.empty(0),
                   np.empty((0, 3), dtype=np.uint8))


class CameraRenderer:
    """Renders CameraScenes for one camera: intrinsics, mount height, floor and sky colours and clip planes fixed.

    mount_height_m: optical centre above the floor (> 0). floor_rgb, sky_rgb: uint8 RGB drawn as given (no
    shading; materials.FLOOR_RGB and SKY_RGB are Gazebo's). The floor is visible up to far_clip_m; beyond it, and
    above the horizon, the sky shows. Objects nearer than near_clip_m or farther than far_clip_m (depth along
    the optical axis) are not drawn. depth_min_m, depth_max_m: the band where the depth image has values (default:
    the clip planes; Gazebo's Waffle publishes only strictly inside 0.4 and 5.0 m). Walls and cylinders are
    shaded as described at AMBIENT_SHADE and dimmed with depth; shading never changes a hue. What depends only on
    the camera (column rays, the floor row, the background) is computed here once, and image-sized scratch buffers
    are reused, so an instance must not render from two threads at once. The images render() returns are new
    arrays, safe to keep.
    """

    def __init__(self, intrinsics, mount_height_m, floor_rgb, sky_rgb, far_clip_m=CLIP_FAR_M,
                 near_clip_m=CLIP_NEAR_M, depth_min_m=None, depth_max_m=None):
        if mount_height_m <= 0.0:
            raise ValueError(f"mount_height_m must be above the floor (> 0), got {mount_height_m}")
        if not 0.0 < near_clip_m < far_clip_m:
            raise ValueError(f"clip planes must satisfy 0 < near < far, got near {near_clip_m}, far {far_clip_m}")
        self.intrinsics = intrinsics
        self.mount_height_m = float(mount_height_m)
        self.near_clip_m = float(near_clip_m)
        self.far_clip_m = float(far_clip_m)
        self.depth_min_m = self.near_clip_m if depth_min_m is None else float(depth_min_m)
        self.depth_max_m = self.far_clip_m if depth_max_m is None else float(depth_max_m)
        if not 0.0 <= self.depth_min_m < self.depth_max_m:
            raise ValueError(f"depth band must satisfy 0 <= min < max, got {self.depth_min_m}..{self.depth_max_m}")
        width, height = intrinsics.width, intrinsics.height
        # Ray of column j: direction forward + slope_j * left, so the ray parameter is the depth itself.
        self._slope = (intrinsics.cx - np.arange(width)) / intrinsics.fx
        self._slope_max, self._slope_min = self._slope[0], self._slope[-1]
        # First row that shows floor nearer than the far clip; rows above it show sky (where no object is).
        self._floor_row = min(height, math.ceil(intrinsics.cy + intrinsics.fy * self.mount_height_m / self.far_clip_m))
        self._rgb = _RgbCanvas(width, height, self._floor_row, floor_rgb, sky_rgb)
        self._depth = _DepthCanvas(width, height, self._floor_depth_by_row(),
                                   max(self.near_clip_m, self.depth_min_m) / 2.0)
        self._floor_sampler = None
        floor_rows = max(0, height - self._floor_row)
        self._coverage = np.empty((floor_rows, width), dtype=np.int8)
        self._bare = np.empty((floor_rows, width), dtype=np.uint8)

    def use_floor(self, texture):
        """Draw the floor from `texture` (a floor_texture.FloorTexture: a floor of a world's floor layer, where the
        ray meets it, and the background grey outside it) instead of the flat floor colour; None: flat again. Depth
        is NaN where the floor plane is outside the floor rectangle, as Gazebo's depth camera sees no geometry
        there."""
        self._floor_sampler = None if texture is None else FloorSampler(self.intrinsics, self.mount_height_m,
                                                                        self._floor_row, texture)

    def render(self, x, y, yaw, scene, depth=False):
        """Image of `scene` from the camera at world (x, y) looking along yaw (rad): a CameraFrame with rgb and,
        if `depth`, the depth image."""
        spans = self._visible_spans(self._hits(x, y, yaw, scene))
        rgb = self._rgb.draw(spans)
        depth_image = self._depth.draw(spans, self._depth_marks(spans.depth)) if depth else None
        if self._floor_sampler is not None:
            self._draw_floor(spans, x, y, yaw, rgb, depth_image)
        return CameraFrame(rgb, depth_image)

    def _draw_floor(self, spans, x, y, yaw, rgb, depth):
        """Copies the sampled floor into the rows below the horizon where no object covers it."""
        first = self._floor_row
        if first >= self.intrinsics.height:
            return
        import cv2

        floor = self._floor_sampler.sample(x, y, yaw, inside=depth is not None)
        bare = self._bare_floor(spans)
        cv2.copyTo(floor.rgb, bare, rgb[first:])
        if depth is not None:
            # Bare floor outside the floor rectangle: no geometry, no depth.
            outside = cv2.compare(bare, floor.inside, cv2.CMP_GT)
            depth[first:][outside != 0] = np.nan

    def _bare_floor(self, spans):
        """(rows below the horizon, W) uint8: 255 where no span covers the pixel (a running count of spans)."""
        first, width = self._floor_row, self.intrinsics.width
        covered = self._coverage
        covered.fill(0)
        start = np.maximum(spans.first, first) - first
        end = spans.end - first
        keep = end > start
        flat = covered.reshape(-1)
        flat[start[keep] * width + spans.column[keep]] += 1
        inside = keep & (spans.end < self.intrinsics.height)
        flat[end[inside] * width + spans.column[inside]] -= 1
        _running_sum(covered)
        import cv2

        return cv2.compare(covered, 0, cv2.CMP_EQ, dst=self._bare)

    def _floor_depth_by_row(self):
        rows = np.arange(self.intrinsics.height, dtype=float)
        with np.errstate(divide="ignore"):
            floor_depth = self.mount_height_m * self.intrinsics.fy / (rows - self.intrinsics.cy)
        floor_depth[rows < self._floor_row] = np.nan
        floor_depth[~self._in_depth_band(floor_depth)] = np.nan
        return floor_depth.astype(np.float32)

    def _in_depth_band(self, depth):
        return (depth > self.depth_min_m) & (depth < self.depth_max_m)

    def _depth_marks(self, span_depth):
        return np.where(self._in_depth_band(span_depth), span_depth, _OUT_OF_BAND_MARK)

    def _hits(self, x, y, yaw, scene):
        """Per column, the depth of every wall and cylinder the column's ray meets within the clip planes."""
        view = _View.at(x, y, yaw)
        slope = self._slope[:, None]
        parts = []
        with np.errstate(divide="ignore", invalid="ignore"):
            if len(scene.segments):
                parts.append(self._segment_hits(scene, view, slope))
            if len(scene.circles):
                parts.extend(self._circle_hits(scene, view, slope))
        parts = [part for part in parts if part.depth.shape[1]]
        if not parts:
            return None
        width = self.intrinsics.width
        return _Hits(np.concatenate([part.depth for part in parts], axis=1),
                     np.concatenate([part.height for part in parts]),
                     np.concatenate([part.colour for part in parts]),
                     np.concatenate([np.broadcast_to(part.light, (width, part.depth.shape[1])) for part in parts],
                                    axis=1))

    def _in_clip(self, depth):
        """depth where it is a number inside the clip planes, else inf (a miss)."""
        return np.where((depth >= self.near_clip_m) & (depth <= self.far_clip_m), depth, np.inf)

    def _segment_hits(self, scene, view, slope):
        seg = scene.segments
        fwd1, left1 = view.to_camera(seg[:, 0], seg[:, 1])
        fwd2, left2 = view.to_camera(seg[:, 2], seg[:, 3])
        # Cull walls behind the near plane, beyond the far plane, or wholly left or right of the field of view.
        keep = ~((fwd1 < self.near_clip_m) & (fwd2 < self.near_clip_m))
        keep &= np.minimum(fwd1, fwd2) <= self.far_clip_m
        keep &= ~((left1 > self._slope_max * fwd1) & (left2 > self._slope_max * fwd2))
        keep &= ~((left1 < self._slope_min * fwd1) & (left2 < self._slope_min * fwd2))
        fwd1, left1, fwd2, left2 = fwd1[keep], left1[keep], fwd2[keep], left2[keep]
        d_fwd, d_left = fwd2 - fwd1, left2 - left1
        # The ray (s, s * slope) meets the wall at fraction t of the way from end 1 to end 2.
        t = (left1 - fwd1 * slope) / (d_fwd * slope - d_left)
        depth = self._in_clip(np.where((t >= 0.0) & (t <= 1.0), fwd1 + t * d_fwd, np.inf))
        # Light the face the camera sees: the wall's normal that points towards the camera.
        length = np.hypot(d_fwd, d_left)
        normal_fwd, normal_left = d_left / length, -d_fwd / length
        towards_camera = np.where(normal_fwd * fwd1 + normal_left * left1 > 0.0, -1.0, 1.0)
        light = view.light(towards_camera * normal_fwd, towards_camera * normal_left)
        return _Hits(depth, scene.segment_heights[keep], scene.segment_colours[keep], light)

    def _circle_hits(self, scene, view, slope):
        """The cylinders' near surfaces and, for cylinders lower than the camera, their far surfaces too, whose
        inside shows where the cylinder's top would be."""
        fwd, left = view.to_camera(scene.circles[:, 0], scene.circles[:, 1])
        radius = scene.circles[:, 2]
        # Cull cylinders behind the near plane, beyond the far plane, around the camera, or outside the field of
        # view (farther than their radius from the half-plane on the inside of either edge of the view).
        keep = (fwd + radius >= self.near_clip_m) & (fwd - radius <= self.far_clip_m)
        keep &= fwd ** 2 + left ** 2 > radius ** 2
        keep &= (left - self._slope_max * fwd) / math.hypot(1.0, self._slope_max) <= radius
        keep &= (self._slope_min * fwd - left) / math.hypot(1.0, self._slope_min) <= radius
        fwd, left, radius = fwd[keep], left[keep], radius[keep]
        heights, colours = scene.circle_heights[keep], scene.circle_colours[keep]
        # |s (1, slope) - centre|^2 = radius^2, i.e. a s^2 - 2 b s + c = 0, for the ray parameter (= depth) s.
        a = 1.0 + slope ** 2
        b = fwd + left * slope
        root = np.sqrt(b ** 2 - a * (fwd ** 2 + left ** 2 - radius ** 2))
        near_side = (b - root) / a
        low = heights < self.mount_height_m
        far_side = ((b + root) / a)[:, low]
        return (self._circle_part(near_side, slope, fwd, left, radius, heights, colours, view, _OUTWARDS),
                self._circle_part(far_side, slope, fwd[low], left[low], radius[low], heights[low], colours[low], view,
                                  _INWARDS))

    def _circle_part(self, depth, slope, fwd, left, radius, heights, colours, view, facing):
        """Hits at `depth` (NaN for a miss) on cylinders, lit with their normal times `facing` (+1 outwards)."""
        depth = self._in_clip(depth)
        light = view.light(facing * (depth - fwd) / radius, facing * (depth * slope - left) / radius)
        return _Hits(depth, heights, colours, light)

    def _visible_spans(self, hits):
        """The visible parts of the hits, as _Spans.

        Per column, hits sorted near to far: a hit covers rows from its top down to its foot on the floor; every
        nearer hit's foot is lower, so a nearer hit hides the farther one from the nearer one's top downwards, and
        the visible part of hit k ends at the smallest first row of the hits in front of it."""
        if hits is None:
            return _NO_SPANS
        count = int(np.isfinite(hits.depth).sum(axis=1).max())
        if count == 0:
            return _NO_SPANS
        intr, height = self.intrinsics, self.intrinsics.height
        order = np.argsort(hits.depth, axis=1)[:, :count]
        depth = np.take_along_axis(hits.depth, order, axis=1)
        hit = np.isfinite(depth)
        safe_depth = np.where(hit, depth, 1.0)
        top = intr.cy - intr.fy * (hits.height[order] - self.mount_height_m) / safe_depth
        foot = intr.cy + intr.fy * self.mount_height_m / safe_depth
        first = np.where(hit, np.clip(np.ceil(top), 0, height), height).astype(np.intp)
        end = np.where(hit, np.clip(np.floor(foot) + 1, 0, height), height).astype(np.intp)
        nearer_first = np.minimum.accumulate(first, axis=1)
        end[:, 1:] = np.minimum(end[:, 1:], nearer_first[:, :-1])
        column, rank = np.nonzero(end > first)
        obj = order[column, rank]
        span_depth = depth[column, rank]
        shade = hits.light[column, obj] * np.maximum(MIN_DEPTH_DIMMING, 1.0 - DEPTH_DIMMING_PER_M * span_depth)
        rgb = np.minimum(hits.colour[obj] * shade[:, None], _MAX_CHANNEL).astype(np.uint8)
        return _Spans(column, first[column, rank], end[column, rank], span_depth, rgb)


class _RgbCanvas:
    """Paints the spans over the sky/floor background with one pass over a new image.

    Each column of the image is piecewise constant, so the image is the running sum, down the rows, of a sparse
    image of changes: the background's (sky at row 0, floor from the floor row) plus, per span, colour minus
    background at its first row and the reverse at its end (and a correction where a span crosses the floor row).
    uint8 arithmetic wraps modulo 256, so the running sum gives exact colours; it costs one numpy add per row."""

    def __init__(self, width, height, floor_row, floor_rgb, sky_rgb):
        self._width, self._height, self._floor_row = width, height, floor_row
        self._sky = np.asarray(sky_rgb, dtype=np.int16)
        self._floor = np.asarray(floor_rgb, dtype=np.int16)
        self._sky_row = np.tile(self._sky, width).astype(np.uint8)
        self._floor_row_change = np.tile(self._floor - self._sky, width).astype(np.uint8)

    def draw(self, spans):
        image = np.zeros((self._height, 3 * self._width), dtype=np.uint8)
        image[0] = self._sky_row
        if self._floor_row < self._height:
            image[self._floor_row] = self._floor_row_change
        colour = spans.rgb.astype(np.int16)
        channel = 3 * spans.column[:, None] + np.arange(3)
        self._add(image, spans.first, channel, colour - self._background_at(spans.first))
        inside = spans.end < self._height
        self._add(image, spans.end[inside], channel[inside],
                  self._background_at(spans.end[inside] - 1) - colour[inside])
        crosses = (spans.first < self._floor_row) & (spans.end > self._floor_row)
        self._add(image, np.full(int(crosses.sum()), self._floor_row), channel[crosses], self._sky - self._floor)
        _running_sum(image)
        return image.reshape(self._height, self._width, 3)

    def _background_at(self, rows):
        return np.where((rows < self._floor_row)[:, None], self._sky, self._floor)

    @staticmethod
    def _add(image, rows, channel, change):
        """Adds change ((n, 3) or (3,)) at (rows, channel); the positions must be distinct within one call."""
        image.reshape(-1)[rows[:, None] * image.shape[1] + channel] += np.asarray(change).astype(np.uint8)


class _DepthCanvas:
    """The depth image by the same running sum in float32: +depth at a span's first row, -depth at its end.

    Rounding leaves a residue of order 1e-5 m where no span is, far below `object_threshold_m` (half the smallest
    depth a span can have), so a larger sum is an object's depth. Sums near _OUT_OF_BAND_MARK (spans outside the
    depth band) become NaN; where the sum is below the threshold the floor's depth (a function of the row, NaN
    outside the band) shows."""

    def __init__(self, width, height, floor_depth_by_row, object_threshold_m):
        self._width, self._height = width, height
        self._background = np.ascontiguousarray(np.broadcast_to(floor_depth_by_row[:, None], (height, width)))
        self._object_threshold = np.float32(object_threshold_m)
        self._out_of_band_threshold = np.float32(_OUT_OF_BAND_MARK / 2)
        # Scratch: fresh image-sized temporaries would cost a page fault per 4 KiB on every frame.
        self._mask = np.empty((height, width), dtype=bool)

    def draw(self, spans, marked_depth):
        depth = np.zeros((self._height, self._width), dtype=np.float32)
        flat = depth.reshape(-1)
        value = marked_depth.astype(np.float32)
        flat[spans.first * self._width + spans.column] += value
        inside = spans.end < self._height
        flat[spans.end[inside] * self._width + spans.column[inside]] -= value[inside]
        _running_sum(depth)
        np.copyto(depth, np.float32(np.nan), where=np.less(depth, self._out_of_band_threshold, out=self._mask))
        np.copyto(depth, self._background, where=np.less(depth, self._object_threshold, out=self._mask))
        return depth


def _running_sum(image):
    """image[i] += image[i - 1] for rows i = 1.. in place: a cumulative sum down the image, one contiguous add per
    row (numpy's cumsum along axis 0 is an order of magnitude slower on images)."""
    rows = list(image)
    for above, row in zip(rows, rows[1:]):
        np.add(above, row, out=row)
