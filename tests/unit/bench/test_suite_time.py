"""scripts/bench's suite-time rows from the record a whole-suite scripts/test run writes."""
import pytest

from bench.suite_time import rows_from

RECORD = {"total_s": 600, "pytest_s": 405, "exit": 0, "workers": 3, "cores": 2, "commit": "abc1234",
          "date": "2026-11-24T02:40:00Z"}


def test_rows_give_minutes_against_the_7_minute_target():
    tests_only, whole = rows_from(RECORD)
    assert tests_only[1:] == (pytest.approx(6.75), "min", 7.0, "<=")
    assert whole[1:] == (pytest.approx(10.0), "min", 7.0, "<=")
    assert "abc1234 on 2 cores, 3 workers" in tests_only[0] and "FAILED" not in tests_only[0]


def test_a_failed_run_says_so():
    assert "FAILED" in rows_from({**RECORD, "exit": 1})[0][0]
