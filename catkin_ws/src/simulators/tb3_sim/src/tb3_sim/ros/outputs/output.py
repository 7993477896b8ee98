"""The seam every periodic output of the simulator plugs into (flatland's ModelPlugin with its update timer).

An output is one small object: the rate it runs at in simulated time, whether it is lazy (read only while
someone subscribes to one of its topics, as Gazebo's sensors are), `read(world, now_s, wanted)` giving a plain
reading, and its topics, each with the message class and the conversion from that reading to a message.
`OutputPublisher` loops over the registered outputs after every physics step; adding a sensor is one module
with an `Output` subclass, one line in `registry`, and its tests.
"""

from typing import Any, Callable, NamedTuple

from tb3_sim.core.schedule import PeriodicSchedule


class Topic(NamedTuple):
    """A topic an output publishes: `name` as rospy resolves it ("/clock", "odom" in the node's namespace,
    "~model_states" under /gazebo), `message_class`, `convert(reading) -> message`, `latch` (published once
    at start and kept for late subscribers) and `queued` (big messages such as images: sent by a writer thread
    that keeps only the newest, so a slow subscriber drops frames instead of holding up the physics loop; the
    other topics are written synchronously by the loop, which is faster for small messages)."""

    name: str
    message_class: type
    convert: Callable[[Any], Any]
    latch: bool = False
    queued: bool = False


class Output:
    """Base class of the periodic outputs. Subclasses set `rate_hz`, `lazy` and `frame_ids` as class
    attributes, build `self.topics` (a tuple of Topic) and implement `read`.

    `rate_hz` is in simulated time; 0 means every physics step; `self.schedule` (a PeriodicSchedule) says when a
    reading is due. `frame_ids` are the frames its messages are stamped in (headers, TF frames, markers).
    """

    rate_hz = 0.0
    lazy = True
    frame_ids = ()

    def __init__(self):
        self.topics = ()
        self.schedule = PeriodicSchedule(self.rate_hz)

    def read(self, world, now_s, wanted):
        """The reading at `now_s` (world locked); `wanted` is the set of this output's topic names that have
        subscribers, so a reading can skip what nobody will receive."""
        raise NotImplementedError

    def reset(self, now_s):
        """Start afresh at `now_s` after the clock jumped (reset_simulation): schedule, history, noise streams."""
        self.schedule.reset(now_s)

    def forget_motion(self):
        """The robot or a model jumped (reset_world, a teleport): drop history that would turn the jump into a
        spike. Most outputs keep none."""
