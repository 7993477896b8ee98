"""A handshake timeout for rospy's inbound TCPROS connections (see handshake); startup/sitecustomize.py applies it
in every Python process of the lab."""
from rospy_handshake_timeout.handshake import HANDSHAKE_TIMEOUT_S, patch

__all__ = ["HANDSHAKE_TIMEOUT_S", "patch"]
