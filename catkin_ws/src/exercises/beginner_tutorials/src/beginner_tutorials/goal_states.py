"""actionlib goal states as names, and what the counter client's exit code makes of them."""

# actionlib_msgs/GoalStatus constants, in value order (PENDING = 0 ... LOST = 9).
GOAL_STATE_NAMES = ("PENDING", "ACTIVE", "PREEMPTED", "SUCCEEDED", "ABORTED", "REJECTED", "PREEMPTING",
                    "RECALLING", "RECALLED", "LOST")


def goal_state_name(state):
    """'SUCCEEDED' for 3, and so on; an unknown value is named as such rather than raising."""
    if 0 <= state < len(GOAL_STATE_NAMES):
        return GOAL_STATE_NAMES[state]
    return "UNKNOWN({})".format(state)


def client_exit_code(state_name, cancel_requested):
    """0 when the goal ended the way the user asked (succeeded, or preempted/recalled after --cancel-after);
    1 otherwise (aborted, rejected, lost), so scripts can tell."""
    wanted = {"SUCCEEDED"} | ({"PREEMPTED", "RECALLED"} if cancel_requested else set())
    return 0 if state_name in wanted else 1
