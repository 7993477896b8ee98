"""Facts about nodes of a running graph, from the master and the nodes' own XML-RPC APIs."""
import xmlrpc.client

import rosgraph


def node_pid(master_uri, node_name):
    """The process id of `node_name` (e.g. '/gazebo'), as the node itself reports it."""
    node_uri = rosgraph.Master("/roslab_test", master_uri=master_uri).lookupNode(node_name)
    code, message, pid = xmlrpc.client.ServerProxy(node_uri).getPid("/roslab_test")
    if code != 1:
        raise RuntimeError("getPid on {} failed: {}".format(node_name, message))
    return pid


def subscribers(master_uri, topic):
    """Names of the nodes the master lists as subscribers of `topic` (empty when none)."""
    _, subscriptions, _ = rosgraph.Master("/roslab_test", master_uri=master_uri).getSystemState()
    return next((nodes for name, nodes in subscriptions if name == topic), [])
