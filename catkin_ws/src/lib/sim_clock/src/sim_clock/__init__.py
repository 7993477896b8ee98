"""sim_clock: /use_sim_time put back as a simulator found it (param), a warning when it is stuck (watch), and
rospy's time notifications without a deprecation warning at every /clock message (quiet)."""
from sim_clock.param import UNSET, parse_state, read_state, restore_state
from sim_clock.quiet import quiet_time_notifications
from sim_clock.watch import wait_for_clock, warn_if_clock_missing

__all__ = ["UNSET", "parse_state", "quiet_time_notifications", "read_state", "restore_state", "wait_for_clock",
           "warn_if_clock_missing"]
