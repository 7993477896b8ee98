"""What hostile sample submissions (sample_submissions.py) add to the reference move server: functions its main()
calls before it starts serving, each trying to get out of the grader's sandbox or to swamp it. What they find
they print, one JSON line, so a test reads the outcome from the node's log in the grader's output.

Placeholders (@NAME@) are Python literals the test fills in (make_submission's `fill`), since only the test knows
where it put the other submissions and which addresses this host has."""

SLEEP_SECONDS = 4242424
"""The children of `forks_children` run `sleep 4242424`: the test finds them on /proc by that argument."""
CHILDREN = 30
MEGABYTES = 50
REPORT_PREFIX = "hostile report: "

FORKS_CHILDREN = '''
def leave_children_behind():
    """Start children that leave this node's session (setsid), fork once more so no one waits for them, ignore
    the polite signals and sleep for weeks."""
    import json
    import os
    import signal

    pids = []
    for _ in range(@CHILDREN@):
        child = os.fork()
        if child == 0:
            os.setsid()
            if os.fork() == 0:
                for polite in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
                    signal.signal(polite, signal.SIG_IGN)
                os.execvp("sleep", ["sleep", "@SLEEP_SECONDS@"])
            os._exit(0)
        pids.append(child)
    for child in pids:
        os.waitpid(child, 0)
    print("@REPORT_PREFIX@" + json.dumps({"children": len(pids)}), flush=True)
'''.replace("@CHILDREN@", str(CHILDREN)).replace("@SLEEP_SECONDS@", str(SLEEP_SECONDS)).replace(
    "@REPORT_PREFIX@", REPORT_PREFIX)

REACHES_NETWORK = '''
def try_the_network():
    """Connect to the internet, to this host's own address and to the host's ROS master; report the errno names."""
    import errno
    import json
    import socket

    outcomes = {}
    for label, host, port in @NETWORK_TARGETS@:
        try:
            socket.create_connection((host, port), timeout=5).close()
            outcomes[label] = "connected"
        except OSError as error:
            outcomes[label] = errno.errorcode.get(error.errno, str(error))
    print("@REPORT_PREFIX@" + json.dumps(outcomes), flush=True)
'''.replace("@REPORT_PREFIX@", REPORT_PREFIX)

SNOOPS = '''
def snoop():
    """Read another student's files (where the test put them, and whatever lies in /tmp or next to this
    workspace), then write files outside this workspace; report what was read and what could be written."""
    import errno
    import glob
    import json
    import os

    home = os.path.expanduser("~")
    # Beyond the paths it aims at, everything under /tmp and next to this workspace, but the lab's checkout: it is
    # readable by design, and a lab cloned under /tmp (with its build, venv and byte-code) made the report longer
    # than the log keeps.
    aimed = @READ_PATHS@
    lab = @LAB_ROOT@ + os.sep
    read = {}
    for pattern in aimed + ["/tmp/**/*", os.path.join(os.path.dirname(os.path.dirname(home)), "**", "*")]:
        for path in glob.glob(pattern, recursive=True):
            if pattern not in aimed and path.startswith(lab):
                continue
            if os.path.isfile(path) and not path.startswith(home):
                try:
                    with open(path, errors="replace") as stolen:
                        read[path] = stolen.read(200)
                except OSError as error:
                    read[path] = errno.errorcode.get(error.errno, str(error))
    written = {}
    for path in @WRITE_PATHS@ + [os.path.join(home, "..", "@MARKER@")]:
        try:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as planted:
                planted.write("snooped")
            written[path] = "written"
        except OSError as error:
            written[path] = errno.errorcode.get(error.errno, str(error))
    print("@REPORT_PREFIX@" + json.dumps({"read": read, "written": written}), flush=True)
'''.replace("@REPORT_PREFIX@", REPORT_PREFIX)

PRINTS_MEGABYTES = '''
def shout():
    """Print @MEGABYTES@ MB to stdout, a megabyte at a time."""
    line = "All work and no play makes Jack a dull boy. " * 20 + "\\n"
    megabyte = line * (1024 * 1024 // len(line))
    for _ in range(@MEGABYTES@):
        print(megabyte, end="", flush=True)
'''.replace("@MEGABYTES@", str(MEGABYTES))
