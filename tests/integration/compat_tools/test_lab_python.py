"""The Python the lab's nodes run on (`#!/usr/bin/env python3` in a terminal that sourced scripts/env.sh: the venv)
imports what the courses' example nodes import: pandas, OpenCV with cv_bridge, matplotlib (headless) and SciPy."""
import subprocess

CHECK = """
import matplotlib
matplotlib.use("Agg")
import cv2, cv_bridge, numpy, pandas, scipy.spatial.transform
import matplotlib.pyplot as plt
image = numpy.zeros((4, 6, 3), numpy.uint8)
message = cv_bridge.CvBridge().cv2_to_imgmsg(image, "bgr8")
assert cv_bridge.CvBridge().imgmsg_to_cv2(message, "bgr8").shape == (4, 6, 3)
assert cv2.cvtColor(image, cv2.COLOR_BGR2HSV).shape == (4, 6, 3)
assert pandas.DataFrame({"x": [1.0, 2.0]})["x"].mean() == 1.5
assert abs(scipy.spatial.transform.Rotation.from_euler("z", 90, degrees=True).as_quat()[3] - 0.7071) < 1e-3
plt.plot([0, 1], [0, 1])
import sys
print(sys.executable)
"""


def test_the_lab_python_imports_the_course_libraries():
    result = subprocess.run(["/usr/bin/env", "python3", "-c", CHECK], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip().endswith(".venv/bin/python3")
