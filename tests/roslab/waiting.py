"""Waiting with timeouts on the graph of a given master, without being a node (plain master API calls)."""
import socket
import time
import urllib.parse

import rosgraph


class WaitTimeout(AssertionError):
    """The condition did not become true in time; the message says what was awaited."""


def wait_until(predicate, timeout_s, what, interval_s=0.05):
    """Poll `predicate()` until it returns a truthy value (returned) or `timeout_s` wall seconds pass."""
    deadline = time.monotonic() + timeout_s
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise WaitTimeout("timed out after {:.1f} s waiting for {}".format(timeout_s, what))
        time.sleep(interval_s)


def _master(master_uri):
    return rosgraph.Master("/roslab_test", master_uri=master_uri)


def service_uri(master_uri, name):
    """The rosrpc URI of service `name` as the master knows it, or None while it is not registered."""
    try:
        return _master(master_uri).lookupService(name)
    except (rosgraph.MasterError, OSError):
        return None


def wait_for_service(master_uri, name, timeout_s=20.0):
    """Wait until `name` is registered with the master; returns its rosrpc URI."""
    return wait_until(lambda: service_uri(master_uri, name), timeout_s, "service " + name)


def wait_for_service_gone(master_uri, name, timeout_s=20.0, killed_ok=False):
    """Wait until `name` is no longer registered (its server has left the master); with `killed_ok`, also once
    the registered server no longer accepts connections: a node roslaunch had to SIGKILL never unregisters, and
    its registration outlives it until another node registers the name."""
    def gone():
        uri = service_uri(master_uri, name)
        return uri is None or (killed_ok and not _accepts_connections(uri))
    wait_until(gone, timeout_s, f"service {name} to leave the master")


def _accepts_connections(rosrpc_uri):
    host, port = urllib.parse.urlparse(rosrpc_uri).netloc.rsplit(":", 1)
    try:
        socket.create_connection((host, int(port)), timeout=1.0).close()
        return True
    except OSError:
        return False


def wait_for_topic(master_uri, name, timeout_s=20.0):
    """Wait until some node publishes `name`; returns its type as the master knows it."""
    def lookup():
        try:
            topics = dict(_master(master_uri).getPublishedTopics("/"))
        except (rosgraph.MasterError, OSError):
            return None
        return topics.get(name)
    return wait_until(lookup, timeout_s, "a publisher on " + name)


def wait_for_param(master_uri, name, timeout_s=20.0):
    """Wait until parameter `name` exists (e.g. /use_sim_time, before starting nodes that must use sim time:
    rospy reads it once, at init_node); returns its value."""
    def lookup():
        try:
            master = _master(master_uri)
            return (master.getParam(name),) if master.hasParam(name) else None
        except (rosgraph.MasterError, OSError):
            return None
    return wait_until(lookup, timeout_s, "parameter " + name)[0]
