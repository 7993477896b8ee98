"""Which /cmd_vel publishers the simulator is not connected to yet, from its getBusInfo answer (the grader waits
for none before each check, lab_grader.checks.command_links)."""
from lab_grader.checks.command_links import unheard

STUDENT = "http://localhost:40001/"
GRADER = "http://localhost:40002/"


def connection(uri, topic="/cmd_vel", direction="i"):
    """One getBusInfo entry of a rospy node: (id, the other end's URI, direction, transport, topic, connected,
    transport info)."""
    return [7, uri, direction, "TCPROS", topic, True, "TCPROS connection on port 41 to [...]"]


def test_a_publisher_the_simulator_is_connected_to_is_heard():
    assert unheard({STUDENT, GRADER}, [connection(STUDENT), connection(GRADER)], "/cmd_vel") == set()


def test_a_new_publisher_is_unheard_until_the_simulator_connects_to_it():
    assert unheard({STUDENT, GRADER}, [connection(GRADER)], "/cmd_vel") == {STUDENT}


def test_connections_of_other_topics_or_outbound_do_not_count():
    bus_info = [connection(STUDENT, topic="/odom"), connection(STUDENT, direction="o"), connection(GRADER)]
    assert unheard({STUDENT, GRADER}, bus_info, "/cmd_vel") == {STUDENT}


def test_no_publisher_nothing_to_wait_for():
    assert unheard(set(), [], "/cmd_vel") == set()
