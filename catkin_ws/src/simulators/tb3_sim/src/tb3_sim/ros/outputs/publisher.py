"""Publishes the registered outputs after each physics step: the loop the seam promises (no rospy here).

Publishers are made by an injected `make_publisher(topic)` (the node passes rospy's; tests pass fakes with
`publish(msg)` and `get_num_connections()`).
"""

import math

from tb3_sim.core.schedule import TIME_EPSILON_S


class OutputPublisher:
    """The registered outputs (in publishing order) and one publisher per topic."""

    def __init__(self, outputs, make_publisher):
        self._make_publisher = make_publisher
        self.outputs = ()
        self.publishers = {}
        self.add(outputs)

    def add(self, outputs, now_s=0.0):
        """Publish `outputs` too (a robot joined at sim time `now_s`); topics of the same name share a publisher
        (every robot's odometry goes out on the one /tf)."""
        for output in outputs:
            output.reset(now_s)
            for topic in output.topics:
                if topic.name not in self.publishers:
                    self.publishers[topic.name] = self._make_publisher(topic)
        self.outputs += tuple(outputs)
        # Per output, its (topic, publisher) pairs, split into outputs that run every physics step (/clock) and
        # periodic ones: collect() runs after every step, so it looks nothing up by name and asks the periodic
        # outputs only when the earliest of them is due.
        routes = [(output, tuple((topic, self.publishers[topic.name]) for topic in output.topics))
                  for output in self.outputs]
        self._routes = tuple(routes)
        self._every_step = tuple(route for route in routes if route[0].schedule.period_s == 0.0)
        self._periodic = tuple(route for route in routes if route[0].schedule.period_s > 0.0)
        self._next_due_s = self._earliest_due()

    def _earliest_due(self):
        return min((output.schedule.next_due_s for output, _ in self._periodic), default=math.inf)

    def output(self, kind):
        """The registered output of class `kind` (e.g. ScanOutput), or None."""
        return next((output for output in self.outputs if isinstance(output, kind)), None)

    def latched(self, world):
        """(publisher, message) pairs for every latched topic, read now regardless of subscribers (at start)."""
        pairs = []
        for output, routes in self._routes:
            latched = [(topic, publisher) for topic, publisher in routes if topic.latch]
            if latched:
                reading = output.read(world, world.time_s, {topic.name for topic, _ in latched})
                pairs.extend((publisher, topic.convert(reading)) for topic, publisher in latched)
        return pairs

    def collect(self, world):
        """(publisher, message) pairs due now that the world has stepped to `world.time_s`.

        An output due now is read if it is not lazy or one of its topics has subscribers; a message is built
        only for a topic with subscribers.
        """
        now_s = world.time_s
        due = []
        for route in self._every_step:
            self._publish_due(world, now_s, route, due)
        reached_s = now_s + TIME_EPSILON_S
        if reached_s >= self._next_due_s:
            # One pass both publishes what is due and finds the next deadline; a deadline not yet reached is
            # compared here rather than asked of its schedule (a call per output per tick).
            next_due_s = math.inf
            for route in self._periodic:
                schedule = route[0].schedule
                if reached_s >= schedule.next_due_s and schedule.due(now_s):
                    self._publish_due(world, now_s, route, due)
                if schedule.next_due_s < next_due_s:
                    next_due_s = schedule.next_due_s
            self._next_due_s = next_due_s
        return due

    @staticmethod
    def _publish_due(world, now_s, route, due):
        """Append the (publisher, message) pairs of the output in `route`, due now, to `due`."""
        output, routes = route
        wanted = [(topic, publisher) for topic, publisher in routes if publisher.get_num_connections()]
        if output.lazy and not wanted:
            return
        reading = output.read(world, now_s, {topic.name for topic, _ in wanted})
        due.extend((publisher, topic.convert(reading)) for topic, publisher in wanted)

    def reset(self, now_s):
        """Every output starts afresh at `now_s` (after reset_simulation rewound the clock)."""
        for output in self.outputs:
            output.reset(now_s)
        self._next_due_s = self._earliest_due()

    def forget_motion(self):
        """The robot or a model jumped (reset_world, a teleport)."""
        for output in self.outputs:
            output.forget_motion()
