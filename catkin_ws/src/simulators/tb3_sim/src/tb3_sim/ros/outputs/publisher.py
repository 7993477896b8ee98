"""Publishes the registered outputs after each physics step: the loop the seam promises (no rospy here).

Publishers are made by an injected `make_publisher(topic)` (the node passes rospy's; tests pass fakes with
`publish(msg)` and `get_num_connections()`).
"""


class OutputPublisher:
    """The registered outputs (in publishing order) and one publisher per topic."""

    def __init__(self, outputs, make_publisher):
        self.outputs = tuple(outputs)
        self.publishers = {topic.name: make_publisher(topic) for output in self.outputs for topic in output.topics}

    def output(self, kind):
        """The registered output of class `kind` (e.g. ScanOutput), or None."""
        return next((output for output in self.outputs if isinstance(output, kind)), None)

    def latched(self, world):
        """(publisher, message) pairs for every latched topic, read now regardless of subscribers (at start)."""
        pairs = []
        for output in self.outputs:
            latched = [topic for topic in output.topics if topic.latch]
            if latched:
                reading = output.read(world, world.time_s, {topic.name for topic in latched})
                pairs.extend((self.publishers[topic.name], topic.convert(reading)) for topic in latched)
        return pairs

    def collect(self, world):
        """(publisher, message) pairs due now that the world has stepped to `world.time_s`.

        An output due now is read if it is not lazy or one of its topics has subscribers; a message is built
        only for a topic with subscribers.
        """
        now_s = world.time_s
        due = []
        for output in self.outputs:
            if not output.due(now_s):
                continue
            wanted = [topic for topic in output.topics if self.publishers[topic.name].get_num_connections()]
            if output.lazy and not wanted:
                continue
            reading = output.read(world, now_s, {topic.name for topic in wanted})
            due.extend((self.publishers[topic.name], topic.convert(reading)) for topic in wanted)
        return due

    def reset(self, now_s):
        """Every output starts afresh at `now_s` (after reset_simulation rewound the clock)."""
        for output in self.outputs:
            output.reset(now_s)

    def forget_motion(self):
        """The robot or a model jumped (reset_world, a teleport)."""
        for output in self.outputs:
            output.forget_motion()
