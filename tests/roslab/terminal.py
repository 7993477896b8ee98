"""An interactive bash in a pseudo-terminal (pexpect), driven the way a student types: commands, Tab, Ctrl-C.

The shell is `bash -i`, so it reads Debian's /etc/bash.bashrc and the .bashrc of the HOME it is given (tests
write one, as a student's would be). Its prompt is set to PROMPT once it has started, so that the output of
each command is everything between the command line and the next prompt. `close()` ends the shell and every
process started from it (a node left running in the foreground included), by pid.
"""
import os
import re

import pexpect

from roslab.processes import descendants, kill_if_alive

PROMPT = "@@student-prompt@@ "
SET_PROMPT = "PS1='@@student-''prompt@@ '"   # its echo does not contain PROMPT
COLUMNS = 400   # long command lines stay on one line (readline wraps them otherwise)


class Terminal:
    """`bash -i` with environment `env` in folder `cwd`; everything it prints is copied to `log_path`."""

    def __init__(self, env, cwd, log_path, timeout_s=60):
        self._log = open(log_path, "w")
        self.shell = pexpect.spawn("bash", ["-i"], env=env, cwd=str(cwd), encoding="utf-8", codec_errors="replace",
                                   dimensions=(50, COLUMNS), timeout=timeout_s)
        self.shell.logfile_read = self._log
        self.shell.sendline(SET_PROMPT)
        self.shell.expect_exact(PROMPT)
        self.startup = strip_escapes(self.shell.before)   # what .bashrc printed, before the first prompt

    def run(self, command, timeout_s=None):
        """Type `command` and Enter; returns what it printed (without the command line), once the prompt is back."""
        self.shell.sendline(command)
        return self._output_until_prompt(timeout_s)

    def type(self, text):
        """Type `text` without pressing Enter."""
        self.shell.send(text)

    def tab(self, expected, timeout_s=None):
        """Press Tab and wait until the terminal shows `expected` (a regular expression); returns the match."""
        self.shell.send("\t")
        self.shell.expect(expected, timeout=_pexpect_timeout(timeout_s))
        return self.shell.match.group(0)

    def enter(self, timeout_s=None):
        """Press Enter on the line typed so far; returns what the command printed."""
        self.shell.send("\r")
        return self._output_until_prompt(timeout_s)

    def discard_line(self, timeout_s=None):
        """Erase the line typed so far (Ctrl-U) and press Enter on the empty line; returns once the prompt is back
        on a new line (readline redraws the prompt on the old one for Ctrl-U)."""
        self.shell.send("\x15\r")
        self.shell.expect_exact("\n" + PROMPT, timeout=_pexpect_timeout(timeout_s))

    def wait_for(self, pattern, timeout_s=None):
        """Wait until the terminal shows `pattern` (a regular expression), e.g. from a command still running."""
        self.shell.expect(pattern, timeout=_pexpect_timeout(timeout_s))

    def interrupt(self, timeout_s=None):
        """Ctrl-C, then wait for the prompt; returns what was printed meanwhile.

        Not within a moment of a rospy node's start: rospy's SIGINT handler calls the master, and hangs for
        good when the main thread is in a call to the master itself (as during the first log line)."""
        self.shell.sendintr()
        return self._output_until_prompt(timeout_s)

    def _output_until_prompt(self, timeout_s):
        self.shell.expect_exact(PROMPT, timeout=_pexpect_timeout(timeout_s))
        lines = self.shell.before.replace("\r\n", "\n").split("\n", 1)
        return strip_escapes(lines[1] if len(lines) > 1 else "")

    def close(self):
        """Exit the shell; SIGKILL it and everything started from it that is still running."""
        offspring = descendants(self.shell.pid) if self.shell.isalive() else set()
        if self.shell.isalive():
            self.shell.sendline("exit")
            self.shell.expect([pexpect.EOF, pexpect.TIMEOUT], timeout=5)
        self.shell.close(force=True)
        for pid, started in offspring:
            kill_if_alive(pid, started)
        self._log.close()


def _pexpect_timeout(timeout_s):
    """pexpect's timeout argument: -1 means the terminal's own timeout (None would wait forever)."""
    return -1 if timeout_s is None else timeout_s


def strip_escapes(text):
    """`text` without terminal escape sequences (colours, bracketed-paste switches) and carriage returns."""
    return re.sub(r"\x1b\[[0-9;?]*[A-Za-z]|\r", "", text)


def student_env(home, **extra):
    """The environment of a fresh terminal of a student whose home is `home`: a plain PATH, no ROS variables.
    `extra` adds or replaces variables (e.g. ROS_MASTER_URI of a test's master)."""
    env = {"HOME": str(home), "PATH": "/usr/local/bin:/usr/bin:/bin", "TERM": "dumb", "LANG": "C.UTF-8",
           "USER": os.environ.get("USER", "student")}
    env.update(extra)
    return env
