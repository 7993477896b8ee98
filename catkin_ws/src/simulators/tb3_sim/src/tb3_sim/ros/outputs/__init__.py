"""The simulator's periodic outputs (clock, odometry, scan, IMU, model states, world markers,
camera) behind one seam."""

from tb3_sim.ros.outputs.output import Output, Topic
from tb3_sim.ros.outputs.publisher import OutputPublisher
from tb3_sim.ros.outputs.registry import registered_outputs

__all__ = ["Output", "OutputPublisher", "Topic", "registered_outputs"]
