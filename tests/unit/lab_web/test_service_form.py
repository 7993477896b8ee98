"""The page's service form against the Week 4 services' real request classes: fields listed, values converted,
and values that do not fit refused as `rosservice call` would."""
import pytest
from gazebo_msgs.srv import SpawnModel
from tuos_msgs.srv import Approach, SetBool, TimedMovement

from beginner_tutorials.srv import add_two_int
from lab_web.service_form import FormError, request_fields, request_values, response_text


def test_week4_requests_are_listed_field_by_field():
    assert request_fields(SetBool._request_class) == [{"name": "request_signal", "type": "bool"}]
    assert request_fields(TimedMovement._request_class) == [
        {"name": "movement_request", "type": "string"}, {"name": "duration", "type": "int32"}]
    assert request_fields(Approach._request_class) == [
        {"name": "approach_distance", "type": "float32"}, {"name": "approach_velocity", "type": "float64"}]


def test_nested_requests_are_not_for_the_form():
    with pytest.raises(FormError, match="initial_pose is a geometry_msgs/Pose"):
        request_fields(SpawnModel._request_class)


def test_values_are_converted_to_the_field_types():
    assert request_values(TimedMovement._request_class, {"movement_request": "fwd", "duration": "3"}) == \
        {"movement_request": "fwd", "duration": 3}
    assert request_values(SetBool._request_class, {"request_signal": "true"}) == {"request_signal": True}
    assert request_values(Approach._request_class, {"approach_distance": 0.4, "approach_velocity": "nan"})[
        "approach_velocity"] != 0.1   # nan reaches the server, which must refuse it itself


@pytest.mark.parametrize("request_class, values, reason", [
    (TimedMovement._request_class, {"duration": "2.5"}, "duration must be an integer"),
    (TimedMovement._request_class, {"duration": 2 ** 31}, "int32 from -2147483648 to 2147483647"),
    (add_two_int._request_class, {"a": 2 ** 63}, "int64 from"),
    (SetBool._request_class, {"request_signal": "yes"}, "true or false"),
    (Approach._request_class, {"approach_velocity": "fast"}, "must be a number"),
    (Approach._request_class, {"approach_velocity": 10 ** 308 * 10}, "an integer of 310 digits"),
    (TimedMovement._request_class, {"movement_request": 5}, "must be a string"),
    (SetBool._request_class, {"data": True}, "no field data"),
])
def test_values_that_do_not_fit_are_refused(request_class, values, reason):
    with pytest.raises(FormError, match=reason):
        request_values(request_class, values)


def test_replies_print_like_rosservice_call():
    reply = SetBool._response_class(response_signal=True, response_message="Moving")
    assert response_text(reply) == "response_signal: True\nresponse_message: Moving"
