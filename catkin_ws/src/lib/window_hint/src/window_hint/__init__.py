"""window_hint: one line saying how to see a window here when there is no display (see hints), the display check
(display) and the relay in front of Debian's window tools (relay)."""
from window_hint.display import NO_DISPLAY, display_problem, display_reachable
from window_hint.hints import can_open_window, no_display_line

__all__ = ["NO_DISPLAY", "can_open_window", "display_problem", "display_reachable", "no_display_line"]
