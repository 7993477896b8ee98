"""The grader's end of tb3_sim's private ground-truth channel (tb3_sim.ros.ground_truth documents the protocol):
the robot's true motion in the simulator's own sim time, the world changes ROS clients made, a reset and a
noise-free front distance, over a Unix socket only trusted processes can reach. No ROS import.

Why not /odom, /clock and /gazebo/reset_world: any node on the master can publish /clock and /odom, pause
physics, or serve a /gazebo/reset_world of its own, so what the checks measure must not come through ROS. The
grader's box puts the socket in a root-only folder its sandboxed student processes cannot see.

`TruthClient(path)` connects and reads on a daemon thread: `latest` is the newest Sample (motion.Sample), `now()`
its sim time; `mark()` / `since(mark)` give every sample, event and paused heartbeat after a point (what one check
saw); `request(name)` sends a request and waits for its reply. A connection that ends (the simulator died) makes
every wait raise TruthLost.
"""
import json
import socket
import threading
import time
from typing import List, NamedTuple, Optional, Tuple

from lab_grader.checks.motion import Sample
from lab_grader.checks.verdicts import CheckError

CONNECT_TIMEOUT_S = 30.0
HELLO_TIMEOUT_S = 30.0
REPLY_TIMEOUT_S = 10.0
MAX_LINE_BYTES = 64 * 1024


class TruthLost(CheckError):
    """The ground-truth channel closed or never opened (the simulator is gone): an error verdict."""


class WorldChange(NamedTuple):
    """A world change a ROS client made: the /gazebo service's name (`what`), the model (`detail`), sim time."""

    t: float
    what: str
    detail: str

    def words(self):
        return "called /gazebo/{}{} at {:.2f} s".format(self.what, " ({})".format(self.detail) if self.detail
                                                        else "", self.t)


class Mark(NamedTuple):
    samples: int
    changes: int
    paused: int


class Seen(NamedTuple):
    """What the channel brought after a Mark: samples (physics running), world changes, and the sim times at which
    physics was reported paused."""

    samples: Tuple[Sample, ...]
    changes: Tuple[WorldChange, ...]
    paused_at: Tuple[float, ...]


class TruthClient:
    """See the module docstring. `identity` is the simulator's hello: {"node", "uri", "robot"}."""

    def __init__(self, path, connect_timeout_s=CONNECT_TIMEOUT_S):
        self._socket = self._connect(str(path), connect_timeout_s)
        self._changed = threading.Condition()
        self._samples: List[Sample] = []
        self._changes: List[WorldChange] = []
        self._paused_at: List[float] = []
        self._replies = {}
        self._next_id = 0
        self._closed = None
        self._stream = self._socket.makefile("rb")
        self._socket.settimeout(HELLO_TIMEOUT_S)
        try:
            hello = self._read_line()
        except (OSError, ValueError) as error:
            raise TruthLost("the ground-truth channel at {} did not introduce itself within {:.0f} s: {}".format(
                path, HELLO_TIMEOUT_S, error)) from None
        if hello is None or hello.get("kind") != "hello":
            raise TruthLost("the ground-truth channel at {} did not introduce itself".format(path))
        # Then blocking without a timeout, whatever socket.setdefaulttimeout says (rospy sets 60 s there): the
        # reader thread waits for the simulator, which reports at least every 0.05 s of wall time while it runs.
        self._socket.settimeout(None)
        self.identity = {key: hello.get(key) for key in ("node", "uri", "robot")}
        threading.Thread(target=self._read, name="ground-truth", daemon=True).start()

    @staticmethod
    def _connect(path, timeout_s):
        deadline = time.monotonic() + timeout_s
        while True:
            client = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            try:
                client.connect(path)
                return client
            except OSError as error:
                client.close()
                if time.monotonic() > deadline:
                    raise TruthLost("cannot reach the simulator's ground-truth channel at {} after {:.0f} s: {}"
                                    .format(path, timeout_s, error.strerror or error)) from None
                time.sleep(0.1)

    def _read_line(self):
        line = self._stream.readline(MAX_LINE_BYTES)
        if not line:
            return None
        return json.loads(line)

    def _read(self):
        try:
            while True:
                message = self._read_line()
                if message is None:
                    break
                self._take(message)
            reason = "the simulator closed the ground-truth channel"
        except (OSError, ValueError) as error:
            reason = "the ground-truth channel broke: {}".format(error)
        with self._changed:
            self._closed = reason
            self._changed.notify_all()

    def _take(self, message):
        kind = message.get("kind")
        with self._changed:
            if kind == "state":
                if message["paused"]:
                    self._paused_at.append(message["t"])
                else:
                    self._samples.append(Sample(message["t"], message["x"], message["y"], message["yaw"],
                                                message["v"], message["w"]))
            elif kind == "event":
                self._changes.append(WorldChange(message["t"], message["what"], message.get("detail") or ""))
            elif kind == "reply":
                self._replies[message.get("id")] = message
            self._changed.notify_all()

    # ---- reading --------------------------------------------------------------------------------------------------

    @property
    def latest(self) -> Optional[Sample]:
        with self._changed:
            return self._samples[-1] if self._samples else None

    def now(self) -> float:
        """The simulator's sim time (s) as last reported (0 before the first report)."""
        with self._changed:
            times = [self._samples[-1].t] if self._samples else []
            times += self._paused_at[-1:]
        return max(times, default=0.0)

    def mark(self) -> Mark:
        with self._changed:
            return Mark(len(self._samples), len(self._changes), len(self._paused_at))

    def since(self, mark: Mark) -> Seen:
        with self._changed:
            return Seen(tuple(self._samples[mark.samples:]), tuple(self._changes[mark.changes:]),
                        tuple(self._paused_at[mark.paused:]))

    def wait(self, timeout_s):
        """Wait up to `timeout_s` wall seconds for anything new; TruthLost once the channel has closed."""
        with self._changed:
            if self._closed is None:
                self._changed.wait(timeout_s)
            if self._closed is not None:
                raise TruthLost(self._closed)

    def request(self, name, timeout_s=REPLY_TIMEOUT_S) -> dict:
        """Send request `name` (reset_world, front_distance) and return its reply; TruthLost without one."""
        with self._changed:
            self._next_id += 1
            request_id = self._next_id
        try:
            self._socket.sendall((json.dumps({"id": request_id, "request": name}) + "\n").encode())
        except OSError as error:
            raise TruthLost("cannot send to the ground-truth channel: {}".format(error)) from None
        deadline = time.monotonic() + timeout_s
        with self._changed:
            while request_id not in self._replies:
                if self._closed is not None:
                    raise TruthLost(self._closed)
                if time.monotonic() > deadline:
                    raise TruthLost("the simulator did not answer {} within {:.0f} s".format(name, timeout_s))
                self._changed.wait(0.05)
            reply = self._replies.pop(request_id)
        if "error" in reply:
            raise TruthLost("the simulator refused {}: {}".format(name, reply["error"]))
        return reply

    def close(self):
        try:
            self._socket.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self._socket.close()
