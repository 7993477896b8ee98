"""TopicProbe: the test's eyes and hands on topics, through the probe node (see probe_node.py)."""
import json
import os
import select
import subprocess
import sys
import time
from pathlib import Path

import numpy

from roslab.waiting import wait_until

# The probe node runs as `python3 -m roslab.probe_node` with the folder holding roslab on its path, so that it
# can use the package's other modules.
ROSLAB_PARENT = Path(__file__).resolve().parents[1]


class ProbeError(RuntimeError):
    """The probe node could not do what the test asked; the text is the node's error."""


class TopicProbe:
    """A rospy node in a child process: subscribe, collect messages with their arrival times, publish.

    Create it through `RosMaster.probe()`, which ends it with the master's other processes.
    """

    def __init__(self, master, ready_timeout_s=30.0):
        env = dict(master.env, PYTHONPATH=os.pathsep.join(filter(None, [str(ROSLAB_PARENT),
                                                                          master.env.get("PYTHONPATH")])))
        self._process = subprocess.Popen([sys.executable, "-m", "roslab.probe_node"], env=env,
                                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                                         stderr=open(master.workdir / "probe.log", "w"), start_new_session=True)
        first = self._read_reply(ready_timeout_s)
        if not first.get("ready"):
            raise ProbeError("probe node did not start: {}".format(first))

    def _read_reply(self, timeout_s):
        readable, _, _ = select.select([self._process.stdout], [], [], timeout_s)
        if not readable:
            raise ProbeError("probe node did not answer within {} s".format(timeout_s))
        line = self._process.stdout.readline()
        if not line:
            raise ProbeError("probe node exited (code {})".format(self._process.poll()))
        return json.loads(line)

    def _ask(self, op, **args):
        self._process.stdin.write(json.dumps(dict(args, op=op)) + "\n")
        self._process.stdin.flush()
        reply = self._read_reply(60)
        if not reply.pop("ok"):
            raise ProbeError(reply["error"])
        return reply

    def subscribe(self, topic, msg_type, wait_s=5.0, image_file=None):
        """Subscribe to `topic`; waits up to `wait_s` for a publisher connection; returns the connections.

        With `image_file` (a path) the topic is an image topic: messages come back without their pixel data, and
        the latest image, decoded by cv_bridge, is kept at that path as a .npy file (see `latest_image`).
        """
        args = {} if image_file is None else {"image_file": str(image_file)}
        return self._ask("subscribe", topic=topic, type=msg_type, wait_s=wait_s, **args)["connections"]

    def subscribe_images(self, topics, folder):
        """Subscribe to each image topic of `topics` ({topic: type}) with its own .npy file in `folder` (see
        `subscribe`); returns {topic: path}, the files for `latest_image`."""
        files = {}
        for topic, msg_type in topics.items():
            files[topic] = Path(folder) / (topic.strip("/").replace("/", "_") + ".npy")
            self.subscribe(topic, msg_type, image_file=files[topic])
        return files

    @staticmethod
    def latest_image(image_file):
        """The latest image the probe decoded into `image_file` (a numpy array), or None before the first."""
        try:
            return numpy.load(image_file)
        except FileNotFoundError:
            return None

    def take(self, topic):
        """Messages received on `topic` since the last take: [{"wall", "ros", "msg"}, ...], oldest first."""
        return self._ask("take", topic=topic)["messages"]

    def collect(self, topic, duration_s):
        """Messages received during the next `duration_s` wall seconds (earlier ones are discarded)."""
        self.take(topic)
        time.sleep(duration_s)
        return self.take(topic)

    def wait_for_message(self, topic, timeout_s=20.0, predicate=lambda msg: True, interval_s=0.1):
        """The first message on `topic` (subscribed already) satisfying `predicate`, as a plain dict; the
        probe is asked every `interval_s` (shorten it for a fast topic when many waits add up)."""
        def matching():
            return next((entry["msg"] for entry in self.take(topic) if predicate(entry["msg"])), None)
        return wait_until(matching, timeout_s, "a matching message on " + topic, interval_s=interval_s)

    def publish(self, topic, msg_type, msg, wait_s=5.0):
        """Publish one message given as a dict, once every subscriber the master lists (at least one) has
        connected or `wait_s` has passed; returns how many were connected."""
        return self._ask("publish", topic=topic, type=msg_type, msg=msg, wait_s=wait_s)["subscribers"]

    def now(self):
        """The probe's rospy time in seconds (simulated when /use_sim_time was set before it started)."""
        return self._ask("now")["now"]

    def sleep_sim(self, seconds, timeout_s=30.0):
        """Return once `seconds` of the probe's time (sim time under /use_sim_time) have passed: a wait that
        means the same at any real-time factor, where a wall-clock sleep waits 3 sim seconds at 3x for what 1
        needs."""
        until_s = self.now() + seconds
        wait_until(lambda: self.now() >= until_s, timeout_s, "{} s of the probe's time".format(seconds))

    def interrupt(self):
        """Ask the probe to end (its stdin closed: it exits at the end of its input); stop() waits for it."""
        if self._process.poll() is None and not self._process.stdin.closed:
            self._process.stdin.close()

    def stop(self):
        self.interrupt()
        if self._process.poll() is None:
            try:
                self._process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
