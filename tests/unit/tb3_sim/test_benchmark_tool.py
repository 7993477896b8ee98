"""The core micro-benchmarks scripts/bench runs still run against the current core (values are not judged)."""
from tb3_sim.tools.benchmark import bench_scan, bench_steps


def test_scan_and_step_benchmarks_run():
    assert bench_scan(repeats=2) > 0.0
    steps_per_s, real_time_factor = bench_steps(sim_seconds=0.1)
    assert steps_per_s > 0.0 and real_time_factor > 0.0
