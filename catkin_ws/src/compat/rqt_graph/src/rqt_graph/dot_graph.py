"""The ROS graph in Graphviz's DOT language, as rqt_graph's default view draws it (no ROS import).

rqt_graph's default is "Nodes only" with "Hide: Debug" on: one ellipse per node, one arrow from each publishing
node to each subscribing node of a topic, labelled with the topic; rosout and its topics (/rosout, /rosout_agg)
are left out, as are topics with no subscriber or no publisher (no arrow to draw). Nodes with no arrow still show.
"""
from typing import NamedTuple

DEBUG_NODES = frozenset({"/rosout"})
DEBUG_TOPICS = frozenset({"/rosout", "/rosout_agg"})


class Graph(NamedTuple):
    nodes: list     # node names, sorted
    edges: list     # (publisher, subscriber, topic), sorted


def node_graph(publishers, subscribers):
    """The graph from the master's system state lists ([[topic, [node, ...]], ...] for publishers and
    subscribers), debug hidden."""
    subscribed = {topic: set(nodes) for topic, nodes in subscribers if topic not in DEBUG_TOPICS}
    nodes = {node for _, names in [*publishers, *subscribers] for node in names} - DEBUG_NODES
    edges = set()
    for topic, publishing in publishers:
        for publisher in set(publishing) - DEBUG_NODES:
            for subscriber in subscribed.get(topic, set()) - DEBUG_NODES:
                edges.add((publisher, subscriber, topic))
    return Graph(sorted(nodes), sorted(edges))


def _quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def to_dot(graph):
    """DOT text: left to right, as rqt_graph lays it out."""
    lines = ["digraph rosgraph {", "  rankdir=LR;", "  node [shape=ellipse, fontname=\"Helvetica\"];",
             "  edge [fontname=\"Helvetica\", fontsize=10];"]
    lines += [f"  {_quoted(node)};" for node in graph.nodes]
    lines += [f"  {_quoted(publisher)} -> {_quoted(subscriber)} [label={_quoted(topic)}];"
              for publisher, subscriber, topic in graph.edges]
    lines.append("}")
    return "\n".join(lines) + "\n"
