"""The simulator's periodic outputs (clock, odometry, scan, IMU, model states, world markers,
camera) behind one seam."""

from tb3_sim.ros.outputs.output import Output, Topic
from tb3_sim.ros.outputs.publisher import OutputPublisher
from tb3_sim.ros.outputs.registry import robot_outputs, world_outputs

__all__ = ["Output", "OutputPublisher", "Topic", "robot_outputs", "world_outputs"]
