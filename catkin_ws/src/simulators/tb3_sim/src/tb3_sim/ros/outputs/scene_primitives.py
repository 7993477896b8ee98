"""The world's fixed scene as drawing primitives for pages and tools: the floor layer with its markings and the
static shapes, as JSON (core.primitives.to_data, one object per primitive, in painting order) in a std_msgs/String
on `~scene_primitives` (/gazebo/scene_primitives), latched. It is the same description the simulator's own
views and camera draw, so a browser view (lab_web) draws the floor markings without knowing any kind of marking.
Not a Gazebo topic. Static shapes without a colour carry "rgb": null (each view draws them in its own wall colour).
The text is built once: the fixed scene never changes while the simulator runs.
"""
import json
from typing import NamedTuple

from std_msgs.msg import String

from tb3_sim.core.primitives import to_data
from tb3_sim.core.scene_primitives import scene_primitives
from tb3_sim.ros.outputs.output import Output, Topic

# Latched, so a late subscriber gets it at once; republished this often (sim time) while someone listens.
SCENE_RATE_HZ = 0.2


class SceneReading(NamedTuple):
    text: str


class ScenePrimitivesOutput(Output):
    rate_hz = SCENE_RATE_HZ
    lazy = True

    def __init__(self):
        super().__init__()
        self.topics = (Topic("~scene_primitives", String, lambda reading: String(data=reading.text), latch=True),)
        self._text = None

    def read(self, world, now_s, wanted):
        if self._text is None:
            description = world.description
            primitives = scene_primitives(description.floor, description.static_shapes)
            self._text = json.dumps([to_data(primitive) for primitive in primitives], separators=(",", ":"))
        return SceneReading(self._text)
