"""The reports' drawing modules (matplotlib, and tb3_sim's scene for the worlds), imported when a picture is first
drawn rather than when the grader starts: their import took 0.7 s of an idle machine's start-up, and 2-3 s at load
10, before the first line of progress, while a grading needs them only for its report, after the checks. `warm()`
imports them on a thread of their own as grading starts (the packages build meanwhile), so they are ready when the
first report is drawn. No ROS import."""
import importlib
import threading

MODULES = ("lab_grader.trajectory_picture", "lab_grader.summary_html")


def warm() -> None:
    """Import MODULES on a daemon thread (an import the main thread needs meanwhile waits for it: Python's import
    lock is per module)."""
    threading.Thread(target=lambda: [importlib.import_module(name) for name in MODULES], name="warm-pictures",
                     daemon=True).start()
