"""Load (issue 8, item 3): 20 concurrent clients x 100 calls on add_two_int (the Python server, and the C++
one) and on /gazebo/get_model_state while tb3_sim runs at real time (see roslab.load). Every call must
succeed with the right answer, and /odom and /scan must keep their rates meanwhile, measured from their
header stamps in sim time with no message missing. Latencies are not asserted here:
tests/bench/load_bench.py reports them (scripts/bench)."""
import pytest

from roslab.load import CALLS, CLIENTS, EXPECTED_RATES_HZ, LOADS, LoadGraph

RATE_TOLERANCE = 0.1          # +-10 %: 30 +- 3 Hz for /odom, 5 +- 0.5 Hz for /scan
MISSING_GAP = 1.5             # a gap of 1.5 periods between two stamps means a message went missing


@pytest.fixture(scope="module")
def graph(ros_master):
    return LoadGraph(ros_master)


@pytest.mark.parametrize("load", sorted(LOADS))
def test_concurrent_clients_all_succeed_and_the_robot_topics_keep_their_rates(graph, load):
    run = graph.hammer(LOADS[load])
    print("{}: {} calls in {:.1f} s, p50 {:.1f} ms, p99 {:.1f} ms; {}".format(
        load, len(run.latencies_s), run.wall_s, run.percentile_ms(50), run.percentile_ms(99), run.topics))
    assert run.failures == []
    assert len(run.latencies_s) == CLIENTS * CALLS
    for topic, expected_hz in EXPECTED_RATES_HZ.items():
        rates = run.topics[topic]
        assert rates["stamps_hz"] == pytest.approx(expected_hz, rel=RATE_TOLERANCE), (topic, rates)
        assert rates["largest_gap_s"] < MISSING_GAP / expected_hz, ("a message went missing", topic, rates)
