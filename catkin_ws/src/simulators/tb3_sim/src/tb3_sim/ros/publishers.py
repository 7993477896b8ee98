"""The rospy publishers of the simulator's outputs: how each topic is written, and a subscriber count that costs
nothing to ask.

The output loop asks every due topic for its subscriber count after each physics step (hundreds of thousands of
times a minute when unpaced). rospy's get_num_connections takes a lock each time; here the count is kept up to
date by rospy's own connect and disconnect callbacks (SubscribeListener) and read as a plain attribute.
"""

import select
import socket
import threading
import warnings

import rospy

from stop_request.closed_topic import shutting_down


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


class QueuedPublisher(CountedPublisher):
    """A CountedPublisher whose `publish(msg)` hands the message to a writer thread of its own and returns: the
    thread serialises and publishes the newest message it was given (one handed over while it is busy replaces
    the waiting one). The physics loop never waits for a big message: a 1920x1080 frame's JPEG (20-40 ms, encoded
    as the compressed image is serialised) took the loop past the pacer's 50 ms lag and cost the simulator real
    time for every frame."""

    def __init__(self, name, message_class, **options):
        super().__init__(name, message_class, **options)
        self._waiting = None
        self._ready = threading.Condition()
        threading.Thread(target=self._write, name="publish " + name, daemon=True).start()
        self.publish = self._hand_over

    def get_num_connections(self):
        if self._connections:
            self._close_departed()
        return self._connections

    def _close_departed(self):
        """Close the connections whose subscriber has gone. A TCPROS subscriber sends nothing after its handshake,
        so its socket reads as ready only once the subscriber has closed it; rospy itself notices only when a
        later write fails, one or two frames on, each rendered for nobody (lab_web's camera snapshots, which
        subscribe, take one image and leave, cost tb3_sim three or four 1920x1080 frames each)."""
        transports = [getattr(connection, "_connection", connection)   # rospy's QueuedConnection wraps it
                      for connection in list(self._publisher.impl.connections)]
        sockets = {transport.socket: transport for transport in transports
                   if getattr(transport, "socket", None) is not None}
        try:
            departed = select.select(list(sockets), [], [], 0)[0]
        except (OSError, ValueError):
            return   # a socket closed meanwhile: rospy's own clean-up has it
        for sock in departed:
            if _at_end(sock):
                sockets[sock].close()   # rospy's clean-up callback removes the connection: peer_unsubscribe

    def _hand_over(self, message):
        with self._ready:
            self._waiting = message
            self._ready.notify()

    def _write(self):
        while not rospy.is_shutdown():
            with self._ready:
                while self._waiting is None:
                    self._ready.wait()
                message, self._waiting = self._waiting, None
            try:
                self._publisher.publish(message)
            except (rospy.ROSException, rospy.ROSSerializationException) as error:
                if shutting_down():
                    return   # Ctrl-C closed the publisher
                rospy.logerr("tb3_sim could not publish %s: %s", self._publisher.resolved_name, error)


def _at_end(sock):
    """Whether a socket select() found readable was closed by its peer (a peek reads nothing or fails), rather
    than holding bytes a subscriber sent after all."""
    try:
        return sock.recv(1, socket.MSG_PEEK | socket.MSG_DONTWAIT) == b""
    except BlockingIOError:
        return False
    except OSError:
        return True


def output_publisher(topic):
    """The publisher of an output's `topic` (an outputs.Topic).

    Latched and queued topics keep one message for rospy's writer thread per subscriber; queued ones (images) are
    also serialised in a thread of their own (QueuedPublisher). The others are written
    synchronously, in the calling thread (rospy's queue_size=None), on purpose: the thread hand-off costs more
    than a whole physics step, and publishing from the loop thread makes the simulator 3-4x faster. The catch: a
    subscriber process that stops reading altogether (suspended with Ctrl-Z) holds the loop up once its TCP
    buffer is full. rospy's SyntaxWarning about the missing queue size is silenced because the choice is
    deliberate.
    """
    if topic.queued:
        return QueuedPublisher(topic.name, topic.message_class, queue_size=1, latch=topic.latch)
    if topic.latch:
        return CountedPublisher(topic.name, topic.message_class, queue_size=1, latch=topic.latch)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SyntaxWarning)
        return CountedPublisher(topic.name, topic.message_class, queue_size=None)
