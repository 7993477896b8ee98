"""Calling services with fuzzed requests and checking the graph survived, for tests/integration/*/test_fuzz_*.

`ServiceFuzzer` makes one call per request in a thread of the test process (rospy.ServiceProxy needs no
node) and fails the test when the call does not come back within its budget, when the node died (a transport
error), or when the node's handler raised something it did not mean to (rospy's "error processing request",
which also prints a traceback in the node's terminal). A refusal the node chose — a ServiceException with
text, or a failure response — is a normal outcome, returned for the test to judge against the service's
documentation. `GraphWatch` checks afterwards that every node still runs as the same process, still offers
its services, and printed no traceback.
"""
import os
import threading
from typing import NamedTuple, Optional

import rosgraph
import rospy
from hypothesis import HealthCheck, settings

from roslab.graph import node_pid

MIN_REQUESTS = 200
"""Requests each service must receive from one fuzz test."""

REPLY_BUDGET_S = 2.0
"""Wall seconds a refusal or an instant reply may take while two cores are shared by the whole graph (the
Week 4 tests ask for 1 s on an idle machine). A request that legitimately moves the robot gets its motion
time added: the fuzz modules run the simulator at real_time_factor >= 1, so sim seconds <= wall seconds."""

FUZZ_SETTINGS = settings(max_examples=MIN_REQUESTS, deadline=None, derandomize=True, database=None,
                         suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                HealthCheck.large_base_example])
"""Reproducible in CI (derandomize: the same examples on every run, nothing stored between runs); no
per-example deadline because some valid requests drive the robot for a while."""

_NODE_GONE = ("transport error", "unable to connect", "unavailable", "Connection refused")
_UNHANDLED = "error processing request"


class Reply(NamedTuple):
    """What one call returned: the response, or the text of the ServiceException the node chose to raise."""

    response: Optional[object]
    error: Optional[str]


class ServiceFuzzer:
    """Calls one service, counting requests; see the module docstring for what fails the test."""

    def __init__(self, name, service_class):
        self.name = name
        self.calls = 0
        self._proxy = rospy.ServiceProxy(name, service_class)

    def call(self, *args, motion_s=0.0, **fields):
        """Send one request (positional fields or keywords); `motion_s` is the sim time it may legitimately
        take on top of REPLY_BUDGET_S. Returns a Reply."""
        self.calls += 1
        outcome = {}

        def run():
            try:
                outcome["reply"] = Reply(self._proxy(*args, **fields), None)
            except rospy.ServiceException as error:
                outcome["reply"] = Reply(None, str(error))
            except Exception as error:  # handed to the test thread, which fails with it
                outcome["raised"] = error

        worker = threading.Thread(target=run, daemon=True)
        worker.start()
        budget_s = REPLY_BUDGET_S + motion_s
        worker.join(budget_s)
        request = "{} {} {}".format(self.name, _shorten(args), _shorten(fields))
        assert not worker.is_alive(), "no reply within {:.1f} s: {}".format(budget_s, request)
        if "raised" in outcome:
            raise outcome["raised"]
        reply = outcome["reply"]
        if reply.error is not None:
            assert not any(text in reply.error for text in _NODE_GONE), \
                "the node went away: {} -> {}".format(request, reply.error)
            assert _UNHANDLED not in reply.error, \
                "unhandled exception in the node: {} -> {}".format(request, reply.error[:500])
        return reply


def _shorten(value, limit=300):
    text = repr(value)
    return text if len(text) <= limit else text[:limit] + "...({} chars)".format(len(text))


class GraphWatch:
    """The nodes and services a fuzz test must leave alive, with the node processes' PIDs taken at the start
    (a respawned node would have a new PID) and the processes whose output must stay free of tracebacks."""

    def __init__(self, master_uri, nodes, services, processes):
        self._master_uri = master_uri
        self._pids = {node: node_pid(master_uri, node) for node in nodes}
        self._services = list(services)
        self._processes = list(processes)

    def assert_alive(self):
        master = rosgraph.Master("/roslab_test", master_uri=self._master_uri)
        for node, pid in self._pids.items():
            assert _process_exists(pid), "node {} (pid {}) died".format(node, pid)
            assert node_pid(self._master_uri, node) == pid, "node {} was restarted".format(node)
        for service in self._services:
            assert master.lookupService(service), "service {} is gone".format(service)
        for process in self._processes:
            output = process.output()
            assert "Traceback" not in output, "traceback in {}:\n{}".format(
                process.command, output[max(0, output.index("Traceback") - 500):][:3000])


def _process_exists(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True
