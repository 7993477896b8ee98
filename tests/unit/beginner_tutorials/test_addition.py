"""add_two_int's argument check (client) and overflow-safe sum (server)."""
import pytest

from beginner_tutorials.addition import INT64_MAX, INT64_MIN, checked_sum, parse_addends, parse_int64, usage
from beginner_tutorials.errors import SumOutOfRangeError, TutorialError, UsageError


def test_two_integers_are_parsed():
    assert parse_addends(["4", "5"]) == (4, 5)
    assert parse_addends(["-7", "+3"]) == (-7, 3)


def test_int64_limits_are_accepted():
    assert parse_addends([str(INT64_MIN), str(INT64_MAX)]) == (-(2 ** 63), 2 ** 63 - 1)


@pytest.mark.parametrize("args, reason", [
    ([], "expected 2 arguments, A and B; got 0"),
    (["4"], "expected 2 arguments, A and B; got 1"),
    (["4", "5", "6"], "expected 2 arguments, A and B; got 3"),
    (["4", "x"], "'x' is not an integer"),
    (["4.0", "5"], "'4.0' is not an integer"),
    (["0x10", "5"], "'0x10' is not an integer"),
    (["1_000", "5"], "'1_000' is not an integer"),
    ([" 4", "5"], "' 4' is not an integer"),
    (["", "5"], "'' is not an integer"),
    (["-", "5"], "'-' is not an integer"),
    (["4", "9223372036854775808"],
     "9223372036854775808 is outside the int64 range -9223372036854775808..9223372036854775807"),
    (["-9223372036854775809", "4"],
     "-9223372036854775809 is outside the int64 range -9223372036854775808..9223372036854775807"),
])
def test_wrong_arguments_name_the_problem(args, reason):
    with pytest.raises(UsageError) as caught:
        parse_addends(args)
    assert str(caught.value) == reason


def test_usage_names_the_program_and_the_range():
    text = usage("add_two_int_client.py")
    assert text.startswith("usage: add_two_int_client.py A B\n")
    assert "-9223372036854775808 to 9223372036854775807 (int64)" in text


def test_parse_int64_is_the_single_value_rule():
    assert parse_int64("-0") == 0
    with pytest.raises(UsageError):
        parse_int64("٣")  # a Unicode digit, which int() would accept


@pytest.mark.parametrize("a, b, total", [(4, 5, 9), (-4, 5, 1), (INT64_MAX, 0, INT64_MAX),
                                         (INT64_MAX, INT64_MIN, -1), (INT64_MIN, 0, INT64_MIN)])
def test_sums_inside_int64_are_returned(a, b, total):
    assert checked_sum(a, b) == total


@pytest.mark.parametrize("a, b", [(INT64_MAX, 1), (INT64_MIN, -1), (INT64_MAX, INT64_MAX)])
def test_sums_outside_int64_are_refused_with_the_range(a, b):
    with pytest.raises(SumOutOfRangeError) as caught:
        checked_sum(a, b)
    assert str(caught.value) == ("{} + {} is outside the int64 range -9223372036854775808..9223372036854775807; "
                                 "the sum cannot be returned".format(a, b))


def test_all_logic_errors_share_one_root():
    assert issubclass(UsageError, TutorialError) and issubclass(SumOutOfRangeError, TutorialError)
