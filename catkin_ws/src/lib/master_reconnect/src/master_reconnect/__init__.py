"""master_reconnect: keep a rospy node registered when roscore is restarted (see watchdog)."""
from master_reconnect.watchdog import keep_registered

__all__ = ["keep_registered"]
