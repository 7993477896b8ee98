"""The handshake patch on a stand-in of rospy.impl.tcpros_base: an inbound connection is handled in its own
thread, its header read times out, the socket gets its timeout back afterwards, outbound reads are untouched. The
real rospy is patched in every node of tests/integration/lab/test_idle_connection.py."""
import io
import queue
import socket
import types

import pytest
from rosgraph.network import ROSHandshakeException, encode_ros_handshake_header, read_ros_handshake_header

from rospy_handshake_timeout import handshake


def stand_in():
    """A module like tcpros_base: TCPROSServer._tcp_server_callback reads the header through the module's
    read_ros_handshake_header and reports (header or error, the socket's timeout afterwards)."""
    module = types.SimpleNamespace(read_ros_handshake_header=read_ros_handshake_header,
                                   rosgraph=types.SimpleNamespace(network=types.SimpleNamespace(
                                       ROSHandshakeException=ROSHandshakeException)))
    results = queue.Queue()

    class TCPROSServer:
        def _tcp_server_callback(self, sock, client_addr):
            try:
                header = module.read_ros_handshake_header(sock, io.BytesIO(), 4096)
            except ROSHandshakeException as error:
                header = error
            results.put((header, sock.gettimeout()))

    module.TCPROSServer = TCPROSServer
    handshake.patch(module)
    return module, results


@pytest.fixture
def short_timeout(monkeypatch):
    monkeypatch.setattr(handshake, "HANDSHAKE_TIMEOUT_S", 0.3)


def test_an_idle_connection_times_out_in_its_own_thread_and_keeps_its_timeout(short_timeout):
    module, results = stand_in()
    server_end, client_end = socket.socketpair()
    server_end.settimeout(60.0)
    module.TCPROSServer()._tcp_server_callback(server_end, ("127.0.0.1", 1))
    assert results.empty(), "the accept thread is free at once"
    error, timeout = results.get(timeout=5)
    assert isinstance(error, ROSHandshakeException) and "no handshake header within 0.3 s" in str(error)
    assert timeout == 60.0
    client_end.close()


def test_a_header_is_read_as_before():
    module, results = stand_in()
    server_end, client_end = socket.socketpair()
    # a new socket's timeout is socket.getdefaulttimeout(): None, or 60 s once rospy has run in this process
    timeout_before = server_end.gettimeout()
    client_end.sendall(encode_ros_handshake_header({"callerid": "/talker", "topic": "/chatter"}))
    module.TCPROSServer()._tcp_server_callback(server_end, ("127.0.0.1", 1))
    header, timeout = results.get(timeout=5)
    assert header == {"callerid": "/talker", "topic": "/chatter"} and timeout == timeout_before


def test_outbound_reads_are_untouched_and_patching_twice_changes_nothing(short_timeout):
    module, _ = stand_in()
    callback = module.TCPROSServer._tcp_server_callback
    handshake.patch(module)
    assert module.TCPROSServer._tcp_server_callback is callback
    reader, writer = socket.socketpair()
    reader.settimeout(2.0)
    writer.sendall(encode_ros_handshake_header({"error": "none"}))
    assert module.read_ros_handshake_header(reader, io.BytesIO(), 4096) == {"error": "none"}
    assert reader.gettimeout() == 2.0
