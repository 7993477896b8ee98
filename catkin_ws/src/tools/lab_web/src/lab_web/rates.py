"""Publish rates of topics as the page's graph panel shows them, measured like `rostopic hz`: messages counted
as they arrive, the rate over a sliding window of wall time. No ROS import: the bridge calls `count`."""
import threading
from collections import deque

WINDOW_S = 2.0
"""The rate is over the last 2 s of wall time."""
MAX_STAMPS = 2000
"""Per topic; a faster topic reads as at least MAX_STAMPS / WINDOW_S Hz."""


class TopicRates:
    """Message arrival times per topic (wall seconds, from the caller's clock), thread-safe."""

    def __init__(self):
        self._lock = threading.Lock()
        self._stamps = {}

    def count(self, topic, now_s):
        with self._lock:
            self._stamps.setdefault(topic, deque(maxlen=MAX_STAMPS)).append(now_s)

    def forget(self, topic):
        with self._lock:
            self._stamps.pop(topic, None)

    def rate_hz(self, topic, now_s):
        """Messages per second over the last WINDOW_S, or None when no message arrived in it: `rostopic hz`
        says "no new messages" then, and a rate of 0 would claim a measurement."""
        with self._lock:
            stamps = self._stamps.get(topic)
            if not stamps:
                return None
            recent = [stamp for stamp in stamps if now_s - stamp <= WINDOW_S]
        if len(recent) < 2:
            return None
        span = now_s - recent[0]
        return round((len(recent) - 1) / span, 1) if span > 0 else None
