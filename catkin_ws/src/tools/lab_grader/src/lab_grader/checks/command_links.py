"""Whether the simulator hears every node that publishes the robot's velocity commands (plain Python, no ROS).

rospy sends a message only over the connections its publisher has when it publishes: one published before a
subscriber has connected is lost. A student's node makes its /cmd_vel publisher at start and publishes its first
command when its service is called; the grader calls as soon as the service appears, and the simulator connects to
a new publisher on its own time (the master tells it, it asks the node for a connection, the node answers), which
on a busy machine, with the student's node at a lower priority (lab_grader.sandbox), can come after that first
command: the robot then stands still through the whole move, and the check measures a motion the node did ask
for as none. A marker would not call before the node is up, so before each check the grader waits until the
simulator is connected to every publisher of /cmd_vel (lab_grader.checks.context).
"""
from typing import Iterable, Sequence, Set

INBOUND = "i"


def unheard(publisher_uris: Iterable[str], bus_info: Sequence[Sequence], topic: str) -> Set[str]:
    """The XML-RPC URIs of `publisher_uris` that the subscriber whose getBusInfo answer is `bus_info` has no
    connection from on `topic`. A rospy subscriber lists each connection as (id, the publisher's XML-RPC URI,
    direction "i", transport, topic, connected, ...)."""
    heard = {entry[1] for entry in bus_info
             if len(entry) > 5 and entry[2] == INBOUND and entry[4] == topic and entry[5]}
    return set(publisher_uris) - heard
