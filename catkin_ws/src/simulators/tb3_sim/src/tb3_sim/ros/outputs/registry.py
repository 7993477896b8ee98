"""The simulator's periodic outputs, in publishing order: one line per output.

/clock comes first, so a subscriber on /use_sim_time has the new time before any message stamped with it.
"""

from tb3_sim.core.lidar import Lidar
from tb3_sim.ros.outputs.camera import CameraOutput
from tb3_sim.ros.outputs.clock import ClockOutput
from tb3_sim.ros.outputs.imu import ImuOutput
from tb3_sim.ros.outputs.model_states import ModelStatesOutput
from tb3_sim.ros.outputs.odometry import OdometryOutput
from tb3_sim.ros.outputs.scan import ScanOutput
from tb3_sim.ros.outputs.world_markers import WorldMarkersOutput


def registered_outputs(config):
    """A fresh instance of every output, set up from `config` (a ros.config.SimConfig)."""
    return [
        ClockOutput(),
        OdometryOutput(),
        ScanOutput(Lidar(config.seed, sees_low_objects=config.lidar_sees_low_objects)),
        ImuOutput(),
        ModelStatesOutput(),
        WorldMarkersOutput(),
        CameraOutput(config.camera_width, config.camera_height, config.camera_rate),
    ]
