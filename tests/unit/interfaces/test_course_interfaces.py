"""The generated tuos_msgs classes (and their older course-year twins) carry the md5sums of the course's
definitions (../shared/specs/interfaces.md), so code built elsewhere against them talks to ours."""
import importlib

import pytest

COURSE_PACKAGES = ["tuos_msgs", "com2009_msgs", "tuos_ros_msgs"]

SERVICE_MD5 = {
    # service: (service, request, response)
    "SetBool": ("809e515273297bb2c71988526658bce7", "2c14d11e782ee205fe33d007d480c988",
                "2eebae83968108296ba3643d655e624e"),
    "TimedMovement": ("01da3949d1975f89601d90342172dc85", "98ec7782393184833d09a76461890b3f",
                      "358e233cde0c8a8bcfea4ce193f8fc15"),
    "Approach": ("9969ab457f53a37a2d75e40a76a1f887", "a2f9f80d4d9d15d06a0678fe2155a4db",
                 "4b45950c35bda99bcc3b6c93c7abc007"),
}

ACTION_FIELDS = {
    "CameraSweepGoal": (["sweep_angle", "image_count"], ["float32", "int32"]),
    "CameraSweepResult": (["image_path"], ["string"]),
    "CameraSweepFeedback": (["current_image", "current_angle"], ["int32", "float32"]),
    "SearchGoal": (["fwd_velocity", "approach_distance"], ["float32", "float32"]),
    "SearchResult": (["total_distance_travelled", "closest_object_distance", "closest_object_angle"],
                     ["float32", "float32", "float32"]),
    "SearchFeedback": (["current_distance_travelled"], ["float32"]),
    "NumpyFloat32Array": (["data"], ["float32[]"]),
    "NumpyInt32Array": (["data"], ["int32[]"]),
}


@pytest.mark.parametrize("package", COURSE_PACKAGES)
@pytest.mark.parametrize("service", sorted(SERVICE_MD5))
def test_service_md5sums(package, service):
    srv = importlib.import_module(package + ".srv")
    service_md5, request_md5, response_md5 = SERVICE_MD5[service]
    assert getattr(srv, service)._md5sum == service_md5
    assert getattr(srv, service + "Request")._md5sum == request_md5
    assert getattr(srv, service + "Response")._md5sum == response_md5
    assert getattr(srv, service)._type == "{}/{}".format(package, service)


@pytest.mark.parametrize("package", COURSE_PACKAGES)
@pytest.mark.parametrize("message", sorted(ACTION_FIELDS))
def test_action_and_array_fields(package, message):
    msg_class = getattr(importlib.import_module(package + ".msg"), message)
    slots, types = ACTION_FIELDS[message]
    assert (msg_class.__slots__, msg_class._slot_types) == (slots, types)


@pytest.mark.parametrize("package", COURSE_PACKAGES[1:])
def test_older_course_names_are_identical_to_tuos_msgs(package):
    from tuos_msgs import msg as tuos_msg
    twin = importlib.import_module(package + ".msg")
    for name in ["CameraSweepAction", "SearchAction", "NumpyFloat32Array", "NumpyInt32Array"]:
        assert getattr(twin, name)._md5sum == getattr(tuos_msg, name)._md5sum
