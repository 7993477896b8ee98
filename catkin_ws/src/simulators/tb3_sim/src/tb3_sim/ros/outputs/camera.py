"""A robot's camera as Gazebo's camera plugins publish it: the Waffle's RealSense R200 (openni_kinect plugin,
turtlebot3_waffle.gazebo.xacro) and the Waffle Pi's Raspberry Pi camera (camera plugin, RGB only); the Burger
has none. Topics (in the robot's namespace):

- /camera/rgb/image_raw (sensor_msgs/Image, rgb8) and /camera/rgb/camera_info;
- /camera/rgb/image_raw/compressed (sensor_msgs/CompressedImage): JPEG at quality 80 with the format string
  compressed_image_transport writes for an rgb8 image ("rgb8; jpeg compressed bgr8"); Debian has no Python
  image_transport plugins, so the simulator publishes this topic itself;
- the R200 only: /camera/depth/image_raw (sensor_msgs/Image, 32FC1, metres along the optical axis; NaN where
  nothing is hit and outside the plugin's 0.4..5.0 m band, as Gazebo's Waffle publishes it) and
  /camera/depth/camera_info.
All in frame camera_rgb_optical_frame (the plugin's frameName, also for depth: one sensor, one viewpoint; with the
robot's tf_prefix), at the sensor's rate of sim time (30 Hz), size and horizontal field of view (R200 1920x1080,
1.3439 rad; Pi camera 640x480, 1.085595 rad), as core.turtlebot3 lists them; camera_info as Gazebo computes it
(see core.camera).
Images are queued (see output.Topic): a subscriber that cannot keep up misses frames, the simulation does not
slow down. Lazy: nothing is rendered while no image topic has a subscriber; a camera_info subscriber alone gets
camera_info without a render (Gazebo publishes it only with images). Depth is rendered only while someone takes
it.
The picture is a 2.5D render of the 2D world (core.camera): walls, pillars and models as upright solids of their
height and colour, a floor and a sky. A world with a floor layer shows it in perspective, markings and image
included, lit as Gazebo lights the course floors (core.floor_texture); the depth image then reads the floor's
distance wherever the floor rectangle shows.
"""

import threading
from typing import NamedTuple, Optional

import numpy as np
from sensor_msgs.msg import CameraInfo, CompressedImage, Image

from tb3_sim.core.camera import (
    DISTORTION_MODEL,
    IDENTITY_RECTIFICATION,
    ZERO_DISTORTION,
    CameraIntrinsics,
    CameraRenderer,
    CameraScene,
)
from tb3_sim.core.materials import FLOOR_RGB, SKY_RGB
from tb3_sim.core.turtlebot3 import CAMERA_OPTICAL_FRAME
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

# compressed_image_transport's default quality and the format string it writes for an rgb8 image.
JPEG_QUALITY = 80
JPEG_FORMAT = "rgb8; jpeg compressed bgr8"

RGB_TOPIC = "camera/rgb/image_raw"
RGB_INFO_TOPIC = "camera/rgb/camera_info"
COMPRESSED_TOPIC = "camera/rgb/image_raw/compressed"
DEPTH_TOPIC = "camera/depth/image_raw"
DEPTH_INFO_TOPIC = "camera/depth/camera_info"


class CameraReading(NamedTuple):
    """One frame at `time_s`: `rgb` (H, W, 3) uint8 or None, `depth` (H, W) float32 metres or None."""

    time_s: float
    rgb: Optional[np.ndarray]
    depth: Optional[np.ndarray]


class FloorTextures:
    """The camera's texture of a world's floor layer (view.floor_raster: about 1 s for a detailed 8 x 8 m floor,
    20 s on a 2-core machine at load 20 with the imports it needs), built once and shared by every camera of the
    simulator. The node starts building the world's at world load (`prepare`), as Gazebo loads a world's textures,
    in a thread of its own, so neither the node's start nor the physics loop at the first image waits for it; a
    camera whose first image comes sooner waits for the build to finish."""

    def __init__(self):
        self._lock = threading.Lock()
        self._floor = self._texture = None

    def prepare(self, floor):
        """Start building the texture of the floor.Floor `floor` (None: no floor layer, nothing to build)."""
        if floor is not None:
            threading.Thread(target=self.of, args=(floor,), name="floor texture", daemon=True).start()

    def of(self, floor):
        """The FloorTexture of the floor.Floor `floor`; None for a world without a floor layer."""
        if floor is None:
            return None
        with self._lock:
            if floor is not self._floor:
                from tb3_sim.view.floor_raster import floor_texture  # Qt: loaded by worlds with a floor only

                self._floor, self._texture = floor, floor_texture(floor)
            return self._texture


class CameraOutput(Output):
    """`robot`'s camera (`spec`, a turtlebot3.CameraSpec), named by `naming` (a RobotNaming); the image size and
    rate are the spec's unless given; the floor's texture comes from `floor_textures` (a FloorTextures, its own
    unless given)."""

    lazy = True

    def __init__(self, robot, naming, spec, width_px=None, height_px=None, rate_hz=None, floor_textures=None):
        self.rate_hz = rate_hz or spec.rate_hz
        super().__init__()
        self.robot = robot
        self.spec = spec
        self.frame_id = naming.frame(CAMERA_OPTICAL_FRAME)
        self.frame_ids = (self.frame_id,)
        self.intrinsics = CameraIntrinsics.of(spec, width_px, height_px)
        depth_min_m, depth_max_m = spec.depth_range_m or (None, None)
        self.renderer = CameraRenderer(self.intrinsics, spec.height_m, FLOOR_RGB, SKY_RGB, far_clip_m=spec.clip_far_m,
                                       near_clip_m=spec.clip_near_m, depth_min_m=depth_min_m, depth_max_m=depth_max_m)
        self._floor_textures = floor_textures or FloorTextures()
        self._floor = None
        self._depth_topic = naming.topic(DEPTH_TOPIC)
        topics = [
            Topic(naming.topic(RGB_TOPIC), Image, self._rgb_image, queued=True),
            Topic(naming.topic(RGB_INFO_TOPIC), CameraInfo, self._camera_info),
            Topic(naming.topic(COMPRESSED_TOPIC), CompressedImage, self._compressed_image, queued=True),
        ]
        if spec.depth_range_m is not None:
            topics += [Topic(self._depth_topic, Image, self._depth_image, queued=True),
                       Topic(naming.topic(DEPTH_INFO_TOPIC), CameraInfo, self._camera_info)]
        self.topics = tuple(topics)
        self._image_topics = {topic.name for topic in self.topics if topic.queued}

    def read(self, world, now_s, wanted):
        rgb = depth = None
        if wanted & self._image_topics:
            self._see_floor(world.description.floor)
            pose = self.robot.pose
            x, y = pose.compose(self.spec.x_m, self.spec.y_m)
            rgb, depth = self.renderer.render(x, y, pose.yaw, camera_scene(world.obstacles(excluding=self.robot)),
                                              depth=self._depth_topic in wanted)
        return CameraReading(now_s, rgb, depth)

    def _see_floor(self, floor):
        """Give the renderer the world's floor layer, or keep the plain ground plane when the world has none."""
        if floor is not self._floor:
            self._floor = floor
            self.renderer.use_floor(self._floor_textures.of(floor))

    def _header(self, message, time_s):
        message.header.stamp = messages.stamp(time_s)
        message.header.frame_id = self.frame_id
        return message

    def _rgb_image(self, reading):
        return self._image(reading, reading.rgb, "rgb8")

    def _depth_image(self, reading):
        return self._image(reading, reading.depth, "32FC1")

    def _image(self, reading, pixels, encoding):
        message = self._header(Image(), reading.time_s)
        message.height, message.width = pixels.shape[:2]
        message.encoding = encoding
        message.is_bigendian = 0
        message.step = pixels.strides[0]
        message.data = pixels.tobytes()
        return message

    def _compressed_image(self, reading):
        message = self._header(JpegImage(reading.rgb), reading.time_s)
        message.format = JPEG_FORMAT
        return message

    def _camera_info(self, reading):
        message = self._header(CameraInfo(), reading.time_s)
        message.width, message.height = self.intrinsics.width, self.intrinsics.height
        message.distortion_model = DISTORTION_MODEL
        message.D = list(ZERO_DISTORTION)
        message.K = list(self.intrinsics.k())
        message.R = list(IDENTITY_RECTIFICATION)
        message.P = list(self.intrinsics.p())
        return message


class JpegImage(CompressedImage):
    """sensor_msgs/CompressedImage of an RGB frame whose JPEG (quality JPEG_QUALITY, BGR samples as
    compressed_image_transport writes) is encoded when `data` is first read: as the queued publisher's thread
    serialises it, so the physics loop only renders (ros.publishers.QueuedPublisher). The frame is the renderer's
    own new array, never written again."""

    def __init__(self, rgb):
        super().__init__()
        self._rgb = rgb

    @property
    def data(self):
        if self._rgb is not None:
            import cv2  # about 0.4 s to import: paid at the first compressed frame, not at every simulator start

            bgr = cv2.cvtColor(self._rgb, cv2.COLOR_RGB2BGR)
            self._jpeg = cv2.imencode(".jpg", bgr, [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY])[1].tobytes()
            self._rgb = None
        return self._jpeg

    @data.setter
    def data(self, value):
        self._rgb, self._jpeg = None, value


def camera_scene(obstacles):
    """The camera's view of an obstacles.Obstacles: upright walls and cylinders with their tops and colours."""
    return CameraScene(obstacles.lines, obstacles.line_tops, obstacles.line_rgb,
                       obstacles.circles, obstacles.circle_tops, obstacles.circle_rgb)
