"""Free TCP ports for the masters and servers a test starts, that no ROS node and no other test worker can be
given before they bind.

A port the kernel picked for `bind(("localhost", 0))` and that was released at once is free only for a moment:
every ROS node binds its XML-RPC and TCPROS servers to port 0 too, and the kernel hands out the same range
(net.ipv4.ip_local_port_range, 32768-60999 here) to them and to every outgoing connection. With three test
workers starting nodes, one of them took such a port in the second before the test's web server bound it
(`address already in use`, a failed run). So the ports come from below that range (Linux's default, which this
module assumes), where the kernel never picks one by itself, each xdist worker from a block of its own, counting
on from a random start and skipping any port that cannot be bound right now (another program's).
"""
import itertools
import os
import random
import re
import socket

FIRST_PORT = 20000
LAST_PORT = 32767       # one below the kernel's default ephemeral range
BLOCKS = 8              # xdist workers gw0..gw7 each get a block; more workers share them


def _block():
    """This process's ports: the block of its xdist worker (gwN), or the first block outside xdist."""
    worker = re.fullmatch(r"gw(\d+)", os.environ.get("PYTEST_XDIST_WORKER", ""))
    index = int(worker.group(1)) % BLOCKS if worker else 0
    size = (LAST_PORT - FIRST_PORT + 1) // BLOCKS
    return range(FIRST_PORT + index * size, FIRST_PORT + (index + 1) * size)


_BLOCK = _block()
# Round and round the block from a random start: two sessions on one machine rarely start at the same port.
_START = random.randrange(len(_BLOCK))
_ports = itertools.cycle(itertools.chain(_BLOCK[_START:], _BLOCK[:_START]))


def _bindable(port):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        try:
            sock.bind(("localhost", port))
        except OSError:
            return False
    return True


def free_port():
    """A TCP port on localhost that no other test worker hands out and the kernel does not give to port-0 binds."""
    for port in itertools.islice(_ports, len(_BLOCK)):
        if _bindable(port):
            return port
    raise OSError("no free TCP port in {}-{}".format(_BLOCK[0], _BLOCK[-1]))
