"""turtlebot3_teleop_key's logic: keys -> targets, per-model clamping, the half-step ramp, the printed text."""
import pytest

from turtlebot3_teleop.keyboard_teleop import (
    BANNER,
    MODEL_LIMITS,
    KeyboardTeleop,
    clamp,
    is_known_model,
    is_quit,
    limits_for_model,
    ramp,
    status_line,
)

BURGER, WAFFLE, WAFFLE_PI = (MODEL_LIMITS[name] for name in ("burger", "waffle", "waffle_pi"))


def drive(teleop, keys):
    """Run one loop per entry of `keys` (None: no key in that loop) the way the node does; returns
    (the commands sent, one (linear, angular) per loop, and the lines printed)."""
    sent, printed = [], []
    for key in keys:
        printed.extend(teleop.press(key))
        sent.append(teleop.step())
    return sent, printed


def approx_each(commands):
    return [pytest.approx(command, abs=1e-12) for command in commands]


def line(linear, angular):
    return "currently:\tlinear vel {}\t angular vel {} ".format(linear, angular)


def test_limits_per_model():
    assert (BURGER.linear_mps, BURGER.angular_radps) == (0.22, 2.84)
    assert (WAFFLE.linear_mps, WAFFLE.angular_radps) == (0.26, 1.82)
    assert WAFFLE_PI == WAFFLE


def test_a_key_sequence_gives_the_originals_targets_and_ramped_commands():
    teleop = KeyboardTeleop(WAFFLE)
    sent, printed = drive(teleop, ["w", None, "w", "w", None, None, None, "a", "d", "x", None, None, "s", None])
    assert sent == approx_each([
        (0.005, 0.0), (0.01, 0.0),                  # w: target 0.01, half a step per loop
        (0.015, 0.0), (0.02, 0.0),                  # w w: the target runs ahead of the ramp
        (0.025, 0.0), (0.03, 0.0), (0.03, 0.0),     # ramp reaches 0.03 and holds it
        (0.03, 0.05),                               # a: angular target 0.1
        (0.03, 0.0),                                # d: target back to 0.0 before the ramp reached 0.1
        (0.025, 0.0), (0.02, 0.0), (0.02, 0.0),     # x: target 0.02
        (0.0, 0.0), (0.0, 0.0),                     # s: zero at once, no ramp
    ])
    assert printed == [line(0.01, 0.0), line(0.02, 0.0), line(0.03, 0.0), line(0.03, 0.1), line(0.03, 0.0),
                       line(0.019999999999999997, 0.0), line(0.0, 0.0)]


def test_the_ramp_never_overshoots_and_holds_the_target():
    teleop = KeyboardTeleop(BURGER)
    sent, _ = drive(teleop, ["a", "a", "a"] + [None] * 10)
    angular = [command[1] for command in sent]
    assert angular[:6] == pytest.approx([0.05, 0.1, 0.15, 0.2, 0.25, 0.3])
    assert max(angular) == pytest.approx(0.3) and angular[-1] == pytest.approx(0.3)


@pytest.mark.parametrize("model, linear, angular", [("burger", 0.22, 2.84), ("waffle", 0.26, 1.82),
                                                    ("waffle_pi", 0.26, 1.82)])
def test_targets_are_clamped_per_model(model, linear, angular):
    teleop = KeyboardTeleop(limits_for_model(model))
    _, printed = drive(teleop, ["w"] * 40 + ["a"] * 40)
    assert (teleop.target_linear_mps, teleop.target_angular_radps) == (linear, angular)
    assert printed[-2:] == [line(linear, angular), BANNER]   # the 80th press
    sent, _ = drive(teleop, [None] * 100)
    assert sent[-1] == (linear, angular)
    assert all(abs(lin) <= linear and abs(ang) <= angular for lin, ang in sent)
    drive(teleop, ["x"] * 100 + ["d"] * 100)
    assert (teleop.target_linear_mps, teleop.target_angular_radps) == (-linear, -angular)


@pytest.mark.parametrize("key", [None, "q", "W", "z", "\x1b", "[", "A", "\r", "0"])
def test_unknown_keys_and_no_key_are_ignored_but_the_ramp_goes_on(key):
    teleop = KeyboardTeleop(WAFFLE)
    drive(teleop, ["w", "w"])
    assert teleop.press(key) == []
    assert (teleop.target_linear_mps, teleop.target_angular_radps) == (0.02, 0.0)
    assert teleop.step() == pytest.approx((0.015, 0.0))


@pytest.mark.parametrize("key", ["s", " "])
def test_stop_keys_zero_targets_and_command_at_once(key):
    teleop = KeyboardTeleop(WAFFLE)
    drive(teleop, ["w"] * 5 + ["d"] * 3 + [None] * 20)
    assert teleop.press(key) == [line(0.0, 0.0)]
    assert (teleop.linear_mps, teleop.angular_radps) == (0.0, 0.0)
    assert teleop.step() == (0.0, 0.0)


def test_ctrl_c_is_the_quit_key():
    assert is_quit("\x03")
    assert not any(is_quit(key) for key in (None, "q", "s", "\x04"))


def test_status_line_shows_floats_as_python_prints_them():
    teleop = KeyboardTeleop(WAFFLE)
    _, printed = drive(teleop, ["w"] * 6)
    assert printed[-1] == "currently:\tlinear vel 0.060000000000000005\t angular vel 0.0 "
    assert status_line(0.26, -1.82) == "currently:\tlinear vel 0.26\t angular vel -1.82 "


def test_banner_again_after_every_20_velocity_keys():
    teleop = KeyboardTeleop(BURGER)
    _, printed = drive(teleop, ["w", "x"] * 9 + ["s", " ", "q", None] + ["a"])   # 19 velocity keys
    assert BANNER not in printed and len(printed) == 21
    assert teleop.press("d") == [line(0.0, 0.0), BANNER]
    _, printed = drive(teleop, ["w"] * 40)   # clamped presses count as well
    assert [index for index, text in enumerate(printed) if text == BANNER] == [20, 41]


def test_banner_text():
    assert BANNER.startswith("\nControl Your TurtleBot3!\n---------------------------\nMoving around:\n")
    assert "w/x : increase/decrease linear velocity (Burger : ~ 0.22, Waffle and Waffle Pi : ~ 0.26)\n" in BANNER
    assert "a/d : increase/decrease angular velocity (Burger : ~ 2.84, Waffle and Waffle Pi : ~ 1.82)\n" in BANNER
    assert BANNER.endswith("\nspace key, s : force stop\n\nCTRL-C to quit\n")


@pytest.mark.parametrize("model", ["pizza", "Waffle", "", 3, None, ["waffle"]])
def test_other_models_get_the_burgers_limits(model):
    assert not is_known_model(model)
    assert limits_for_model(model) == BURGER


def test_clamp_and_ramp():
    assert clamp(0.27, 0.26) == 0.26 and clamp(-0.3, 0.26) == -0.26 and clamp(0.1, 0.26) == 0.1
    assert ramp(0.0, 0.003, 0.005) == 0.003
    assert ramp(0.0, 0.02, 0.005) == 0.005
    assert ramp(0.0, -0.02, 0.005) == -0.005
    assert ramp(0.1, 0.1, 0.005) == 0.1
