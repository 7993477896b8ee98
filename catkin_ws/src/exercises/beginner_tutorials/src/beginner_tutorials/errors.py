"""The one exception root of this package's logic; the nodes translate it once, into a usage message
(exit code 1) or a service/action error, so a user mistake never shows a traceback."""


class TutorialError(Exception):
    """A request or command line the tutorial code cannot act on; the text says what is allowed."""


class UsageError(TutorialError):
    """Wrong command-line arguments."""


class SumOutOfRangeError(TutorialError):
    """a + b does not fit the int64 `sum` field of add_two_int."""


class ScanLookupError(TutorialError):
    """The gazebo_server service cannot answer: no scan yet, or a direction outside the scan."""


class CountError(TutorialError):
    """A counter goal that cannot be counted (num_counts < 1)."""
