"""The counter action's progress: feedback values 0..n-1, then finished; n < 1 refused."""
import pytest

from beginner_tutorials.counting import COMPLETE_MESSAGE, COUNT_RATE_HZ, CountingTask
from beginner_tutorials.errors import CountError


def feedback_values(task):
    """What the server publishes: counts_elapsed before each wait, advancing after it."""
    values = []
    while not task.finished:
        values.append(task.counts_elapsed)
        task.advance()
    return values


@pytest.mark.parametrize("num_counts", [1, 3, 10])
def test_feedback_counts_from_zero_to_n_minus_one(num_counts):
    task = CountingTask(num_counts)
    assert feedback_values(task) == list(range(num_counts))
    assert task.finished and task.counts_elapsed == num_counts


def test_tutorial_constants():
    assert COMPLETE_MESSAGE == "Counting complete!"
    assert COUNT_RATE_HZ == 1.0


@pytest.mark.parametrize("num_counts", [0, -1, -(2 ** 31)])
def test_fewer_than_one_count_is_refused_with_the_reason(num_counts):
    with pytest.raises(CountError) as caught:
        CountingTask(num_counts)
    assert str(caught.value) == "num_counts must be at least 1 (one count per second); got {}".format(num_counts)


def test_advancing_past_the_end_is_an_error():
    task = CountingTask(1)
    task.advance()
    with pytest.raises(CountError, match="already counted to 1"):
        task.advance()


def test_preempted_message_says_how_far_it_got():
    task = CountingTask(5)
    task.advance()
    task.advance()
    assert task.preempted_message() == "Counting preempted after 2 of 5 counts"
