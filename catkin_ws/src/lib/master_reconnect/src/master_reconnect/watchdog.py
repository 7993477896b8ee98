"""Re-register a running rospy node with a restarted master.

ROS 1 nodes register their publishers, subscribers and services once, at start-up. When roscore is restarted
(Ctrl-C by mistake, a crash) the new master knows none of them: connections that already exist keep working,
but nothing new can find them (`rosservice call` says the service is not available). This watchdog asks the
master once a second whether it still knows this node; when it does not, it registers everything the node
offers again, exactly as rospy does at start-up, and hands the subscribers the master's current publisher
lists. `on_reregistered` runs afterwards (e.g. to restore parameters the node owns, like /use_sim_time).

Wall-clock timing on purpose: under /use_sim_time a dead master means no /clock either.
"""
import threading
import time
import xmlrpc.client

import rosgraph
import rospy
from rospy.impl.registration import get_service_manager, get_topic_manager

CHECK_PERIOD_WALL_S = 1.0


class MasterWatchdog:
    """Checks the master every CHECK_PERIOD_WALL_S and re-registers this node when it has been forgotten."""

    def __init__(self, on_reregistered=None):
        self.on_reregistered = on_reregistered
        self.reregistrations = 0
        self._thread = threading.Thread(target=self._run, name="master_watchdog", daemon=True)

    def start(self):
        self._thread.start()
        return self

    def _run(self):
        while not rospy.is_shutdown():
            time.sleep(CHECK_PERIOD_WALL_S)
            try:
                if not self._master_knows_us():
                    self._register_everything()
            except (OSError, rosgraph.MasterError, xmlrpc.client.Error) as error:
                rospy.logdebug("master watchdog: master not reachable yet (%s)", error)

    @staticmethod
    def _master():
        return rosgraph.Master(rospy.get_caller_id())

    def _master_knows_us(self):
        try:
            return self._master().lookupNode(rospy.get_caller_id()) == rospy.get_node_uri()
        except rosgraph.MasterError:
            return False   # "unknown node": a fresh master

    def _register_everything(self):
        master, caller_id, node_uri = self._master(), rospy.get_caller_id(), rospy.get_node_uri()
        topics, services = get_topic_manager(), get_service_manager()
        for name, data_type in topics.get_publications():
            master.registerPublisher(name, data_type, node_uri)
        for name, data_type in topics.get_subscriptions():
            publishers = master.registerSubscriber(name, data_type, node_uri)
            xmlrpc.client.ServerProxy(node_uri).publisherUpdate("/master", name, publishers)
        for name, service_uri in services.get_services():
            master.registerService(name, service_uri, node_uri)
        self.reregistrations += 1
        rospy.logwarn("%s re-registered with a restarted ROS master at %s", caller_id, rosgraph.get_master_uri())
        if self.on_reregistered:
            self.on_reregistered()


def keep_registered(on_reregistered=None):
    """Start the watchdog for this node (call after rospy.init_node); returns it."""
    return MasterWatchdog(on_reregistered).start()
