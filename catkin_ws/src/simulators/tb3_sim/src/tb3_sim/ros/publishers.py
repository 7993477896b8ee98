"""The rospy publishers of the simulator's outputs: how each topic is written, and a subscriber count that costs
nothing to ask.

The output loop asks every due topic for its subscriber count after each physics step (hundreds of thousands of
times a minute when unpaced). rospy's get_num_connections takes a lock each time; here the count is kept up to
date by rospy's own connect and disconnect callbacks (SubscribeListener) and read as a plain attribute.
"""

import warnings

import rospy


class CountedPublisher(rospy.SubscribeListener):
    """A rospy publisher (`publish(msg)`) whose `get_num_connections()` is the count rospy last reported."""

    def __init__(self, name, message_class, **options):
        self._connections = 0
        self._publisher = rospy.Publisher(name, message_class, subscriber_listener=self, **options)
        self.publish = self._publisher.publish

    def get_num_connections(self):
        return self._connections

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        self._connections = self._publisher.get_num_connections()

    def peer_unsubscribe(self, topic_name, num_peers):
        self._connections = num_peers


def output_publisher(topic):
    """The publisher of an output's `topic` (an outputs.Topic).

    Latched and queued topics keep one message for rospy's writer thread per subscriber. The others are written
    synchronously, in the calling thread (rospy's queue_size=None), on purpose: the thread hand-off costs more
    than a whole physics step, and publishing from the loop thread makes the simulator 3-4x faster. The catch: a
    subscriber process that stops reading altogether (suspended with Ctrl-Z) holds the loop up once its TCP
    buffer is full. rospy's SyntaxWarning about the missing queue size is silenced because the choice is
    deliberate.
    """
    if topic.latch or topic.queued:
        return CountedPublisher(topic.name, topic.message_class, queue_size=1, latch=topic.latch)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SyntaxWarning)
        return CountedPublisher(topic.name, topic.message_class, queue_size=None)
