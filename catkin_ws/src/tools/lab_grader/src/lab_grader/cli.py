"""`sudo -E rosrun lab_grader grade`: grade a class (or one submission, or one shard of a class) against a suite.

    sudo -E rosrun lab_grader grade submissions/ --suite week4 --out grades/        every student, 2 at a time
    sudo -E rosrun lab_grader grade alice.zip --suite week4 --out grades/           one submission
    sudo -E rosrun lab_grader grade submissions/ --suite week4 --out grades/2 --shard 2/4   a job array's piece
    sudo -E rosrun lab_grader grade --merge grades/1 grades/2 grades/3 --out grades/   the class files

It must run as root (it makes a network namespace and a sandbox user per worker): `sudo -E rosrun lab_grader grade
...` in a ROS terminal, the one form the README uses everywhere. Exit 0 when every submission was graded (whatever
the scores), 2 for bad arguments (a path that does not exist among them, told in one line) or submissions that
could not be read.
"""
import argparse
import os
import shlex
import shutil
import sys
import tempfile
from pathlib import Path

import rospkg

from lab_grader import pictures
from lab_grader.batch import Progress, grade_all, parse_shard
from lab_grader.class_report import read_results, write_class_report
from lab_grader.grade import SubmissionGrader
from lab_grader.sandbox import reserve_slot
from lab_grader.submissions import SubmissionError, find_submissions
from lab_grader.suite_file import SuiteError, load_suite


def lab_root() -> Path:
    """The lab checkout: lab_grader lives in <lab>/catkin_ws/src/tools/lab_grader."""
    return Path(rospkg.RosPack().get_path("lab_grader")).resolve().parents[3]


def command_as_root(argv):
    """The command that grades `argv` as root: `sudo -E` keeps the ROS variables rosrun needs to find the grader
    (plain sudo drops them: "package 'lab_grader' not found"), and the grader restores the rest (nodes/grade)."""
    return " ".join(["sudo -E rosrun lab_grader grade", *(shlex.quote(arg) for arg in argv)])


def faster_than_calibrated(rtf, suite_rtf):
    """The note printed when --rtf runs the simulator faster than the suite's own factor: the nodes must then
    process their sensors' messages (a camera's 1920x1080 frames) that much faster, and on a loaded machine a node
    that falls behind them is judged on what it did (Part 6's calibration graded at 2x beside other work: the
    reference stopped 11 degrees past two pillars, the course template found three pillars of four)."""
    return ("grade: note: the simulator at {:g}x, faster than the {:g}x this suite is calibrated at: a node that "
            "falls behind its sensors on this machine at that speed is judged on what it did".format(rtf, suite_rtf))


def parse_args(argv):
    parser = argparse.ArgumentParser(prog="grade", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("paths", nargs="+", type=Path,
                        help="a submission (a package folder, .zip or .tar.gz) or a folder of them, one per "
                             "student; with --merge, the output folders of the shards")
    parser.add_argument("--suite", default="week4", help="a suite name (week4) or a suite YAML file")
    parser.add_argument("--out", type=Path, required=True, help="output folder (one subfolder per student)")
    parser.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1,
                        help="submissions graded at once (default: the number of cores)")
    parser.add_argument("--shard", help="K/N: grade only the K-th of N pieces of the class")
    parser.add_argument("--rtf", type=float, help="simulator real-time factor (default: the suite's)")
    parser.add_argument("--merge", action="store_true", help="combine shard output folders into the class files")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    missing = [path for path in args.paths if not path.exists()]
    if missing:
        print("grade: {} does not exist".format(", ".join(map(str, missing))), file=sys.stderr)
        return 2
    if args.merge:
        try:
            results = read_results(args.paths)
        except ValueError as error:
            print("grade: {}".format(error), file=sys.stderr)
            return 2
        args.out.mkdir(parents=True, exist_ok=True)
        write_class_report(results, args.out)
        print("grade: merged {} students into {}".format(len(results), args.out))
        return 0
    if os.geteuid() != 0:
        print("grade: must run as root (each submission gets its own network namespace and sandbox user); type:\n"
              "    {}".format(command_as_root(sys.argv[1:] if argv is None else argv)), file=sys.stderr)
        return 2
    try:
        suite = load_suite(args.suite)
        shard = parse_shard(args.shard) if args.shard else None
        if args.jobs < 1:
            raise ValueError("--jobs must be at least 1")
    except (SuiteError, ValueError) as error:
        print("grade: {}".format(error), file=sys.stderr)
        return 2
    work_root = Path(tempfile.mkdtemp(prefix="lab_grader-"))
    os.chmod(work_root, 0o711)   # the sandbox users must reach their own workspace inside
    try:
        return grade_class(args, suite, shard, work_root)
    except SubmissionError as error:   # a submission named on the command line that cannot be read
        print("grade: {}".format(error), file=sys.stderr)
        return 2
    finally:
        shutil.rmtree(work_root, ignore_errors=True)   # unpacked submissions and empty box folders


def grade_class(args, suite, shard, work_root):
    """Grade the submissions `args.paths` name (this shard of them) with `work_root` as scratch space."""
    submissions, rejected = [], []
    for path in args.paths:
        scan = find_submissions(path, work_root / "sources")
        submissions += scan.submissions
        rejected += scan.rejected
    for error in rejected:
        print("grade: skipped {}".format(error), file=sys.stderr)
    submissions.sort(key=lambda submission: submission.student_id)
    if shard:
        submissions = shard.pick(submissions)
    args.out.mkdir(parents=True, exist_ok=True)
    jobs = min(args.jobs, max(1, len(submissions)))
    print("grade: {} submissions, suite {}, {} at a time{}".format(
        len(submissions), suite.name, jobs, ", shard {}/{}".format(*shard) if shard else ""))
    if args.rtf is not None and args.rtf > suite.real_time_factor:
        print(faster_than_calibrated(args.rtf, suite.real_time_factor))

    reservations = []

    def make_grader():   # called by each worker thread
        reservation = reserve_slot()   # a slot no other worker on this machine uses meanwhile
        reservations.append(reservation)
        return SubmissionGrader(suite, work_root / "boxes", lab_root(), reservation.slot, dict(os.environ), args.rtf)

    (work_root / "boxes").mkdir(mode=0o711)
    pictures.warm()   # the reports' matplotlib, imported while the first packages build
    try:
        grade_all(submissions, make_grader, args.out, jobs, Progress(len(submissions)))
    finally:
        for reservation in reservations:
            reservation.release()
    write_class_report(read_results([args.out]), args.out)
    print("grade: results in {} (class.csv, summary.json, one folder per student)".format(args.out))
    return 2 if rejected else 0
