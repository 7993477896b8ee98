"""Restart detection by run id: only a master with a different /run_id than the one the node registered with
asks for a re-registration; a master that does not list the node yet (rospy still registering) does not."""
from master_reconnect.runs import MasterRuns


def test_the_same_master_never_asks_for_a_re_registration():
    runs = MasterRuns("run-a")
    assert not runs.restarted("run-a", knows_node=True)
    assert not runs.restarted("run-a", knows_node=False), "rospy may still be registering with it"


def test_a_new_run_id_asks_until_the_node_registered_with_it():
    runs = MasterRuns("run-a")
    assert runs.restarted("run-b", knows_node=False)
    assert runs.restarted("run-b", knows_node=True), "a partial registration (one new publisher) is no proof"
    runs.registered("run-b")
    assert not runs.restarted("run-b", knows_node=True)


def test_a_master_without_a_run_id_yet_is_waited_for():
    runs = MasterRuns("run-a")
    assert not runs.restarted(None, knows_node=False)
    assert runs.restarted("run-b", knows_node=False)


def test_the_first_master_is_adopted_once_rospy_registered_with_it():
    """The node started before its master: rospy registers by itself, which is no restart."""
    runs = MasterRuns()
    assert not runs.restarted("run-a", knows_node=False)
    assert runs.run_id is None
    assert not runs.restarted("run-a", knows_node=True)
    assert runs.run_id == "run-a"
    assert runs.restarted("run-b", knows_node=False)
