"""Who may open the page. On 127.0.0.1 (the default) anyone on this machine may, as with any local ROS tool.
Listening on another address lets other machines in, and the page drives the robot, so a token is then
required in the URL (?token=...): the one given, or a random one printed with the URL at start.

Every request must also name this machine in its Host header: localhost, a loopback address (127.0.0.1, ::1) or
the configured host; when listening on every interface (0.0.0.0, ::), any IP address or this machine's own name.
This stops DNS rebinding: a website whose name the attacker re-points at 127.0.0.1 reaches the port with
`Host: evil.example:8080` and a matching `Origin: http://evil.example:8080`, which a same-origin check alone
accepts, so without this any site a student visits could drive the robot in the token-less default. An IP
address in the Host header cannot be rebound (the page's origin is then that address itself).
"""
import hmac
import ipaddress
import secrets
import socket
from urllib.parse import urlsplit

LOOPBACK_NAMES = ("localhost",)
WILDCARD_HOSTS = ("0.0.0.0", "::")


class AccessError(ValueError):
    """A host or token setting that cannot be used; the text says why."""


def _ip_address(host):
    try:
        return ipaddress.ip_address(host)
    except ValueError:
        return None


def host_name(host_header):
    """The lower-case name or address of a Host header ("[::1]:8080" -> "::1"), or None when it has none."""
    try:
        name = urlsplit("//" + host_header).hostname
    except ValueError:
        return None
    return name.rstrip(".") if name else None


def is_loopback(host):
    if host in LOOPBACK_NAMES:
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


class AccessPolicy:
    """The host to bind and the token the page must present (None: no token needed, loopback only)."""

    def __init__(self, host, token="", machine_names=None):
        """`machine_names`: this machine's own names, allowed in the Host header when listening on every
        interface (default: socket.gethostname() and getfqdn())."""
        if not isinstance(host, str) or not host:
            raise AccessError("host must be an address such as 127.0.0.1 or 0.0.0.0, got {!r}".format(host))
        self.host = host
        if machine_names is None:
            machine_names = (socket.gethostname(), socket.getfqdn()) if host in WILDCARD_HOSTS else ()
        self._host_names = {name.lower().rstrip(".") for name in (*LOOPBACK_NAMES, host, *machine_names)}
        self.loopback_only = is_loopback(host)
        if token and len(token) < 8:
            raise AccessError("token must be at least 8 characters (or empty for a random one)")
        self.token = None if self.loopback_only and not token else (token or secrets.token_urlsafe(16))

    def allows(self, presented):
        """True when a request with token `presented` (None when absent) may open the page or the socket."""
        if self.token is None:
            return True
        return isinstance(presented, str) and hmac.compare_digest(presented.encode(), self.token.encode())

    def allows_host(self, host_header):
        """True when a request's Host header (None when absent) names this machine (see the module's text)."""
        name = host_name(host_header or "")
        if name is None:
            return False
        address = _ip_address(name)
        if address is not None:
            return address.is_loopback or self.host in WILDCARD_HOSTS or name == self.host.lower()
        return name in self._host_names

    def url(self, port):
        """The URL to open, with the token when one is needed."""
        host = "localhost" if self.loopback_only or self.host in WILDCARD_HOSTS else self.host
        return "http://{}:{}/{}".format(host, port, "?token=" + self.token if self.token else "")

    def warning(self):
        """The line printed when the page is reachable from other machines, or None."""
        if self.loopback_only:
            return None
        return ("lab_web listens on {} (not only this machine): anyone who can reach it and has the token can drive "
                "the robot. Share the URL only with people you trust.".format(self.host))
