"""scripts/bench: run every benchmark module and print one table (wall-clock figures, never asserted).

Each module in BENCHMARKS has `run()` returning rows (measure, value, unit, target, comparison) where
comparison is ">=" or "<=" against target. The table shows value/target as a ratio (>= 1 means the target
is met, whichever the direction), so runs on a noisy shared machine compare by ratio. Also written to
bench-output/bench.md as a Markdown table.

    python3 tests/bench/report.py [module ...]      (from a ROS terminal; scripts/bench does this)
"""
import importlib
import sys
import time
from pathlib import Path

BENCH_DIR = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH_DIR))
sys.path.insert(0, str(BENCH_DIR.parent))

BENCHMARKS = ["tb3_sim_bench", "tb3_sim_profile", "camera_bench", "turtlesim_cpu", "load_bench", "web_bench",
              "web_mapping_bench", "line_follower_bench", "grade_bench", "map_bench", "slam_bench", "nav_bench",
              "explore_bench", "part3_bench", "nav_worlds_bench", "suite_time"]
OUTPUT = BENCH_DIR.parents[1] / "bench-output" / "bench.md"


def target_ratio(value, target, comparison):
    """>= 1 when the target is met: value/target for ">=" targets, target/value for "<=" targets."""
    if comparison == ">=":
        return value / target
    return target / value if value > 0 else float("inf")


def format_rows(rows):
    header = ("measure", "value", "target", "ratio", "met")
    lines = [header]
    for measure, value, unit, target, comparison in rows:
        ratio = target_ratio(value, target, comparison)
        lines.append((measure, "{:.3g} {}".format(value, unit), "{} {:g} {}".format(comparison, target, unit),
                      "{:.2f}".format(ratio), "yes" if ratio >= 1.0 else "NO"))
    return lines


def as_text(lines):
    widths = [max(len(line[i]) for line in lines) for i in range(len(lines[0]))]
    text = ["  ".join(cell.ljust(width) for cell, width in zip(line, widths)).rstrip() for line in lines]
    text.insert(1, "  ".join("-" * width for width in widths))
    return "\n".join(text)


def as_markdown(lines):
    rows = ["| " + " | ".join(line) + " |" for line in lines]
    rows.insert(1, "|" + "---|" * len(lines[0]))
    return "\n".join(rows)


def print_table(rows):
    print(as_text(format_rows(rows)))


def main(argv):
    names = argv[1:] or BENCHMARKS
    rows = []
    for name in names:
        started = time.monotonic()
        print("==> benchmark {} ...".format(name), flush=True)
        rows.extend(importlib.import_module(name).run())
        print("    done in {:.0f} s".format(time.monotonic() - started), flush=True)
    lines = format_rows(rows)
    print()
    print(as_text(lines))
    OUTPUT.parent.mkdir(exist_ok=True)
    OUTPUT.write_text(as_markdown(lines) + "\n")
    print("\n(also in {})".format(OUTPUT.relative_to(BENCH_DIR.parents[1])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
