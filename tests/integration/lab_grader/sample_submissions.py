"""Sample submissions for the grader's tests, made from the lab's own Week 4 reference package (never from real
students' code): the reference as it is, and copies with one typical mistake each, written as a student would
make it. `make_submission(name, folder)` writes one into `folder/<name>/`."""
import shutil
from pathlib import Path

REFERENCE = Path(__file__).resolve().parents[3] / "catkin_ws" / "src" / "exercises" / "week4_services"

MISTAKES = {
    # name: {file in the package: [(text in the reference, what the student wrote instead)]}
    "reference": {},
    "wrong_direction": {"nodes/move_server.py": [("FORWARD_SPEED_MPS = 0.1", "FORWARD_SPEED_MPS = -0.1")]},
    "old_message_package": {"nodes/move_server.py": [("from tuos_msgs.srv", "from com2009_msgs.srv")],
                            "package.xml": [("<depend>tuos_msgs</depend>",
                                             "<depend>tuos_msgs</depend>\n  <depend>com2009_msgs</depend>")]},
    "does_not_build": {"CMakeLists.txt": [("catkin_python_setup()", "catkin_python_setup(\n")]},
    "hangs_in_the_callback": {"nodes/move_server.py": [
        ("        if not request.request_signal:",
         "        rospy.sleep(1e6)\n        if not request.request_signal:")]},
    "busy_waits": {"nodes/move_server.py": [
        ("        if not request.request_signal:", "        while True:\n            pass\n"
                                                    "        if not request.request_signal:")]},
}


def make_submission(name: str, folder: Path) -> Path:
    """The submission `name` (a key of MISTAKES) as a student folder holding the package; returns the folder."""
    student = Path(folder) / name
    package = student / "week4_services"
    shutil.copytree(REFERENCE, package, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for relative, replacements in MISTAKES[name].items():
        path = package / relative
        text = path.read_text()
        for old, new in replacements:
            assert old in text, "the reference changed: {} no longer has {!r}".format(relative, old)
            text = text.replace(old, new, 1)
        path.write_text(text)
    return student
