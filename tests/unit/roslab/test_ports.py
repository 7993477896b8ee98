"""free_port: ports below the kernel's ephemeral range, a block per xdist worker, never one that is in use."""
import itertools
import socket

from roslab import ports


def ephemeral_range():
    with open("/proc/sys/net/ipv4/ip_local_port_range") as limits:
        return tuple(int(word) for word in limits.read().split())


def test_ports_are_below_the_ephemeral_range_and_do_not_repeat():
    handed_out = [ports.free_port() for _ in range(50)]
    assert len(set(handed_out)) == 50
    assert all(port in ports._BLOCK and port < ephemeral_range()[0] for port in handed_out)


def test_each_worker_has_a_block_of_its_own(monkeypatch):
    blocks = []
    for worker in ("gw0", "gw1", "gw2", "gw7"):
        monkeypatch.setenv("PYTEST_XDIST_WORKER", worker)
        blocks.append(set(ports._block()))
    assert all(not (a & b) for a, b in itertools.combinations(blocks, 2))
    monkeypatch.delenv("PYTEST_XDIST_WORKER")
    assert set(ports._block()) == blocks[0]


def test_a_port_in_use_is_skipped(monkeypatch):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as taken:
        taken.bind(("localhost", 0))
        taken.listen()
        busy = taken.getsockname()[1]
        monkeypatch.setattr(ports, "_ports", itertools.cycle([busy, ports._BLOCK[0]]))
        assert ports.free_port() == ports._BLOCK[0]
