"""Pictures of lab_grader's output for the README (run through scripts/grade_screenshots, as root, from a ROS
terminal):

    python3 tests/bench/grade_screenshots.py [output folder, default docs/images]

Grades one copy of each sample submission (tests/integration/lab_grader/sample_submissions.py) with the Week 4
suite at real-time factor 2, 2 at a time, then renders in a headless Chromium (roslab.browser):
- lab_grader_summary.png: the class summary (score histogram, most failed checks, the students);
- lab_grader_report.png: the report of `wrong_direction` (a failed check with its reason and evidence, and the
  trajectories over the world).
Takes a few minutes.
"""
import subprocess
import sys
import tempfile
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(TESTS))

from integration.lab_grader.sample_submissions import SELF_CONTAINED, make_submission  # noqa: E402

from roslab.browser import HeadlessBrowser  # noqa: E402

REPO_ROOT = TESTS.parent
REPORT_OF = "wrong_direction"


def say(text):
    print("grade_screenshots: " + text, flush=True)


def main(out_dir):
    out_dir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="grade-screenshots-") as workdir:
        work = Path(workdir)
        for name in SELF_CONTAINED:
            make_submission(name, work / "class")
        say("grading {} sample submissions (a few minutes)".format(len(SELF_CONTAINED)))
        subprocess.run(["rosrun", "lab_grader", "grade", str(work / "class"), "--suite", "week4", "--out",
                        str(work / "grades"), "--jobs", "2", "--rtf", "2"], check=True)
        browser = HeadlessBrowser()
        try:
            for page, picture in ((work / "grades" / "summary.html", "lab_grader_summary.png"),
                                  (work / "grades" / REPORT_OF / "report.html", "lab_grader_report.png")):
                browser.driver.get(page.as_uri())
                browser.save_full_page(out_dir / picture)
                say("wrote {}".format(out_dir / picture))
                errors = browser.console_errors()
                if errors:
                    say("console errors on {}: {}".format(page.name, errors))
        finally:
            browser.quit()


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else REPO_ROOT / "docs" / "images")
