"""The generated beginner_tutorials classes carry the md5sums and fields of interfaces.md, so the classic
ROS wiki clients (rospy_tutorials/AddTwoInts has the same md5sum) and Gazebo-era course code interoperate."""
import pytest

from beginner_tutorials import msg, srv

SERVICE_MD5 = {
    "add_two_int": "6a2e34150c00229791cc89ff309fff21",
    "gazebo_server": "f585dfe9780f5944bfdaecf9c4a1e42c",
}

ACTION_FIELDS = {
    "counterGoal": (["num_counts"], ["int32"]),
    "counterResult": (["result_message"], ["string"]),
    "counterFeedback": (["counts_elapsed"], ["int32"]),
    "counterActionGoal": (["header", "goal_id", "goal"],
                          ["std_msgs/Header", "actionlib_msgs/GoalID", "beginner_tutorials/counterGoal"]),
}


@pytest.mark.parametrize("service", sorted(SERVICE_MD5))
def test_service_md5sums(service):
    service_class = getattr(srv, service)
    assert service_class._md5sum == SERVICE_MD5[service]
    assert service_class._type == "beginner_tutorials/" + service


def test_service_fields():
    assert (srv.add_two_intRequest.__slots__, srv.add_two_intRequest._slot_types) == (["a", "b"],
                                                                                      ["int64", "int64"])
    assert (srv.add_two_intResponse.__slots__, srv.add_two_intResponse._slot_types) == (["sum"], ["int64"])
    assert srv.gazebo_serverRequest._slot_types == ["int64"]
    assert (srv.gazebo_serverResponse.__slots__, srv.gazebo_serverResponse._slot_types) == (["distance"],
                                                                                            ["float32"])


@pytest.mark.parametrize("message", sorted(ACTION_FIELDS))
def test_action_message_fields(message):
    message_class = getattr(msg, message)
    assert (message_class.__slots__, message_class._slot_types) == ACTION_FIELDS[message]


def test_the_action_bundles_goal_result_and_feedback():
    assert msg.counterAction.__slots__ == ["action_goal", "action_result", "action_feedback"]
