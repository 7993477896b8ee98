"""Re-register a running rospy node with a restarted master.

ROS 1 nodes register their publishers, subscribers and services once, at start-up. When roscore is restarted
(Ctrl-C by mistake, a crash) the new master knows none of them: connections that already exist keep working,
but nothing new can find them (`rosservice call` says the service is not available). This watchdog reads the
master's run id (/run_id, new at every roscore start) once a second; when it differs from the run id of the
master the node registered with, it registers everything the node offers again, exactly as rospy does at
start-up, hands the subscribers the master's current publisher lists and logs one warning. `on_reregistered`
runs afterwards (e.g. to restore parameters the node owns, like /use_sim_time).

A node started before its master is up registers through rospy itself (rospy prints "Unable to register with
master node ..." meanwhile and keeps trying): the watchdog adopts that first master silently. A master started
without roscore or roslaunch (a bare rosmaster) has no /run_id and is not watched.

Wall-clock timing on purpose: under /use_sim_time a dead master means no /clock either.
"""
import threading
import time
import xmlrpc.client

import rosgraph
import rospy
from rospy.impl.registration import get_service_manager, get_topic_manager

from master_reconnect.runs import MasterRuns

CHECK_PERIOD_WALL_S = 1.0
RUN_ID_PARAM = "/run_id"
MASTER_ERRORS = (OSError, rosgraph.MasterError, xmlrpc.client.Error)


class MasterWatchdog:
    """Checks the master every CHECK_PERIOD_WALL_S and re-registers this node with a restarted one."""

    def __init__(self, on_reregistered=None):
        self.on_reregistered = on_reregistered
        self.reregistrations = 0
        self._runs = MasterRuns()
        self._thread = threading.Thread(target=self._run, name="master_watchdog", daemon=True)

    def start(self):
        """Remember the run id of the master rospy registers with now (when it is up), start checking."""
        try:
            self._runs.registered(self._run_id(self._master()))
        except MASTER_ERRORS as error:
            rospy.logdebug("master watchdog: no master yet (%s)", error)
        self._thread.start()
        return self

    def _run(self):
        while not rospy.is_shutdown():
            time.sleep(CHECK_PERIOD_WALL_S)
            try:
                self._check()
            except MASTER_ERRORS as error:
                rospy.logdebug("master watchdog: master not reachable (%s)", error)

    def _check(self):
        master = self._master()
        run_id = self._run_id(master)
        if self._runs.restarted(run_id, self._master_knows_us(master)):
            self._register_everything(master)
            self._runs.registered(run_id)
            self.reregistrations += 1
            rospy.logwarn("%s re-registered with a restarted ROS master at %s", rospy.get_caller_id(),
                          rosgraph.get_master_uri())
            if self.on_reregistered:
                self.on_reregistered()

    @staticmethod
    def _master():
        return rosgraph.Master(rospy.get_caller_id())

    @staticmethod
    def _run_id(master):
        return master.getParam(RUN_ID_PARAM) if master.hasParam(RUN_ID_PARAM) else None

    @staticmethod
    def _master_knows_us(master):
        try:
            return master.lookupNode(rospy.get_caller_id()) == rospy.get_node_uri()
        except rosgraph.MasterError:
            return False   # "unknown node"

    @staticmethod
    def _register_everything(master):
        node_uri = rospy.get_node_uri()
        topics, services = get_topic_manager(), get_service_manager()
        for name, data_type in topics.get_publications():
            master.registerPublisher(name, data_type, node_uri)
        for name, data_type in topics.get_subscriptions():
            publishers = master.registerSubscriber(name, data_type, node_uri)
            xmlrpc.client.ServerProxy(node_uri).publisherUpdate("/master", name, publishers)
        for name, service_uri in services.get_services():
            master.registerService(name, service_uri, node_uri)


def keep_registered(on_reregistered=None):
    """Start the watchdog for this node (call after rospy.init_node); returns it."""
    return MasterWatchdog(on_reregistered).start()
