"""Interference: a submission that tampers with what the checks measure, in words (plain Python, no ROS).

A check's verdict is "interference" when, between the grader's reset before it and the end of its recording,
- physics was paused (the ground-truth channel reports the simulator paused),
- a ROS client changed the world through /gazebo: pause_physics, unpause_physics, set_physics_properties,
  set_model_state (a teleport), reset_world, reset_simulation, spawn_model, delete_model (the grader resets
  through the private channel, which reports nothing), or
- a node other than the simulator published one of GUARDED_TOPICS (a message whose connection header names
  another node; merely advertising one is not interference), or took the simulator's node name (the simulator's
  XML-RPC URI on the master is not the one it gave on the private channel).
Limit: a publisher that forges the simulator's name in its own connection header is not told apart from the
simulator; what it publishes cannot change a measurement (the checks read the private channel), only this verdict.
The measurement itself never reads these topics (lab_grader.checks.ground_truth), so a forgery cannot pass a
check; the verdict says what was done, so a marker sees a cheat rather than a mysterious failure.
"""
from typing import Dict, Iterable, List, Sequence, Set, Tuple

GUARDED_TOPICS = ("/clock", "/odom", "/scan", "/gazebo/model_states", "/tf")


def foreign_publishers(publishers: Iterable[Tuple[str, Sequence[str]]], simulator_node: str) -> Dict[str, Set[str]]:
    """{guarded topic: the nodes other than `simulator_node` publishing it}, from the master's getSystemState
    publisher list [(topic, [node, ...]), ...]."""
    found = {}
    for topic, nodes in publishers:
        if topic in GUARDED_TOPICS:
            others = {node for node in nodes if node != simulator_node}
            if others:
                found[topic] = others
    return found


def findings(seen, publishers: Dict[str, Set[str]], impostor: bool, simulator_node: str) -> List[str]:
    """What interfered, in words (empty: nothing). `seen` is a ground_truth.Seen of the check's window,
    `publishers` the nodes other than the simulator heard publishing guarded topics meanwhile ({topic: nodes}),
    `impostor` whether another process held the simulator's node name."""
    words = []
    if seen.paused_at:
        words.append("physics was paused (from {:.2f} s of sim time)".format(seen.paused_at[0]))
    words += [change.words() for change in seen.changes]
    for topic in sorted(publishers):
        words.append("published {} (node{} {})".format(topic, "s" if len(publishers[topic]) > 1 else "",
                                                         ", ".join(sorted(publishers[topic]))))
    if impostor:
        words.append("registered a node under the simulator's name {}".format(simulator_node))
    return words
