"""The simulator's periodic outputs, in publishing order: one line per output.

World outputs run once per simulator; robot outputs once per robot, named by its RobotNaming. /clock comes first,
so a subscriber on /use_sim_time has the new time before any message stamped with it.
"""

from tb3_sim.core.lidar import Lidar
from tb3_sim.core.odometry_error import DriftingOdometry
from tb3_sim.ros.outputs.camera import CameraOutput
from tb3_sim.ros.outputs.clock import ClockOutput
from tb3_sim.ros.outputs.imu import ImuOutput
from tb3_sim.ros.outputs.model_states import ModelStatesOutput
from tb3_sim.ros.outputs.odometry import OdometryOutput
from tb3_sim.ros.outputs.scan import ScanOutput
from tb3_sim.ros.outputs.scene_primitives import ScenePrimitivesOutput
from tb3_sim.ros.outputs.world_markers import WorldMarkersOutput


def world_outputs(config):
    """A fresh instance of every output the world has once, set up from `config` (a ros.config.SimConfig)."""
    return [
        ClockOutput(config.clock_rate),
        ModelStatesOutput(),
        WorldMarkersOutput(),
        ScenePrimitivesOutput(),
    ]


def robot_outputs(config, robot, naming, index, floor_textures=None):
    """A fresh instance of every output of `robot` (a core.robot.Robot), the `index`-th robot (its LiDAR noise
    stream, and its odometry error's, is the config's seed + index), set up from `config` (a ros.config.SimConfig);
    its camera takes the floor's texture from `floor_textures` (camera.FloorTextures, shared by the robots)."""
    drift = DriftingOdometry(config.odometry_error, config.seed + index) if config.odometry_error.enabled else None
    outputs = [
        OdometryOutput(robot, naming, drift),
        ScanOutput(robot, naming, Lidar(config.seed + index, sees_low_objects=config.lidar_sees_low_objects)),
        ImuOutput(robot, naming),
    ]
    camera = robot.model.camera
    if camera is not None:
        outputs.append(CameraOutput(robot, naming, camera, config.camera_width, config.camera_height,
                                    config.camera_rate, floor_textures))
    return outputs
