"""Velocity commands out of a node, with a last command that stays the last one.

When a node shuts down, its zero Twist must both arrive and stay last:
- rospy hands a published message to a sender thread per subscriber and returns. The node then unregisters
  from the master, the master tells each subscriber the publisher is gone, and the subscriber closes the
  connection, dropping a message it has not handled yet. So a zero Twist followed at once by rospy's teardown
  can be lost, and the robot drives on with the command it had. Waiting FLUSH_WAIT_S before the teardown
  gives it time to leave and be handled.
- rospy runs shutdown hooks while the node's other threads still run: a service thread in the middle of a
  request would otherwise publish its next command after the zero Twist, and the robot would drive on.
"""
import threading
import time

import rospy
from geometry_msgs.msg import Twist

FLUSH_WAIT_S = 0.3
"""Wall time between the last command and the node's teardown. Wall clock, not rospy time: under
/use_sim_time the simulator (and /clock) may already be gone."""


def twist(linear, angular):
    """A Twist with only linear.x (m/s) and angular.z (rad/s) set."""
    message = Twist()
    message.linear.x, message.angular.z = linear, angular
    return message


class CommandPublisher:
    """geometry_msgs/Twist commands on `topic`, until `stop_for_good()` publishes the last one."""

    def __init__(self, topic, queue_size):
        self._publisher = rospy.Publisher(topic, Twist, queue_size=queue_size)
        self._lock = threading.Lock()
        self._stopped = False

    def publish(self, linear, angular):
        """Publish one command (m/s, rad/s) unless the robot was stopped for good; returns whether it was."""
        with self._lock:
            if not self._stopped:
                self._publisher.publish(twist(linear, angular))
            return not self._stopped

    def stop_for_good(self):
        """Publish a zero Twist as the last command and wait FLUSH_WAIT_S for it to be delivered (when anyone
        subscribes); only the first call does anything, so a node's loop and its shutdown hook may both call it."""
        with self._lock:
            if self._stopped:
                return
            self._stopped = True
            self._publisher.publish(twist(0.0, 0.0))
            if self._publisher.get_num_connections():
                time.sleep(FLUSH_WAIT_S)
