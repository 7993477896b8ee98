"""Generated classes carry the original interfaces: turtlesim and turtle_actionlib md5sums from
../shared/specs/turtlesim.md §2 and §4, the ROS 2 Services unit ports from interfaces.md, gazebo_msgs field
lists from tb3_sim.md §5."""
import importlib

import pytest

MD5SUMS = {
    "turtlesim.msg.Pose": "863b248d5016ca62ea2e895ae5265cf9",
    "turtlesim.msg.Color": "353891e354491c51aabe32df673fb446",
    "turtlesim.srv.Spawn": "0b2d2e872a8e2887d5ed626f2bf2c561",
    "turtlesim.srv.SpawnRequest": "57f001c49ab7b11d699f8606c1f4f7ff",
    "turtlesim.srv.SpawnResponse": "c1f3d28f1b044c871e6eff2e9fc3c667",
    "turtlesim.srv.Kill": "c1f3d28f1b044c871e6eff2e9fc3c667",
    "turtlesim.srv.KillResponse": "d41d8cd98f00b204e9800998ecf8427e",
    "turtlesim.srv.SetPen": "9f452acce566bf0c0954594f69a8e41b",
    "turtlesim.srv.TeleportAbsolute": "a130bc60ee6513855dc62ea83fcc5b20",
    "turtlesim.srv.TeleportRelative": "9d5c2dcd348ac8f76ce2a4307bd63a13",
    "turtle_actionlib.msg.ShapeAction": "d73b17d6237a925511f5d7727a1dc903",
    "turtle_actionlib.msg.ShapeActionGoal": "dbfccd187f2ec9c593916447ffd6cc77",
    "turtle_actionlib.msg.ShapeActionResult": "c8d13d5d140f1047a2e4d3bf5c045822",
    "turtle_actionlib.msg.ShapeActionFeedback": "aae20e09065c3809e8a8e87c4c8953fd",
    "turtle_actionlib.msg.ShapeGoal": "3b9202ab7292cebe5a95ab2bf6b9c091",
    "turtle_actionlib.msg.ShapeResult": "b06c6e2225f820dbc644270387cd1a7c",
    "turtle_actionlib.msg.ShapeFeedback": "d41d8cd98f00b204e9800998ecf8427e",
    "turtle_actionlib.msg.Velocity": "9d5c2dcd348ac8f76ce2a4307bd63a13",
    "std_srvs.srv.Empty": "d41d8cd98f00b204e9800998ecf8427e",
    "std_srvs.srv.SetBool": "09fb03525b03e7ea1fd3992bafd87e16",
    "custom_interfaces.srv.MyCustomServiceMessage": "0f1c913663b55d50624c71265d8df6a2",
    "custom_interfaces.srv.Move": "84da34b925980618a0a153c1dcc2b379",
    "custom_interfaces.srv.StringServiceMessage": "eacb96936978c535fc698b2654a80bac",
    "services_quiz_srv.srv.Turn": "79912f95557af6cf3d55d2b6458d92f2",
}

GAZEBO_FIELDS = {
    "msg.ModelState": (["model_name", "pose", "twist", "reference_frame"],
                       ["string", "geometry_msgs/Pose", "geometry_msgs/Twist", "string"]),
    "msg.ModelStates": (["name", "pose", "twist"],
                        ["string[]", "geometry_msgs/Pose[]", "geometry_msgs/Twist[]"]),
    "srv.SpawnModelRequest": (["model_name", "model_xml", "robot_namespace", "initial_pose", "reference_frame"],
                              ["string", "string", "string", "geometry_msgs/Pose", "string"]),
    "srv.SpawnModelResponse": (["success", "status_message"], ["bool", "string"]),
    "srv.DeleteModelRequest": (["model_name"], ["string"]),
    "srv.DeleteModelResponse": (["success", "status_message"], ["bool", "string"]),
    "srv.GetModelStateRequest": (["model_name", "relative_entity_name"], ["string", "string"]),
    "srv.GetModelStateResponse": (["header", "pose", "twist", "success", "status_message"],
                                  ["std_msgs/Header", "geometry_msgs/Pose", "geometry_msgs/Twist", "bool",
                                   "string"]),
    "srv.SetModelStateRequest": (["model_state"], ["gazebo_msgs/ModelState"]),
    "srv.SetModelStateResponse": (["success", "status_message"], ["bool", "string"]),
    "srv.GetWorldPropertiesResponse": (["sim_time", "model_names", "rendering_enabled", "success",
                                        "status_message"],
                                       ["float64", "string[]", "bool", "bool", "string"]),
}


def load(dotted):
    module, name = dotted.rsplit(".", 1)
    return getattr(importlib.import_module(module), name)


@pytest.mark.parametrize("dotted", sorted(MD5SUMS))
def test_md5sum(dotted):
    assert load(dotted)._md5sum == MD5SUMS[dotted]


@pytest.mark.parametrize("dotted", sorted(GAZEBO_FIELDS))
def test_gazebo_msgs_fields(dotted):
    cls = load("gazebo_msgs." + dotted)
    assert (cls.__slots__, cls._slot_types) == GAZEBO_FIELDS[dotted]
