"""The /use_sim_time parameter as a value that can be recorded and put back: "true", "false" or "unset".

A TurtleBot3 launch sets /use_sim_time to true on the master; on a roscore that outlives the launch, it stayed
true, and the next node using wall-clock time (the turtlesim pages' publisher) stood at time 0 and waited for a
/clock that never came. tb3_sim therefore puts it back as it was before the launch when it exits. roslaunch sets
the launch's parameters before it starts any node, so the value the launch found is recorded while roslaunch
reads the launch file (`<param command="$(find sim_clock)/nodes/use_sim_time_state"/>`, run before the master is
told anything) and handed to the node as a parameter.

No rospy here: a rosgraph.Master is passed in, so the tool that records the state runs without a node.
"""
import rosgraph

PARAM = "/use_sim_time"
UNSET = "unset"
STATES = ("true", "false", UNSET)


def read_state(master):
    """'true' or 'false' (as the parameter's truth value) or 'unset' when the master has no /use_sim_time."""
    if not master.hasParam(PARAM):
        return UNSET
    return "true" if master.getParam(PARAM) else "false"


def parse_state(text):
    """The recorded state `text` (one of STATES, any case and surrounding blanks); ValueError for anything else."""
    state = str(text).strip().lower()
    if state not in STATES:
        raise ValueError("use_sim_time state must be one of {}, got {!r}".format(", ".join(STATES), text))
    return state


def restore_state(master, state):
    """Put /use_sim_time back to `state` ('true', 'false' or 'unset': deleted)."""
    state = parse_state(state)
    if state == UNSET:
        if master.hasParam(PARAM):
            master.deleteParam(PARAM)
    else:
        master.setParam(PARAM, state == "true")


def state_on_master(caller_id):
    """read_state of the master of this environment, or 'unset' when no master answers (roslaunch starts one
    afterwards, with no parameters)."""
    try:
        return read_state(rosgraph.Master(caller_id))
    except OSError:
        return UNSET
