"""The counter action's progress: one count per second up to num_counts.

Feedback follows the ROS Theory tutorial: before each one-second wait the server publishes how many counts
have elapsed so far, so a goal of n counts gives feedback 0, 1, ..., n-1 and succeeds after n seconds with
"Counting complete!". num_counts below 1 cannot be counted and is aborted with CountError's text (the
tutorial's server would succeed at once or crash on such goals).
"""
from .errors import CountError

COUNT_RATE_HZ = 1.0
COMPLETE_MESSAGE = "Counting complete!"


class CountingTask:
    """How far one goal has counted. `counts_elapsed` is the feedback value; `advance()` after each wait."""

    def __init__(self, num_counts):
        if num_counts < 1:
            raise CountError("num_counts must be at least 1 (one count per second); got {}".format(num_counts))
        self.num_counts = num_counts
        self.counts_elapsed = 0

    @property
    def finished(self):
        return self.counts_elapsed >= self.num_counts

    def advance(self):
        if self.finished:
            raise CountError("already counted to {}".format(self.num_counts))
        self.counts_elapsed += 1

    def preempted_message(self):
        return "Counting preempted after {} of {} counts".format(self.counts_elapsed, self.num_counts)
