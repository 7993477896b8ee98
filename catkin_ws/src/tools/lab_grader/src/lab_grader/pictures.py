"""The report's drawing module (matplotlib, and tb3_sim's scene for the worlds), imported when a picture is first
drawn rather than when the grader starts: its import took 0.7 s of an idle machine's start-up, and 2-3 s at load
10, before the first line of progress, while a grading needs it only for its report, after the checks. `warm()`
imports it on a thread of its own as grading starts (the packages build meanwhile), so it is ready when the first
report is drawn. (The class summary's histogram is SVG: lab_grader.summary_html needs no plotting library.) No ROS
import."""
import importlib
import threading

MODULES = ("lab_grader.trajectory_picture",)


def warm() -> None:
    """Import MODULES on a daemon thread (an import the main thread needs meanwhile waits for it: Python's import
    lock is per module)."""
    threading.Thread(target=lambda: [importlib.import_module(name) for name in MODULES], name="warm-pictures",
                     daemon=True).start()
