"""The test suite's wall time for scripts/bench, read from what the last whole-suite `scripts/test` run recorded in
bench-output/scripts_test.json (running the suite from here would take as long as the suite and load the machine
under the other benchmarks). A fresh clone's first run includes set-up: the venv and the catkin build.

    source scripts/env.sh && python3 tests/bench/suite_time.py

`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table; none when no
whole-suite run has been recorded yet (it says so). Besides the wall times, two rows put them in context: the
lower bound the run's CPU seconds set on the machine's cores, and the time per test against the target's own
starting point (the suite has grown since the target was set).
"""
import json
from pathlib import Path

RECORD = Path(__file__).resolve().parents[2] / "bench-output" / "scripts_test.json"
TARGET_MIN = 7.0
# Where the target came from: "about 13 minutes" for the 880 tests the suite had then, to be halved. Per test, that
# is 0.44 s of a whole run; a suite that grew since can be compared with it only per test.
BASELINE_TESTS, BASELINE_MIN = 880, 13.0
TARGET_PER_TEST_S = BASELINE_MIN * 60.0 / BASELINE_TESTS / 2.0


def rows_from(record):
    """Table rows for a recorded run (a dict as scripts/test writes it). Records from before scripts/test counted
    tests and CPU seconds give only the two wall-time rows."""
    context = "{} on {} cores, {} workers, {}{}".format(record["commit"], record["cores"], record["workers"],
                                                     record["date"], "" if record["exit"] == 0 else ", FAILED")
    rows = [
        (f"scripts/test, tests only ({context})", record["pytest_s"] / 60.0, "min", TARGET_MIN, "<="),
        (f"scripts/test, whole run incl. set-up ({context})", record["total_s"] / 60.0, "min", TARGET_MIN, "<="),
    ]
    if record.get("cpu_s"):
        # No schedule runs the whole run faster than its CPU seconds spread over every core.
        rows.append((f"scripts/test's lower bound: its {record['cpu_s']} CPU s / {record['cores']} cores",
                     record["cpu_s"] / record["cores"] / 60.0, "min", TARGET_MIN, "<="))
    if record.get("tests"):
        rows.append((f"scripts/test, whole run per test ({record['tests']} tests; when the target was set: "
                     f"{BASELINE_MIN:g} min for {BASELINE_TESTS}, halved)", record["total_s"] / record["tests"], "s",
                     round(TARGET_PER_TEST_S, 2), "<="))
    return rows


def run():
    if not RECORD.is_file():
        print(f"no whole-suite run recorded yet: run scripts/test (it writes {RECORD.name})")
        return []
    return rows_from(json.loads(RECORD.read_text()))


if __name__ == "__main__":
    from report import print_table
    print_table(run())
