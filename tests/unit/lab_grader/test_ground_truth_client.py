"""The grader's end of the simulator's private ground-truth channel, against a scripted server on a real Unix
socket: the simulator's sim time and samples, what came after a mark (samples, world changes, paused heartbeats), a
request answered, and a channel that closes or never opens failing clearly."""
import json
import socket
import threading

import pytest

from lab_grader.checks.ground_truth import TruthClient, TruthLost, WorldChange
from lab_grader.checks.motion import Sample

HELLO = {"kind": "hello", "node": "/gazebo", "uri": "http://localhost:40000/", "robot": "turtlebot3_waffle"}


def state(t, x=0.0, v=0.0, paused=False):
    return {"kind": "state", "t": t, "x": x, "y": 0.0, "yaw": 0.0, "v": v, "w": 0.0, "paused": paused}


class ScriptedSimulator:
    """Accepts one client, sends `hello`, then whatever `send` is given; answers each request with `t` = 7.0."""

    def __init__(self, path):
        self.server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.server.bind(str(path))
        self.server.listen(1)
        self.client = None
        self.accepted = threading.Event()
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        self.client, _ = self.server.accept()
        self.send(HELLO)
        self.accepted.set()
        for line in self.client.makefile("rb"):
            request = json.loads(line)
            self.send({"kind": "reply", "id": request["id"], "t": 7.0, "front_m": 0.42})

    def send(self, message):
        self.client.sendall((json.dumps(message) + "\n").encode())

    def close(self):
        self.client.shutdown(socket.SHUT_RDWR)
        self.client.close()
        self.server.close()


@pytest.fixture
def simulator(tmp_path):
    path = tmp_path / "truth.sock"
    scripted = ScriptedSimulator(path)
    client = TruthClient(path, connect_timeout_s=5)
    scripted.accepted.wait(5)
    yield scripted, client
    client.close()


def wait_for(client, condition):
    for _ in range(500):
        if condition():
            return
        client.wait(0.01)
    raise AssertionError("the client never saw it")


def test_the_simulators_time_samples_and_what_came_after_a_mark(simulator):
    scripted, client = simulator
    assert client.identity == {key: HELLO[key] for key in ("node", "uri", "robot")}
    scripted.send(state(1.0))
    wait_for(client, lambda: client.latest is not None)
    mark = client.mark()
    scripted.send(state(1.1, x=0.01, v=0.1))
    scripted.send({"kind": "event", "t": 1.1, "what": "pause_physics", "detail": ""})
    scripted.send(state(1.1, x=0.01, paused=True))
    wait_for(client, lambda: client.since(mark).paused_at)
    seen = client.since(mark)
    assert seen.samples == (Sample(1.1, 0.01, 0.0, 0.0, 0.1, 0.0),)
    assert seen.changes == (WorldChange(1.1, "pause_physics", ""),)
    assert seen.paused_at == (1.1,) and client.now() == pytest.approx(1.1)
    assert seen.changes[0].words() == "called /gazebo/pause_physics at 1.10 s"


def test_a_request_gets_its_reply_and_a_closed_channel_fails_every_wait(simulator):
    scripted, client = simulator
    assert client.request("front_distance")["front_m"] == 0.42
    scripted.close()
    with pytest.raises(TruthLost, match="closed the ground-truth channel"):
        for _ in range(500):
            client.wait(0.01)


def test_no_simulator_at_the_path_is_a_clear_error(tmp_path):
    with pytest.raises(TruthLost, match="cannot reach the simulator's ground-truth channel"):
        TruthClient(tmp_path / "nothing.sock", connect_timeout_s=0.3)
