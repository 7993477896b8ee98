"""Who may open the page. On 127.0.0.1 (the default) anyone on this machine may, as with any local ROS tool.
Listening on another address lets other machines in, and the page drives the robot, so a token is then
required in the URL (?token=...): the one given, or a random one printed with the URL at start."""
import hmac
import ipaddress
import secrets

LOOPBACK_NAMES = ("localhost",)


class AccessError(ValueError):
    """A host or token setting that cannot be used; the text says why."""


def is_loopback(host):
    if host in LOOPBACK_NAMES:
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


class AccessPolicy:
    """The host to bind and the token the page must present (None: no token needed, loopback only)."""

    def __init__(self, host, token=""):
        if not isinstance(host, str) or not host:
            raise AccessError("host must be an address such as 127.0.0.1 or 0.0.0.0, got {!r}".format(host))
        self.host = host
        self.loopback_only = is_loopback(host)
        if token and len(token) < 8:
            raise AccessError("token must be at least 8 characters (or empty for a random one)")
        self.token = None if self.loopback_only and not token else (token or secrets.token_urlsafe(16))

    def allows(self, presented):
        """True when a request with token `presented` (None when absent) may open the page or the socket."""
        if self.token is None:
            return True
        return isinstance(presented, str) and hmac.compare_digest(presented.encode(), self.token.encode())

    def url(self, port):
        """The URL to open, with the token when one is needed."""
        host = "localhost" if self.loopback_only or self.host in ("0.0.0.0", "::") else self.host
        return "http://{}:{}/{}".format(host, port, "?token=" + self.token if self.token else "")

    def warning(self):
        """The line printed when the page is reachable from other machines, or None."""
        if self.loopback_only:
            return None
        return ("lab_web listens on {} (not only this machine): anyone who can reach it and has the token can drive "
                "the robot. Share the URL only with people you trust.".format(self.host))
