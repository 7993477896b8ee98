"""/detect_fruit_service requests and replies: the accepted words, the refusals and their texts."""
import pytest

from fruit_detector_pkg.fruit_detection import Box, Detection
from fruit_detector_pkg.fruit_request import (
    STALE_IMAGE_S,
    FruitReply,
    FruitRequestError,
    check_image_age,
    fruit_from_request,
    reply_for,
)

TOPIC = "/camera/rgb/image_raw"


@pytest.mark.parametrize("word, fruit", [("apple", "apple"), ("banana", "banana"), (" Banana ", "banana"),
                                         ("APPLE\n", "apple"), ("\tapple", "apple")])
def test_fruit_words_ignore_case_and_surrounding_space(word, fruit):
    assert fruit_from_request(word) == fruit


@pytest.mark.parametrize("word", ["kiwi", "", "  ", "apples", "app le", "pineapple", "bananas!", "🍎"])
def test_other_words_are_refused_naming_the_allowed_ones(word):
    with pytest.raises(FruitRequestError) as refused:
        fruit_from_request(word)
    assert str(refused.value) == "unknown fruit '{}': detect must be apple or banana".format(word)


def test_no_image_yet_asks_whether_the_simulator_runs():
    with pytest.raises(FruitRequestError, match="^no camera image has arrived on /camera/rgb/image_raw yet: is "
                                                "the simulator running\\?$"):
        check_image_age(TOPIC, None)


def test_an_old_image_is_not_trusted():
    check_image_age(TOPIC, STALE_IMAGE_S - 0.01)
    with pytest.raises(FruitRequestError, match="arrived 2.5 s ago: is the simulator still running"):
        check_image_age(TOPIC, 2.5)


def test_reply_when_in_view():
    detection = Detection("apple", Box(180, 220, 41, 40), (200.4, 239.6), 1257.0, (640, 480))
    assert reply_for(detection) == FruitReply(
        True, "apple detected at x=200, y=240 (41x40 px box, left of the centre of the 640x480 image), in view")


def test_reply_right_of_centre():
    detection = Detection("banana", Box(400, 300, 80, 20), (439.5, 309.5), 1600.0, (640, 480))
    assert "right of the centre" in reply_for(detection).message


def test_reply_when_not_in_view():
    assert reply_for(Detection("banana", None, None, None, (640, 480))) == FruitReply(False, "no banana in view")
