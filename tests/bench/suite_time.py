"""The test suite's wall time for scripts/bench, read from what the last whole-suite `scripts/test` run recorded in
bench-output/scripts_test.json (running the suite from here would take as long as the suite and load the machine
under the other benchmarks). A fresh clone's first run includes set-up: the venv and the catkin build.

    source scripts/env.sh && python3 tests/bench/suite_time.py

`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table; none when no
whole-suite run has been recorded yet (it says so).
"""
import json
from pathlib import Path

RECORD = Path(__file__).resolve().parents[2] / "bench-output" / "scripts_test.json"
TARGET_MIN = 7.0


def rows_from(record):
    """Table rows for a recorded run (a dict as scripts/test writes it)."""
    context = "{} on {} cores, {} workers, {}{}".format(record["commit"], record["cores"], record["workers"],
                                                     record["date"], "" if record["exit"] == 0 else ", FAILED")
    return [
        (f"scripts/test, tests only ({context})", record["pytest_s"] / 60.0, "min", TARGET_MIN, "<="),
        (f"scripts/test, whole run incl. set-up ({context})", record["total_s"] / 60.0, "min", TARGET_MIN, "<="),
    ]


def run():
    if not RECORD.is_file():
        print(f"no whole-suite run recorded yet: run scripts/test (it writes {RECORD.name})")
        return []
    return rows_from(json.loads(RECORD.read_text()))


if __name__ == "__main__":
    from report import print_table
    print_table(run())
