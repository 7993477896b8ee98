"""roscpp's console line format: padded severities, nanosecond stamps, ROSCONSOLE_FORMAT tokens."""
from roscpp_console.line_format import DEFAULT_FORMAT, SEVERITIES, console_line, stamp_text


def test_stamps_have_nine_digits_of_nanoseconds():
    assert stamp_text(1_700_000_000_000_000_123) == "1700000000.000000123"
    assert stamp_text(12_500_000_000) == "12.500000000"
    assert stamp_text(0) == "0.000000000"


def test_the_default_line_is_roscpps():
    tokens = {"severity": SEVERITIES["INFO"], "time": "1700000000.123456789", "message": "Clearing turtlesim."}
    assert console_line(DEFAULT_FORMAT, tokens) == "[ INFO] [1700000000.123456789]: Clearing turtlesim."


def test_severities_are_five_characters_wide():
    assert [SEVERITIES[name] for name in ("DEBUG", "INFO", "WARNING", "ERROR", "CRITICAL")] == [
        "DEBUG", " INFO", " WARN", "ERROR", "FATAL"]


def test_user_formats_fill_known_tokens_and_keep_unknown_ones():
    line = console_line("${node} ${line} ${severity}: ${message} ${nonsense}",
                        {"node": "/turtlesim", "line": 42, "severity": "ERROR", "message": "m"})
    assert line == "/turtlesim 42 ERROR: m ${nonsense}"
