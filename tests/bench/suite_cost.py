"""Where the test suite's time goes: the test modules that cost the most CPU and wall time in the last whole-suite
run (scripts/test records each module's cost in bench-output/module_cost.jsonl; tests/conftest.py measures it).
CPU seconds include every process a module started and ended (roscore, simulators, nodes), so on a machine with
C cores a suite of S CPU seconds needs at least S / C seconds whatever the scheduling.

    python3 tests/bench/suite_cost.py [how many modules, default 20]
"""
import json
import sys
from pathlib import Path

LOG = Path(__file__).resolve().parents[2] / "bench-output" / "module_cost.jsonl"
SHOWN = 20


def read_costs(path=LOG):
    return [json.loads(line) for line in Path(path).read_text().splitlines() if line.strip()]


def table(costs, shown=SHOWN):
    """Lines of a table of the `shown` costliest modules by CPU, with totals (test counts: logs from before
    conftest counted them show none)."""
    total_cpu = sum(cost["cpu_s"] for cost in costs)
    total_wall = sum(cost["wall_s"] for cost in costs)
    total_tests = sum(cost.get("tests", 0) for cost in costs)
    lines = ["{:<72} {:>6} {:>8} {:>8} {:>6}".format("module", "tests", "CPU s", "wall s", "CPU %")]
    for cost in sorted(costs, key=lambda cost: cost["cpu_s"], reverse=True)[:shown]:
        lines.append("{:<72} {:>6} {:>8.1f} {:>8.1f} {:>5.1f}%".format(
            cost["module"][-72:], cost.get("tests", ""), cost["cpu_s"], cost["wall_s"],
            100.0 * cost["cpu_s"] / total_cpu))
    lines.append("{:<72} {:>6} {:>8.1f} {:>8.1f}".format("all {} modules".format(len(costs)), total_tests or "",
                                                         total_cpu, total_wall))
    return lines


if __name__ == "__main__":
    if not LOG.is_file():
        sys.exit("no module costs recorded yet: run scripts/test (it writes {})".format(LOG))
    print("\n".join(table(read_costs(), int(sys.argv[1]) if len(sys.argv) > 1 else SHOWN)))
