"""Which master a node is registered with, and whether a master it sees now is a restarted one (no ROS imports).

roscore sets the parameter /run_id to a fresh UUID every time it starts, so a different run id proves that
the master was restarted. A master that does not list the node proves nothing: rospy registers a new node in
the background and keeps retrying until the master is up, so for a moment after start-up the master may not
know it yet.
"""


class MasterRuns:
    """The run id of the master this node is registered with (None until one is known)."""

    def __init__(self, run_id=None):
        self.run_id = run_id

    def restarted(self, run_id, knows_node):
        """One look at the master: its /run_id (None while roscore has not set it yet) and whether it lists this
        node. True when it is a restarted master, so the node must register everything again (then call
        `registered`). The first master seen is adopted once it lists the node: rospy registers with it."""
        if run_id is None:
            return False
        if self.run_id is None:
            if knows_node:
                self.run_id = run_id
            return False
        return run_id != self.run_id

    def registered(self, run_id):
        """The node has registered everything with the master of `run_id`."""
        self.run_id = run_id
