"""Goal state names match actionlib_msgs/GoalStatus, and the counter client's exit code rule."""
import pytest
from actionlib_msgs.msg import GoalStatus

from beginner_tutorials.goal_states import GOAL_STATE_NAMES, client_exit_code, goal_state_name


@pytest.mark.parametrize("name", GOAL_STATE_NAMES)
def test_names_match_the_goal_status_constants(name):
    assert goal_state_name(getattr(GoalStatus, name)) == name


def test_unknown_states_are_named_not_raised():
    assert goal_state_name(42) == "UNKNOWN(42)"
    assert goal_state_name(-1) == "UNKNOWN(-1)"


@pytest.mark.parametrize("state, cancel_requested, code", [
    ("SUCCEEDED", False, 0), ("SUCCEEDED", True, 0),
    ("PREEMPTED", True, 0), ("RECALLED", True, 0),
    ("PREEMPTED", False, 1), ("ABORTED", False, 1), ("ABORTED", True, 1), ("REJECTED", False, 1),
    ("LOST", False, 1),
])
def test_exit_code(state, cancel_requested, code):
    assert client_exit_code(state, cancel_requested) == code
