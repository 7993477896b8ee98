"""A student's node reading /map (student_map_reader.py), run against a test's master."""
import json
import subprocess
import sys
from pathlib import Path

READER = Path(__file__).with_name("student_map_reader.py")
READER_TIMEOUT_S = 180   # rospy's start-up on a loaded machine, and the reader's own 60 s wait for /map


def read_map_as_a_student(env):
    """What the student's node saw: {"grid": rows, "free", "walls", "unknown": counts, "origin": [x, y]}."""
    reader = subprocess.run([sys.executable, str(READER)], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, timeout=READER_TIMEOUT_S)
    assert reader.returncode == 0, reader.stderr
    return json.loads(reader.stdout)
