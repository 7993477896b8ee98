"""bubblewrap's command line for a student process: the host read-only, the workspace the only writable host
folder, covers (the work root, /tmp, /dev/shm) mounted before the workspace is bound back, every namespace but the
network one new, and the student named in /etc/passwd."""
from pathlib import Path

from lab_grader.bwrap import bwrap_args, passwd_with_student

LAB = Path("/work/main")
WORK = Path("/srv/grading")
WORKSPACE = WORK / "slot3-abc" / "workspace"


def args(**overrides):
    options = dict(lab_root=LAB, work_root=WORK, workspace=WORKSPACE, cwd=WORKSPACE, tmp_bytes=1000, passwd_fd=7)
    options.update(overrides)
    return bwrap_args(**options)


def mounts(argv, option):
    """The destinations of every `option SRC DEST` (or `option DEST` for one-operand options), in order."""
    operands = {"--ro-bind": 2, "--bind": 2, "--symlink": 2, "--ro-bind-data": 2, "--tmpfs": 1, "--proc": 1,
                "--dev": 1, "--remount-ro": 1}[option]
    return [argv[i + operands] for i, word in enumerate(argv) if word == option]


def test_only_the_workspace_is_bound_writable_and_the_host_parts_are_read_only():
    argv = args()
    assert mounts(argv, "--bind") == [str(WORKSPACE)]
    assert mounts(argv, "--ro-bind") == ["/usr", "/etc", str(LAB)]
    assert mounts(argv, "--ro-bind-data") == ["/etc/passwd"]
    assert set(mounts(argv, "--symlink")) <= {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}
    assert mounts(argv, "--tmpfs") == ["/dev/shm", "/tmp", str(WORK)]
    assert mounts(argv, "--remount-ro") == ["/dev", str(WORK)]
    assert "--dev-bind" not in argv and "--share-net" not in argv and "--unshare-net" not in argv


def test_covers_come_before_the_workspace_and_are_made_read_only_after_it():
    argv = args()
    position = {(word, argv[i + 1]): i for i, word in enumerate(argv) if word in ("--tmpfs", "--remount-ro")}
    bind = argv.index("--bind")
    assert position[("--tmpfs", "/tmp")] < bind and position[("--tmpfs", str(WORK))] < bind
    assert position[("--remount-ro", str(WORK))] > bind


def test_sizes_namespaces_and_session():
    argv = args()
    assert [argv[i + 1] for i, word in enumerate(argv) if word == "--size"] == ["1000", "1000", "1048576"]
    for option in ("--unshare-user", "--disable-userns", "--unshare-pid", "--unshare-ipc", "--unshare-uts",
                   "--die-with-parent", "--new-session"):
        assert option in argv
    assert argv[argv.index("--chdir") + 1] == str(WORKSPACE)
    assert argv[argv.index("--ro-bind-data") + 1] == "7"


def test_without_a_passwd_fd_the_hosts_passwd_is_used():
    assert "--ro-bind-data" not in args(passwd_fd=None)


def test_the_students_passwd_line_is_added_to_the_hosts(tmp_path):
    host = tmp_path / "passwd"
    host.write_text("root:x:0:0:root:/root:/bin/bash")
    lines = passwd_with_student(61003, 61003, WORKSPACE, host).decode().splitlines()
    assert lines == ["root:x:0:0:root:/root:/bin/bash",
                     "student:x:61003:61003:lab_grader sandbox:{}:/bin/sh".format(WORKSPACE)]


def test_a_lab_checked_out_below_tmp_is_bound_after_tmp_is_covered():
    """A CI clone in /tmp: the private /tmp must not hide the lab (its venv, devel space and libraries)."""
    lab = Path("/tmp/ci-clone")
    argv = args(lab_root=lab)
    lab_bind = [i for i, word in enumerate(argv) if word == "--ro-bind" and argv[i + 2] == str(lab)]
    tmp_cover = [i for i, word in enumerate(argv) if word == "--tmpfs" and argv[i + 1] == "/tmp"]
    assert lab_bind and tmp_cover and tmp_cover[0] < lab_bind[0]
