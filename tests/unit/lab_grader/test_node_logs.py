"""A student's logs read for a marker: the traceback a node died with (also a SyntaxError, which has no
"Traceback" header), and catkin's error lines of a failed build without its status chatter."""
from lab_grader.node_logs import build_errors, traceback_of

SYNTAX_ERROR_LOG = """  File "/ws/src/week4_services/nodes/move_server.py", line 12
    print "Starting the move server..."
    ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^
SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?
"""

IMPORT_ERROR_LOG = """[INFO] [1.0]: starting
Traceback (most recent call last):
  File "/ws/src/pkg/scripts/approach_server.py", line 4, in <module>
    from com2009_msgs.srv import Approach
ModuleNotFoundError: No module named 'com2009_msg'
[rospy.core] signal_shutdown [atexit]
"""

BUILD_LOG = """-- Using CATKIN_DEVEL_PREFIX: /ws/devel
-- nosetests not found, Python tests can not be run (try installing package 'python3-nose')
CMake Error at week4_services/CMakeLists.txt:6:
  Parse error.  Function missing ending ")".  End of file reached.


-- Configuring incomplete, errors occurred!
Invoking "cmake" failed
"""


def test_the_last_traceback_line_and_the_traceback_of_a_syntax_error():
    last, text = traceback_of("[INFO] hello\n" + SYNTAX_ERROR_LOG)
    assert last == "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?"
    assert text.startswith('  File "/ws/src/week4_services/nodes/move_server.py", line 12')
    assert text.endswith(last)


def test_the_last_traceback_line_of_an_import_error_leaves_rospys_shutdown_lines_out():
    last, text = traceback_of(IMPORT_ERROR_LOG)
    assert last == "ModuleNotFoundError: No module named 'com2009_msg'"
    assert text.startswith("Traceback (most recent call last):") and "signal_shutdown" not in text


def test_a_log_without_a_traceback_has_none():
    assert traceback_of("[INFO] the move server is ready\n") == (None, None)


def test_catkins_error_lines_without_its_status_chatter():
    errors = build_errors(BUILD_LOG)
    assert errors[0] == "CMake Error at week4_services/CMakeLists.txt:6:"
    assert "Parse error" in errors[1] and errors[-1] == 'Invoking "cmake" failed'
    assert not any("nosetests" in line for line in errors)
