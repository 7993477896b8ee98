"""The simulator node's parameters as one validated, typed object (no ROS imports: the node passes a dict).

Private parameters (all optional; see `tb3_sim.ros.node` for what each one does):

    ~world                   "empty"    a shipped world name (empty, turtlebot3_world, approach_arena) or a path
                                        to a world YAML file
    ~spawn_robot             true       false: start without a robot (gazebo_ros's empty world); robots then
                                        come with /gazebo/spawn_urdf_model (spawn_model -urdf)
    ~model                   "waffle"   the robot's TurtleBot3 model: burger, waffle or waffle_pi
    ~x_pos, ~y_pos, ~yaw     0.0        robot spawn pose in the world frame (m, m, rad)
    ~robot_name              turtlebot3_<model>  the robot's model name in /gazebo/* services
    ~seed                    0          LiDAR noise seed (int)
    ~real_time_factor        1.0        sim seconds per wall second; any value > 0, or 0 = as fast as possible
    ~clock_rate              100.0      /clock messages per second of sim time; 0 = after every physics step
    ~lidar_sees_low_objects  false      true: the scan also sees models lower than the scan plane (0.132 m on a
                                        Waffle)
    ~clamp_command           false      true: clamp cmd_vel to the model's limits (Waffle 0.26 m/s, 1.82 rad/s;
                                        Gazebo does not)
    ~paused                  false      start with physics paused (as gazebo's `paused` arg)
    ~headless                false      true: never open a window; false: a window when $DISPLAY is set
    ~snapshot_path           "/tmp/tb3_sim.png"  where the ~snapshot service writes its PNG
    ~publish_static_tf       true       publish each robot's fixed joints (its URDF's) on /tf_static
    ~camera_width            model's    camera image width in pixels, 16..4096 (Waffle's R200 1920, Waffle Pi 640)
    ~camera_height           model's    camera image height in pixels, 16..4096 (1080, 480)
    ~camera_rate             model's    camera frames per second of sim time, (0, 1000] (30)
    ~odom_scale_error        0.0        odometry error, off by default (Gazebo's odometry is the true pose): the
                                        fraction by which /odom overstates distance (0.02: 2 %), in [-0.5, 0.5]
    ~odom_heading_drift      0.0        ... heading error added per metre travelled (rad/m; 1 deg/m = 0.01745)
    ~odom_heading_noise      0.0        ... seeded random heading walk (rad per sqrt(m), >= 0; seed: ~seed)
                                        (see core.odometry_error; set them before the node starts, e.g.
                                        `rosparam set /gazebo/odom_scale_error 0.02`)
    ~ground_truth_socket     ""         a Unix socket path: serve the robot's true motion and the world changes
                                        to one trusted client (the grader; see ground_truth); empty: off
The camera settings apply to every robot that has a camera; unset, each camera keeps its model's own.
"""

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from tb3_sim.core.errors import ConfigError
from tb3_sim.core.odometry_error import OdometryErrorModel
from tb3_sim.core.turtlebot3 import DEFAULT_MODEL, TURTLEBOT3_MODELS

DEFAULT_WORLD = "empty"
DEFAULT_SNAPSHOT_PATH = "/tmp/tb3_sim.png"
WORLD_FILE_SUFFIX = ".yaml"
GAZEBO_WORLD_SUFFIX = ".world"
# gazebo_ros's pub_clock_frequency default: see outputs.clock for why /clock is not sent after every step.
DEFAULT_CLOCK_RATE_HZ = 100.0
CAMERA_SIZE_RANGE_PX = (16, 4096)
MAX_CAMERA_RATE_HZ = 1000.0
MAX_ODOM_SCALE_ERROR = 0.5


@dataclass(frozen=True)
class SimConfig:
    """Validated node settings; `world_path` is resolved to an existing file."""

    world_path: Path
    spawn_robot: bool = True
    model: str = DEFAULT_MODEL.name
    x_pos: float = 0.0
    y_pos: float = 0.0
    yaw: float = 0.0
    robot_name: str = DEFAULT_MODEL.robot_name
    seed: int = 0
    real_time_factor: float = 1.0
    clock_rate: float = DEFAULT_CLOCK_RATE_HZ
    lidar_sees_low_objects: bool = False
    clamp_command: bool = False
    paused: bool = False
    headless: bool = False
    snapshot_path: str = DEFAULT_SNAPSHOT_PATH
    publish_static_tf: bool = True
    camera_width: Optional[int] = None
    camera_height: Optional[int] = None
    camera_rate: Optional[float] = None
    odometry_error: OdometryErrorModel = OdometryErrorModel()
    ground_truth_socket: str = ""


def resolve_world(value, worlds_dir):
    """Path of the world file named by `value`: a shipped world's name (looked up in `worlds_dir`), a Gazebo
    .world name or path as launch files pass to gazebo_ros (`worlds/empty.world`,
    `$(find turtlebot3_gazebo)/worlds/turtlebot3_house.world`: the shipped world of the same name; Gazebo's
    files themselves are not read), or a path to a world YAML file.

    Raises ConfigError naming the shipped worlds if there is no such file.
    """
    if not isinstance(value, str) or not value.strip():
        raise ConfigError(f"~world must be a world name or a file path, got {value!r}")
    worlds_dir = Path(worlds_dir)
    if value.endswith(GAZEBO_WORLD_SUFFIX):
        value = Path(value).stem
    is_path = value.endswith(WORLD_FILE_SUFFIX) or "/" in value
    path = Path(value).expanduser() if is_path else worlds_dir / (value + WORLD_FILE_SUFFIX)
    if not path.is_file():
        shipped = ", ".join(sorted(p.stem for p in worlds_dir.glob("*" + WORLD_FILE_SUFFIX)))
        raise ConfigError(f"~world: no world file {path} (shipped worlds: {shipped}; or give a path to a "
                          f"{WORLD_FILE_SUFFIX} file)")
    return path


def config_from_params(params, worlds_dir):
    """A SimConfig from the node's private parameters `params` (a dict, e.g. rospy.get_param("~")).

    Unknown keys are ignored (launch files may set more); bad types and values raise ConfigError.
    """
    reader = _ParamReader(params)
    model = reader.choice("model", DEFAULT_MODEL.name, TURTLEBOT3_MODELS)
    return SimConfig(
        world_path=resolve_world(params.get("world", DEFAULT_WORLD), worlds_dir),
        spawn_robot=reader.flag("spawn_robot", True),
        model=model,
        x_pos=reader.number("x_pos", 0.0),
        y_pos=reader.number("y_pos", 0.0),
        yaw=reader.number("yaw", 0.0),
        robot_name=reader.name("robot_name", TURTLEBOT3_MODELS[model].robot_name),
        seed=reader.integer("seed", 0),
        real_time_factor=reader.number("real_time_factor", 1.0, minimum=0.0),
        clock_rate=reader.number("clock_rate", DEFAULT_CLOCK_RATE_HZ, minimum=0.0),
        lidar_sees_low_objects=reader.flag("lidar_sees_low_objects", False),
        clamp_command=reader.flag("clamp_command", False),
        paused=reader.flag("paused", False),
        headless=reader.flag("headless", False),
        snapshot_path=reader.text("snapshot_path", DEFAULT_SNAPSHOT_PATH),
        publish_static_tf=reader.flag("publish_static_tf", True),
        camera_width=reader.optional(reader.integer, "camera_width", CAMERA_SIZE_RANGE_PX),
        camera_height=reader.optional(reader.integer, "camera_height", CAMERA_SIZE_RANGE_PX),
        camera_rate=reader.optional(reader.number, "camera_rate", minimum=0.0, maximum=MAX_CAMERA_RATE_HZ,
                                    exclusive_minimum=True),
        odometry_error=OdometryErrorModel(
            scale_error=reader.number("odom_scale_error", 0.0, minimum=-MAX_ODOM_SCALE_ERROR,
                                      maximum=MAX_ODOM_SCALE_ERROR),
            heading_drift=reader.number("odom_heading_drift", 0.0),
            heading_noise=reader.number("odom_heading_noise", 0.0, minimum=0.0)),
        ground_truth_socket=reader.optional(reader.text, "ground_truth_socket") or "",
    )


class _ParamReader:
    def __init__(self, params):
        self._params = params

    def number(self, key, default, minimum=None, maximum=None, exclusive_minimum=False):
        value = self._params.get(key, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise ConfigError(f"~{key} must be a finite number, got {value!r}")
        if minimum is not None and (value <= minimum if exclusive_minimum else value < minimum):
            raise ConfigError(f"~{key} must be {'>' if exclusive_minimum else '>='} {minimum}, got {value!r}")
        if maximum is not None and value > maximum:
            raise ConfigError(f"~{key} must be <= {maximum}, got {value!r}")
        return float(value)

    def integer(self, key, default, bounds=None):
        value = self._params.get(key, default)
        if isinstance(value, bool) or not isinstance(value, int):
            raise ConfigError(f"~{key} must be an integer, got {value!r}")
        if bounds is not None and not bounds[0] <= value <= bounds[1]:
            raise ConfigError(f"~{key} must be in [{bounds[0]}, {bounds[1]}], got {value!r}")
        return value

    def optional(self, read, key, *args, **kwargs):
        """`read(key, default, ...)` if `key` is given, else None (the default is then someone else's)."""
        return read(key, None, *args, **kwargs) if key in self._params else None

    def choice(self, key, default, choices):
        value = self._params.get(key, default)
        if not isinstance(value, str) or value not in choices:
            raise ConfigError(f"~{key} must be one of {', '.join(choices)}, got {value!r}")
        return value

    def flag(self, key, default):
        value = self._params.get(key, default)
        if value is not default and not isinstance(value, bool):
            raise ConfigError(f"~{key} must be true or false, got {value!r}")
        return value

    def name(self, key, default):
        value = self._params.get(key, default)
        if not isinstance(value, str) or not value or any(c.isspace() for c in value):
            raise ConfigError(f"~{key} must be a non-empty string without spaces, got {value!r}")
        return value

    def text(self, key, default):
        value = self._params.get(key, default)
        if not isinstance(value, str) or not value.strip():
            raise ConfigError(f"~{key} must be a non-empty string, got {value!r}")
        return value
