"""The submission sandbox contains real processes: no network but its own loopback (shared with its trusted
processes, private from other boxes: two roscores on 11311 at once), no reading other submissions or writing
outside its workspace, no signalling the grader's processes, no new user namespaces, and limits that stop fork
bombs, busy loops, sleepers, memory hogs and floods of output. When a box closes, nothing of it is left: no
process of its uid, nothing in its network namespace, no namespace holder, no workspace."""
import os
import signal
import sys
import time

import pytest

from lab_grader import procfs
from lab_grader.errors import SandboxError
from lab_grader.sandbox import GRADER_SLOTS, MIB, STUDENT_NICENESS, SubmissionSandbox, reserve_slot
from lab_grader.sandbox_process import StopReason

from .conftest import LAB_ROOT, SLOT_A, TEST_LIMITS, last_json

PYTHON = sys.executable  # the lab's venv python, which lives in the (read-only) lab checkout
HTTP_PORT = 8765
WAIT_FOR_PORT = """
import socket, sys, time
deadline = time.monotonic() + 10
while time.monotonic() < deadline:
    try:
        socket.create_connection(("127.0.0.1", int(sys.argv[1])), 0.2).close()
        break
    except OSError:
        time.sleep(0.05)
"""
NETWORK_PROBE = """
import errno, json, socket, sys, time, urllib.request
report = {}
try:
    socket.create_connection(("1.1.1.1", 80), timeout=5).close()
    report["internet"] = "connected"
except OSError as error:
    report["internet"] = errno.errorcode.get(error.errno, str(error))
deadline = time.monotonic() + 10
while True:
    try:
        report["loopback"] = urllib.request.urlopen("http://127.0.0.1:%d/hello.txt" % int(sys.argv[1]),
                                                    timeout=1).read().decode()
        break
    except OSError as error:
        if time.monotonic() > deadline:
            report["loopback"] = str(error)
            break
        time.sleep(0.05)
print(json.dumps(report))
"""


def test_a_student_reaches_its_boxs_loopback_but_no_other_host(box, env, tmp_path):
    served = tmp_path / "served"
    served.mkdir()
    (served / "hello.txt").write_text("hello from the grader")
    box.start_trusted([PYTHON, "-m", "http.server", "--bind", "127.0.0.1", str(HTTP_PORT)], env,
                      tmp_path / "http.log", cwd=served)
    result = box.run_student([PYTHON, "-c", NETWORK_PROBE, str(HTTP_PORT)], env, tmp_path / "probe.log")
    assert result.ok, (tmp_path / "probe.log").read_text()
    report = last_json(tmp_path / "probe.log")
    assert report["internet"] == "ENETUNREACH", "no route at all (not a timeout): the box has only loopback"
    assert report["loopback"] == "hello from the grader"


def test_two_boxes_each_run_a_roscore_on_11311_at_once_and_their_students_use_it(box, other_box, env, tmp_path):
    trusted_env = dict(env, ROS_HOME=str(tmp_path / "ros"), ROS_LOG_DIR=str(tmp_path / "ros" / "log"))
    for name, sandbox in (("alice", box), ("bob", other_box)):
        sandbox.start_trusted(["roscore", "-p", "11311"], trusted_env, tmp_path / "roscore_{}.log".format(name))
    for name, sandbox in (("alice", box), ("bob", other_box)):
        node = "import rospy; rospy.init_node(\"student\"); rospy.set_param(\"/owner\", \"{}\")".format(name)
        script = "{0} -c '{1}' 11311 && {0} -c '{2}' && rosparam get /owner".format(PYTHON, WAIT_FOR_PORT, node)
        log = tmp_path / "student_{}.log".format(name)
        result = sandbox.run_student(["sh", "-c", script], env, log)
        assert result.ok and log.read_text().strip() == name, log.read_text()
    for name, sandbox in (("alice", box), ("bob", other_box)):
        log = tmp_path / "check_{}.log".format(name)
        assert sandbox.run_trusted(["rosparam", "get", "/owner"], trusted_env, log).ok
        assert log.read_text().strip() == name, "each box's master kept its own parameter"
    assert list((box.workspace / ".ros" / "log").glob("student*.log")), "the node logged into the workspace"


FILE_PROBE = """
import json, sys
report = {}
for path in sys.argv[1:]:
    try:
        with open(path, "a"):
            pass
        report[path] = "written"
    except OSError as error:
        report[path] = type(error).__name__
print(json.dumps(report))
"""


def test_a_student_cannot_read_another_submission_nor_write_outside_its_workspace(box, other_box, env, tmp_path):
    secret = other_box.workspace / "solution.py"
    secret.write_text("the other student's answer")
    os.chmod(secret, 0o644)  # readable by anyone who can see it: only the sandbox hides it
    read = box.run_student(["cat", str(secret)], env, tmp_path / "read.log")
    assert read.returncode == 1 and "No such file or directory" in (tmp_path / "read.log").read_text()
    listing = box.run_student(["ls", "-a", str(box.work_root)], env, tmp_path / "ls.log")
    assert listing.ok and (tmp_path / "ls.log").read_text().split() == [".", "..", box.workspace.parent.name]

    targets = {"lab checkout": LAB_ROOT / "graded.txt", "work root": box.work_root / "graded.txt",
               "other workspace": other_box.workspace / "graded.txt", "etc": "/etc/graded.txt",
               "usr": "/usr/graded.txt", "root's home": "/root/graded.txt", "passwd": "/etc/passwd",
               "shadow": "/etc/shadow", "own workspace": box.workspace / "graded.txt", "tmp": "/tmp/graded.txt"}
    result = box.run_student([PYTHON, "-c", FILE_PROBE] + [str(path) for path in targets.values()], env,
                             tmp_path / "write.log")
    assert result.ok, (tmp_path / "write.log").read_text()
    report = last_json(tmp_path / "write.log")
    outcome = {name: report[str(path)] for name, path in targets.items()}
    # OSError is EROFS (a read-only mount); FileNotFoundError: the folder does not exist in the sandbox's view.
    assert outcome == {"lab checkout": "OSError", "work root": "OSError", "other workspace": "FileNotFoundError",
                       "etc": "OSError", "usr": "OSError", "root's home": "FileNotFoundError", "passwd": "OSError",
                       "shadow": "PermissionError", "own workspace": "written", "tmp": "written"}, outcome
    assert (box.workspace / "graded.txt").stat().st_uid == box.uid
    for name in ("lab checkout", "work root", "other workspace", "etc", "usr", "root's home", "tmp"):
        assert not os.path.exists(targets[name]), "{} was written on the host".format(name)


def test_a_student_cannot_signal_the_trusted_processes_of_its_box(box, env, tmp_path):
    trusted = box.start_trusted(["sleep", "60"], env, tmp_path / "sleep.log")
    attack = ("import json, os, signal\nreport = {}\n"
              "try:\n    os.kill(%d, signal.SIGKILL)\n    report['kill'] = 'sent'\n"
              "except OSError as error:\n    report['kill'] = type(error).__name__\n"
              "print(json.dumps(report))\n" % trusted.pid)
    result = box.run_student([PYTHON, "-c", attack], env, tmp_path / "attack.log")
    assert result.ok, (tmp_path / "attack.log").read_text()
    # The pid namespace hides the grader's processes altogether (ProcessLookupError); without it, the other uid
    # would refuse the signal (PermissionError).
    assert last_json(tmp_path / "attack.log")["kill"] in ("ProcessLookupError", "PermissionError")
    box.run_student(["kill", "-KILL", "-1"], env, tmp_path / "kill_all.log")
    time.sleep(0.2)
    assert trusted.running(), "the grader's process survived"


def test_a_student_cannot_create_user_namespaces(box, env, tmp_path):
    result = box.run_student(["unshare", "--user", "--map-root-user", "id"], env, tmp_path / "unshare.log")
    assert result.returncode == 1 and "unshare failed" in (tmp_path / "unshare.log").read_text()


FORK_BOMB = """
import errno, os, time
forked = 0
try:
    for _ in range(1000):
        if os.fork() == 0:
            time.sleep(1000)
            os._exit(0)
        forked += 1
    print("forked", forked, "without error", flush=True)
except OSError as error:
    print("forked", forked, "then", errno.errorcode[error.errno], flush=True)
time.sleep(1000)
"""


def test_a_fork_bomb_hits_the_process_limit_and_the_box_still_cleans_up(work_root, env, tmp_path):
    log = tmp_path / "bomb.log"
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, TEST_LIMITS) as sandbox:
        sandbox.start_student([PYTHON, "-c", FORK_BOMB], env, log)
        deadline = time.monotonic() + 10
        while not log.read_text() and time.monotonic() < deadline:
            time.sleep(0.05)
        words = log.read_text().split()
        assert words[:1] == ["forked"] and words[2:] == ["then", "EAGAIN"], log.read_text()
        assert len(sandbox.student_processes()) <= TEST_LIMITS.processes
        uid, holder = sandbox.uid, sandbox.netns_holder_pid
    assert procfs.processes_of_uid(uid) == [] and procfs.process_info(holder) is None


def test_a_busy_loop_is_stopped_by_the_cpu_limit(box, env, tmp_path):
    result = box.run_student([PYTHON, "-c", "while True: pass"], env, tmp_path / "busy.log")
    assert result.stop_reason == StopReason.CPU_LIMIT and result.signal == signal.SIGXCPU


def test_a_sleeper_is_stopped_by_the_wall_timeout_at_once(box, env, tmp_path):
    result = box.run_student(["sleep", "1000"], env, tmp_path / "sleep.log", timeout_s=1.0)
    assert result.stop_reason == StopReason.TIMEOUT and result.returncode is None
    assert result.duration_s >= 1.0
    assert box.student_processes() == [], "the sleeper is gone now, not only when the box closes"


def test_a_memory_hog_fails_to_allocate_beyond_the_address_space_limit(box, env, tmp_path):
    result = box.run_student([PYTHON, "-c", "hog = bytearray({})".format(TEST_LIMITS.memory_bytes)], env,
                             tmp_path / "hog.log")
    assert result.returncode == 1 and "MemoryError" in (tmp_path / "hog.log").read_text()


def test_printing_50_mb_leaves_a_log_no_bigger_than_the_cap_marked_truncated(box, env, tmp_path):
    log = tmp_path / "flood.log"
    result = box.run_student(["sh", "-c", "head -c 50000000 /dev/zero | tr '\\0' x"], env, log)
    assert result.ok and result.truncated, "the program ran to its end, its output was cut"
    assert log.stat().st_size <= TEST_LIMITS.output_bytes
    assert log.read_bytes().startswith(b"xxxx") and b"output truncated" in log.read_bytes()[-200:]


def test_the_whole_workspace_is_capped_not_only_each_file(work_root, env, tmp_path):
    """Files under the per-file cap add up to no more than workspace_bytes: the write past it fails with ENOSPC,
    as on a full disk, and the box still closes cleanly."""
    limits = TEST_LIMITS._replace(file_bytes=6 * MIB, workspace_bytes=16 * MIB)
    writes = "for i in 1 2 3 4 5; do head -c {} /dev/zero > part$i || exit 9; done".format(5 * MIB)
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, limits) as sandbox:
        result = sandbox.run_student(["sh", "-c", writes], env, tmp_path / "fill.log")
        assert result.returncode == 9 and "No space left on device" in (tmp_path / "fill.log").read_text()
        written = sum(path.stat().st_size for path in sandbox.workspace.iterdir())
        assert 10 * MIB < written <= 16 * MIB
        box_dir = sandbox.workspace.parent
    assert not box_dir.exists()


def test_a_trusted_process_reads_the_lines_the_grader_sends_until_the_pipe_ends(box, env, tmp_path):
    """The check runner's command pipe: each line arrives as sent, the end of the pipe ends the reader, and a line
    sent to a process that has exited is refused instead of raising."""
    reader = box.start_trusted([PYTHON, "-c", "import sys\nfor line in sys.stdin:\n    print('got', line.strip(), "
                                "flush=True)"], env, tmp_path / "reader.log", commands=True)
    assert reader.send_line('{"exercise": "move_server.py"}') and reader.send_line("second")
    reader.close_input()
    result = reader.wait(10)
    assert result.ok, (tmp_path / "reader.log").read_text()
    assert (tmp_path / "reader.log").read_text().splitlines() == ['got {"exercise": "move_server.py"}', "got second"]
    assert reader.send_line("too late") is False


def test_a_short_output_is_kept_whole(box, env, tmp_path):
    result = box.run_student(["sh", "-c", "echo out; echo err >&2; exit 3"], env, tmp_path / "short.log")
    assert result.returncode == 3 and result.stop_reason is None and not result.truncated
    assert sorted((tmp_path / "short.log").read_text().split()) == ["err", "out"]


def test_student_processes_run_below_the_trusted_ones(box, env, tmp_path):
    """Niceness 10: a busy-waiting student must not starve the simulator that measures it (stat field 19)."""
    result = box.run_student(["sh", "-c", "cat /proc/self/stat"], env, tmp_path / "stat.log")
    assert result.ok
    assert (tmp_path / "stat.log").read_text().rsplit(")", 1)[1].split()[16] == str(STUDENT_NICENESS)


PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>alice_pkg</name><version>0.0.1</version><description>a submission</description>
  <maintainer email="alice@example.org">alice</maintainer><license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""
CMAKELISTS = ("cmake_minimum_required(VERSION 3.0.2)\nproject(alice_pkg)\nfind_package(catkin REQUIRED)\n"
              "catkin_package()\n")


def test_a_submission_copied_into_the_workspace_builds_with_catkin_make_on_top_of_the_lab(work_root, env, tmp_path):
    source = tmp_path / "alice" / "alice_pkg"
    source.mkdir(parents=True)
    (source / "package.xml").write_text(PACKAGE_XML)
    (source / "CMakeLists.txt").write_text(CMAKELISTS)
    (source / "notes").symlink_to("/etc/shadow")
    build_limits = TEST_LIMITS._replace(cpu_s=60, processes=64, output_bytes=1024 * 1024)
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, build_limits) as sandbox:
        src = sandbox.copy_into_workspace(source.parent, "src")
        assert os.readlink(src / "alice_pkg" / "notes") == "/etc/shadow", "copied as a symlink, not followed"
        assert {path.lstat().st_uid for path in [src, *src.rglob("*")]} == {sandbox.uid}
        build = sandbox.run_student(["catkin_make"], env, tmp_path / "build.log")
        assert build.ok, (tmp_path / "build.log").read_text()[-3000:]
        find = sandbox.run_student(["bash", "-c", "source devel/setup.bash && rospack find alice_pkg && "
                                    "rospack find turtlesim"], env, tmp_path / "find.log")
        assert find.ok and (tmp_path / "find.log").read_text().split() == [
            str(src / "alice_pkg"), str(LAB_ROOT / "catkin_ws" / "src" / "simulators" / "turtlesim")]


def test_root_never_writes_through_the_students_workspace(box, env, tmp_path):
    """The workspace belongs to the student's uid: the grader (root) refuses to copy or log where a student could
    have planted a symlink, or while a student process could plant one."""
    (tmp_path / "package").mkdir()
    box.run_student(["ln", "-s", "/etc", "evil"], env, tmp_path / "ln.log")
    with pytest.raises(SandboxError, match="leads outside the workspace"):
        box.copy_into_workspace(tmp_path / "package", "evil/planted")
    assert not os.path.exists("/etc/planted")
    with pytest.raises(SandboxError, match="must not be inside the student's workspace"):
        box.run_trusted(["true"], env, box.workspace / "evil" / "planted.log")
    with pytest.raises(SandboxError, match="must not be inside the student's workspace"):
        box.run_student(["true"], env, box.workspace / "build.log")
    sleeper = box.start_student(["sleep", "60"], env, tmp_path / "sleep.log")
    with pytest.raises(SandboxError, match="while no student process runs"):
        box.copy_into_workspace(tmp_path / "package", "src")
    sleeper.stop()
    assert box.copy_into_workspace(tmp_path / "package", "src") == box.workspace / "src"


def test_after_the_box_closes_nothing_of_it_remains(work_root, env, tmp_path):
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, TEST_LIMITS) as sandbox:
        # A student's daemon that double-forks out of its parent, and a trusted one that leaves its session.
        sandbox.start_student(["sh", "-c", "(sleep 1000 &); sleep 1000"], env, tmp_path / "student.log")
        sandbox.start_trusted(["setsid", "sh", "-c", "sleep 1000 & echo started"], env, tmp_path / "trusted.log")
        deadline = time.monotonic() + 5
        while len(sandbox.student_processes()) < 4 and time.monotonic() < deadline:
            time.sleep(0.05)
        uid, holder, namespace = sandbox.uid, sandbox.netns_holder_pid, sandbox.net_namespace
        box_dir = sandbox.workspace.parent
        in_namespace = procfs.processes_in_net_namespace(namespace)
        assert len(in_namespace) >= 5 and holder in in_namespace
    assert procfs.processes_of_uid(uid) == []
    assert procfs.processes_in_net_namespace(namespace) == []
    assert procfs.process_info(holder) is None
    assert not box_dir.exists()
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, TEST_LIMITS):
        pass  # the slot is free again


def test_grader_workers_reserve_distinct_slots_machine_wide():
    """Two workers (of one grade run, or of two at once) never hold the same slot, and a released slot can be
    reserved again."""
    first, second = reserve_slot(), reserve_slot()
    try:
        assert first.slot != second.slot and {first.slot, second.slot} <= set(range(GRADER_SLOTS))
        first.release()
        third = reserve_slot()
        assert third.slot != second.slot
        third.release()
    finally:
        first.release()
        second.release()
