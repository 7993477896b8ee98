"""counter_client.py's command line: `counter_client.py [NUM_COUNTS] [--cancel-after SECONDS]`.

NUM_COUNTS is passed on unchecked (any int32) so the server's own answer to 0 or a negative count can be
seen; SECONDS must be positive.
"""
import argparse
from typing import NamedTuple, Optional

from .errors import UsageError

DEFAULT_NUM_COUNTS = 10
INT32_MIN = -(2 ** 31)
INT32_MAX = 2 ** 31 - 1


class CounterOptions(NamedTuple):
    num_counts: int
    cancel_after_s: Optional[float]


class _Parser(argparse.ArgumentParser):
    """argparse that raises UsageError instead of printing and exiting, so the node owns the exit."""

    def error(self, message):
        raise UsageError(message)


def _int32(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("{!r} is not an integer".format(text)) from None
    if not INT32_MIN <= value <= INT32_MAX:
        raise argparse.ArgumentTypeError("{} is outside the int32 range {}..{}".format(text, INT32_MIN, INT32_MAX))
    return value


def _positive_seconds(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("{!r} is not a number of seconds".format(text)) from None
    if not 0 < value < float("inf"):
        raise argparse.ArgumentTypeError("{} is not a positive, finite number of seconds".format(text))
    return value


def _parser(program):
    parser = _Parser(prog=program, description="Send a goal to the counter action server (my_action_server) "
                     "and print its feedback and result.")
    parser.add_argument("num_counts", nargs="?", type=_int32, default=DEFAULT_NUM_COUNTS, metavar="NUM_COUNTS",
                        help="how many counts, one per second (int32; default {})".format(DEFAULT_NUM_COUNTS))
    parser.add_argument("--cancel-after", type=_positive_seconds, metavar="SECONDS", dest="cancel_after_s",
                        help="cancel (preempt) the goal after this many seconds")
    return parser


def usage(program):
    return _parser(program).format_usage().rstrip()


def parse_counter_options(args, program="counter_client.py"):
    """The options from `args` (remappings already removed); UsageError with argparse's reason otherwise."""
    namespace = _parser(program).parse_args(args)
    return CounterOptions(namespace.num_counts, namespace.cancel_after_s)
