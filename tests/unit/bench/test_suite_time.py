"""scripts/bench's suite-time rows from the record a whole-suite scripts/test run writes."""
import pytest

from bench.suite_time import rows_from

RECORD = {"total_s": 600, "pytest_s": 405, "cpu_s": 1080, "tests": 1500, "exit": 0, "workers": 3, "cores": 2,
          "commit": "abc1234", "date": "2026-11-24T02:40:00Z"}


def test_rows_give_minutes_against_the_7_minute_target():
    tests_only, whole, _, _ = rows_from(RECORD)
    assert tests_only[1:] == (pytest.approx(6.75), "min", 7.0, "<=")
    assert whole[1:] == (pytest.approx(10.0), "min", 7.0, "<=")
    assert "abc1234 on 2 cores, 3 workers" in tests_only[0] and "FAILED" not in tests_only[0]


def test_the_cpu_seconds_over_the_cores_bound_the_wall_time():
    bound = rows_from(RECORD)[2]
    assert "1080 CPU s / 2 cores" in bound[0]
    assert bound[1:] == (pytest.approx(9.0), "min", 7.0, "<=")


def test_per_test_time_is_compared_with_13_minutes_for_880_tests_halved():
    per_test = rows_from(RECORD)[3]
    assert "1500 tests" in per_test[0]
    assert per_test[1:] == (pytest.approx(0.4), "s", 0.44, "<=")


def test_an_older_record_without_counts_gives_the_wall_times_only():
    older = {key: value for key, value in RECORD.items() if key not in ("cpu_s", "tests")}
    assert [row[2] for row in rows_from(older)] == ["min", "min"]


def test_a_failed_run_says_so():
    assert "FAILED" in rows_from({**RECORD, "exit": 1})[0][0]
