"""The lab's one patch of ROS behaviour: a timeout for the handshake of rospy's inbound TCPROS connections.

Why: rospy (1.16, Debian 12's) accepts every inbound connection of a node (subscribers of its topics, callers of
its services) in one thread, and reads the connection's handshake header there before it accepts the next. The
accepted socket only has rospy's process-wide default timeout of 60 s (masterslave's socket.setdefaulttimeout),
so a connection that sends nothing (a port scan, a stale or crashed client, `nc` left open) stops that node from
taking any new service call or subscriber for 60 s, and every further idle connection adds 60 s more: measured,
`rosservice call /approach_service` failed with "Unable to communicate with service" while one raw connection to
the port `rosservice uri` names stayed open. roscpp reads handshakes asynchronously and has no such stall.

What changes, and nothing else: each inbound connection's handshake is read in a thread of its own (up to
MAX_CONCURRENT_HANDSHAKES at once; beyond that in the accept thread, as rospy does), with a timeout of
HANDSHAKE_TIMEOUT_S; a connection whose header has not arrived by then is closed with a warning in the node's log
("Inbound TCP/IP connection failed: no handshake header within 3 s"). Once the header is read, the socket gets
back the timeout rospy gave it, and rospy handles the connection exactly as before. Outbound connections (this
node subscribing or calling a service) are untouched. A well-behaved client sends its header right after
connect(), in the same call, so 3 s is far above what a loaded machine needs.

`patch(tcpros_base)` takes the module `rospy.impl.tcpros_base` (it imports nothing of ROS itself, so it is
unit-tested with a stand-in).
"""
import contextlib
import socket
import threading
import weakref

HANDSHAKE_TIMEOUT_S = 3.0
MAX_CONCURRENT_HANDSHAKES = 32
_PATCHED_MARK = "_lab_handshake_timeout"
_OUTBOUND = object()   # read_ros_handshake_header's marker for a socket that is not an inbound handshake


def patch(tcpros_base):
    """Give `tcpros_base.TCPROSServer`'s inbound handshakes a thread each and HANDSHAKE_TIMEOUT_S (idempotent)."""
    server_class = tcpros_base.TCPROSServer
    if getattr(server_class, _PATCHED_MARK, False):
        return
    read_header = tcpros_base.read_ros_handshake_header
    handle_connection = server_class._tcp_server_callback
    handshake_error = tcpros_base.rosgraph.network.ROSHandshakeException
    inbound = weakref.WeakKeyDictionary()   # accepted socket -> its timeout before the handshake
    slots = threading.BoundedSemaphore(MAX_CONCURRENT_HANDSHAKES)

    def read_ros_handshake_header(sock, buffer, buff_size):
        previous = inbound.pop(sock, None) if sock in inbound else _OUTBOUND
        if previous is _OUTBOUND:
            return read_header(sock, buffer, buff_size)
        try:
            return read_header(sock, buffer, buff_size)
        except socket.timeout:
            raise handshake_error("no handshake header within {:g} s".format(HANDSHAKE_TIMEOUT_S)) from None
        finally:
            with contextlib.suppress(OSError):   # closed meanwhile
                sock.settimeout(previous)

    def handshake(server, sock, client_addr, slot):
        try:
            handle_connection(server, sock, client_addr)
        finally:
            inbound.pop(sock, None)
            if slot:
                slots.release()

    def _tcp_server_callback(self, sock, client_addr):
        inbound[sock] = sock.gettimeout()
        sock.settimeout(HANDSHAKE_TIMEOUT_S)
        if slots.acquire(blocking=False):
            threading.Thread(target=handshake, args=(self, sock, client_addr, True), name="tcpros_handshake",
                             daemon=True).start()
        else:
            handshake(self, sock, client_addr, False)

    tcpros_base.read_ros_handshake_header = read_ros_handshake_header
    server_class._tcp_server_callback = _tcp_server_callback
    setattr(server_class, _PATCHED_MARK, True)

