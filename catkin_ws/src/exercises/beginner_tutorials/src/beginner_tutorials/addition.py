"""add_two_int: the client's argument check and the server's overflow-safe sum.

Both fields of add_two_int.srv are int64, so the addends and the sum must lie in INT64_MIN..INT64_MAX.
Python integers never overflow, so the range check is explicit; the C++ server applies the same rule with
the same error text (src/add_two_int_server.cpp).
"""
import re

from .errors import SumOutOfRangeError, UsageError

INT64_MIN = -(2 ** 63)
INT64_MAX = 2 ** 63 - 1
INTEGER_PATTERN = re.compile(r"[+-]?[0-9]+")


def usage(program):
    return ("usage: {} A B\n"
            "  prints A + B, computed by the add_two_int service;\n"
            "  A and B are integers from {} to {} (int64)").format(program, INT64_MIN, INT64_MAX)


def parse_int64(text):
    """`text` as an int64, strictly: an optional sign and decimal digits, nothing else (no 4.0, 0x10, 1_000)."""
    if not INTEGER_PATTERN.fullmatch(text):
        raise UsageError("{!r} is not an integer".format(text))
    value = int(text)
    if not INT64_MIN <= value <= INT64_MAX:
        raise UsageError("{} is outside the int64 range {}..{}".format(text, INT64_MIN, INT64_MAX))
    return value


def parse_addends(args):
    """The client's two command-line arguments (remappings already removed) as a pair of int64 values."""
    if len(args) != 2:
        raise UsageError("expected 2 arguments, A and B; got {}".format(len(args)))
    return parse_int64(args[0]), parse_int64(args[1])


def checked_sum(a, b):
    """a + b, or SumOutOfRangeError when the sum does not fit int64 (rejected rather than wrapped around)."""
    total = a + b
    if not INT64_MIN <= total <= INT64_MAX:
        raise SumOutOfRangeError("{} + {} is outside the int64 range {}..{}; the sum cannot be returned".format(
            a, b, INT64_MIN, INT64_MAX))
    return total
