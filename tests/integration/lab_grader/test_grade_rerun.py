"""Mistakes that the measured motion decides, graded twice: a move server that drives backwards and a timed move
server that drives for twice the duration fail those checks with the measured evidence, and graded again (same
suite, same factor) they get the same score and the same verdict for every check.

The two grade runs start together (grading.at_once), each in sandbox slots of its own, as two graders
on one machine: the second no longer waits for the first (the module took 187 s graded one after the other, 81 s
for the first run and 101 s for the second, at load 9-14; 115 s at once, at load 12-14)."""
from functools import partial

import pytest

from .grading import GRADE_TIMEOUT_S, at_once, check, grade_class, others_pass, verdicts

pytestmark = pytest.mark.timeout(GRADE_TIMEOUT_S + 60)
CLASS = ("wrong_direction", "wrong_duration")
TIMED_MOVES = {"timed_fwd": 2, "timed_back": 2, "timed_left": 3, "timed_right": 3}   # check: seconds requested


@pytest.fixture(scope="module")
def gradings(grader_env, tmp_path_factory):
    """The class graded by two grade runs (GradedClass each)."""
    return at_once(*(partial(grade_class, grader_env, CLASS, tmp_path_factory.mktemp(run), "week4")
                     for run in ("first", "second")))


@pytest.fixture(scope="module")
def graded(gradings):
    return gradings[0]


@pytest.mark.slow
def test_driving_backwards_fails_the_move_check_with_the_evidence(graded):
    result = graded.results["wrong_direction"]
    move = check(result, "move_true")
    assert move["verdict"] == "fail"
    assert move["evidence"]["motion"]["forward_m"] < -0.3
    others_pass(result, "move_true")


@pytest.mark.slow
def test_moving_for_twice_the_duration_fails_the_timed_moves_with_the_measured_duration(graded):
    result = graded.results["wrong_duration"]
    for check_id, seconds in TIMED_MOVES.items():
        timed = check(result, check_id)
        assert timed["verdict"] == "fail", timed
        assert "expected the motion to last" in timed["reason"] and "it moved for" in timed["reason"], timed
        assert abs(timed["evidence"]["motion"]["duration_s"] - 2 * seconds) < 0.5, timed["evidence"]["motion"]
        assert timed["evidence"]["reply"] == {"success": True}
    others_pass(result, *TIMED_MOVES)


@pytest.mark.slow
def test_a_rerun_gives_identical_scores_and_verdicts(gradings):
    """The same submissions graded again (same suite, same factor): the same score and the same verdict for every
    check, also where the measured motion decides (a duration, a direction)."""
    first, second = (graded.results for graded in gradings)
    for name in CLASS:
        assert (second[name]["score"], verdicts(second[name])) == (first[name]["score"], verdicts(first[name]))
