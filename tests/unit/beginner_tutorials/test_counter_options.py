"""counter_client.py's command line."""
import pytest

from beginner_tutorials.counter_options import DEFAULT_NUM_COUNTS, CounterOptions, parse_counter_options, usage
from beginner_tutorials.errors import UsageError


@pytest.mark.parametrize("args, options", [
    ([], CounterOptions(DEFAULT_NUM_COUNTS, None)),
    (["3"], CounterOptions(3, None)),
    (["0"], CounterOptions(0, None)),
    (["-2"], CounterOptions(-2, None)),
    (["5", "--cancel-after", "2"], CounterOptions(5, 2.0)),
    (["--cancel-after", "1.5", "5"], CounterOptions(5, 1.5)),
    (["--cancel-after=3"], CounterOptions(DEFAULT_NUM_COUNTS, 3.0)),
])
def test_valid_command_lines(args, options):
    assert parse_counter_options(args) == options


@pytest.mark.parametrize("args, reason", [
    (["three"], "argument NUM_COUNTS: 'three' is not an integer"),
    (["2147483648"], "argument NUM_COUNTS: 2147483648 is outside the int32 range -2147483648..2147483647"),
    (["5", "--cancel-after", "0"], "argument --cancel-after: 0 is not a positive, finite number of seconds"),
    (["5", "--cancel-after", "-1"], "argument --cancel-after: -1 is not a positive, finite number of seconds"),
    (["5", "--cancel-after", "inf"], "argument --cancel-after: inf is not a positive, finite number of seconds"),
    (["5", "--cancel-after", "soon"], "argument --cancel-after: 'soon' is not a number of seconds"),
    (["5", "--cancel-after"], "argument --cancel-after: expected one argument"),
    (["5", "6"], "unrecognized arguments: 6"),
    (["5", "--fast"], "unrecognized arguments: --fast"),
])
def test_wrong_command_lines_raise_usage_errors(args, reason):
    with pytest.raises(UsageError) as caught:
        parse_counter_options(args)
    assert str(caught.value) == reason


def test_usage_shows_both_arguments():
    assert usage("counter_client.py") == "usage: counter_client.py [-h] [--cancel-after SECONDS] [NUM_COUNTS]"
