"""TurtleSim: services, auto-names, errors with the original's texts, logs, ticks, params."""
import math

import pytest

from turtlesim.core.background import param_as_int, read_background
from turtlesim.core.canvas import world_to_screen
from turtlesim.core.errors import (
    DuplicateNameError,
    InvalidNameError,
    NonFiniteValueError,
    TurtleSimError,
    UnknownTurtleError,
)
from turtlesim.core.log import LogLevel

NAN = float('nan')
INF = float('inf')


def test_start_logs_and_spawns_turtle1(make_sim, log):
    sim = make_sim('/sim')
    assert sim.names == ['turtle1']
    assert log.events == [
        (LogLevel.INFO, 'Starting turtlesim with node name /sim'),
        (LogLevel.INFO,
         'Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]'),
    ]


def test_first_tick_only_records_then_every_turtle_publishes(make_sim):
    sim = make_sim()
    assert sim.step(0.0) == []
    results = sim.step(0.016)
    assert [name for name, _ in results] == ['turtle1']
    assert results[0][1].color == (69, 86, 255)


def test_turtles_update_in_alphabetical_order(make_sim):
    sim = make_sim()
    for name in ('zeta', 'Alpha', 'beta', 'a/b'):
        sim.spawn(name, 1.0, 1.0, 0.0)
    sim.step(0.0)
    assert [name for name, _ in sim.step(0.016)] == ['Alpha', 'a/b', 'beta', 'turtle1', 'zeta']


def test_auto_names_follow_the_counter(make_sim, log):
    sim = make_sim()
    assert sim.spawn('', 1.0, 2.0, 0.5) == 'turtle2'
    assert log.events[-1] == (
        LogLevel.INFO, 'Spawning turtle [turtle2] at x=[1.000000], y=[2.000000], theta=[0.500000]')
    sim.kill('turtle2')
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle3'
    assert sim.spawn('named', 1.0, 1.0, 0.0) == 'named'
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle4'
    assert sim.reset() == 'turtle1'
    assert sim.names == ['turtle1']
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle2'


def test_auto_name_skips_names_taken_explicitly(make_sim):
    sim = make_sim()
    sim.spawn('turtle2', 1.0, 1.0, 0.0)
    sim.spawn('turtle3', 1.0, 1.0, 0.0)
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle4'


def test_kill_everything_then_auto_spawn_keeps_counting(make_sim):
    sim = make_sim()
    sim.kill('turtle1')
    assert sim.names == []
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle2'


def test_duplicate_name_fails_with_the_original_text(make_sim):
    sim = make_sim()
    with pytest.raises(DuplicateNameError) as error:
        sim.spawn('turtle1', 1.0, 1.0, 0.0)
    assert str(error.value) == 'A turtled named [turtle1] already exists'
    assert error.value.level is LogLevel.ERROR and error.value.returns_false
    assert sim.names == ['turtle1']


@pytest.mark.parametrize('name, text', [
    ('2turtle', 'Character [2] is not valid as the first character in Graph Resource Name '
                '[2turtle].  Valid characters are a-z, A-Z, / and in some cases ~.'),
    ('my turtle', 'Character [ ] at element [2] is not valid in Graph Resource Name '
                  '[my turtle].  Valid characters are a-z, A-Z, 0-9, / and _.'),
    ('a-b', 'Character [-] at element [1] is not valid in Graph Resource Name [a-b].  '
            'Valid characters are a-z, A-Z, 0-9, / and _.'),
    ('_x', 'Character [_] is not valid as the first character in Graph Resource Name [_x].  '
           'Valid characters are a-z, A-Z, / and in some cases ~.'),
])
def test_invalid_name_fails_with_roscpp_text_and_no_turtle(make_sim, log, name, text):
    sim = make_sim()
    before = list(log.events)
    with pytest.raises(InvalidNameError) as error:
        sim.spawn(name, 1.0, 1.0, 0.0)
    assert str(error.value) == text
    assert not error.value.returns_false
    assert sim.names == ['turtle1']
    assert log.events == before
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle2'


@pytest.mark.parametrize('name', ['t2_b/c', '/abs', '~private', 'A9'])
def test_valid_graph_names_are_accepted(make_sim, name):
    assert make_sim().spawn(name, 1.0, 1.0, 0.0) == name


def test_kill_unknown_fails_with_the_original_text(make_sim):
    sim = make_sim()
    with pytest.raises(UnknownTurtleError) as error:
        sim.kill('nobody')
    assert str(error.value) == 'Tried to kill turtle [nobody], which does not exist'
    assert error.value.returns_false


def test_all_errors_share_one_root():
    for error_class in (DuplicateNameError, InvalidNameError, UnknownTurtleError,
                        NonFiniteValueError):
        assert issubclass(error_class, TurtleSimError)


def test_per_turtle_calls_on_unknown_names_fail(make_sim):
    sim = make_sim()
    with pytest.raises(UnknownTurtleError):
        sim.cmd_vel('ghost', 1.0, 0.0, 0.0, 0.0)
    with pytest.raises(UnknownTurtleError):
        sim.set_pen('ghost', 1, 2, 3, 1, 0)


def test_spawn_does_not_range_check_and_the_tick_clamps(make_sim, log):
    sim = make_sim()
    sim.spawn('far', 20.0, -1.0, 7.0)
    sim.step(0.0)
    pose = dict(sim.step(0.016))['far'].pose
    assert (pose.x, pose.y) == pytest.approx((11.088889, 0.0), abs=1e-5)
    assert pose.theta == pytest.approx(7.0 - 2 * 3.14159265, abs=1e-6)
    assert log.texts(LogLevel.WARN) == [
        'Oh no! I hit the wall! (Clamping from [x=20.000000, y=12.088889])']


def test_nan_cmd_vel_is_ignored_with_a_warning(make_sim, log):
    sim = make_sim()
    sim.step(0.0)
    sim.cmd_vel('turtle1', 1.0, 0.0, 0.0, 0.0)
    sim.cmd_vel('turtle1', NAN, 0.0, 0.0, 0.0)
    sim.cmd_vel('turtle1', 0.0, 0.0, INF, 0.0)
    pose = dict(sim.step(0.016))['turtle1'].pose
    assert pose.linear_velocity == 1.0 and pose.angular_velocity == 0.0
    assert all(math.isfinite(value) for value in pose)
    warnings = log.texts(LogLevel.WARN)
    assert len(warnings) == 2
    assert warnings[0].startswith('Ignoring cmd_vel for turtle [turtle1]')
    assert 'only finite numbers are allowed' in warnings[0]


@pytest.mark.parametrize('vx, vy, w', [(1e39, 0.0, 0.0), (0.0, -1e300, 0.0), (0.0, 0.0, 1e39),
                                       (3e38, 3e38, 0.0)])
def test_cmd_vel_beyond_float32_is_ignored_so_poses_stay_finite(make_sim, log, vx, vy, w):
    sim = make_sim()
    sim.step(0.0)
    sim.cmd_vel('turtle1', 1.0, 0.0, 0.0, 0.0)
    sim.cmd_vel('turtle1', vx, vy, w, 0.0)
    pose = dict(sim.step(0.016))['turtle1'].pose
    assert pose.linear_velocity == 1.0 and pose.angular_velocity == 0.0
    assert log.texts(LogLevel.WARN)[0].startswith('Ignoring cmd_vel for turtle [turtle1]')

def test_non_finite_spawn_fails_without_moving_the_counter(make_sim):
    sim = make_sim()
    with pytest.raises(NonFiniteValueError) as error:
        sim.spawn('', NAN, 1.0, 0.0)
    assert error.value.level is LogLevel.WARN
    with pytest.raises(NonFiniteValueError):
        sim.spawn('big', 1e39, 1.0, 0.0)
    assert sim.names == ['turtle1']
    assert sim.spawn('', 1.0, 1.0, 0.0) == 'turtle2'


def test_non_finite_teleports_are_ignored_and_others_unharmed(make_sim, log):
    sim = make_sim()
    sim.spawn('other', 2.0, 2.0, 0.0)
    sim.teleport_absolute('turtle1', 1.0, NAN, 0.0)
    sim.teleport_relative('turtle1', INF, 0.0)
    sim.step(0.0)
    results = dict(sim.step(0.016))
    assert results['turtle1'].pose.x == pytest.approx(5.544445, abs=1e-5)
    assert results['other'].pose.x == pytest.approx(2.0)
    assert len(log.texts(LogLevel.WARN)) == 2


def test_teleport_applies_in_the_same_tick(make_sim):
    sim = make_sim()
    sim.step(0.0)
    sim.teleport_absolute('turtle1', 1.0, 2.0, 0.5)
    pose = dict(sim.step(0.016))['turtle1'].pose
    assert (pose.x, pose.y, pose.theta) == pytest.approx((1.0, 2.0, 0.5), abs=1e-6)


def test_clear_logs_and_rereads_background_params(make_sim, log, params):
    sim = make_sim()
    sim.set_pen('turtle1', 255, 0, 0, 3, 0)
    sim.teleport_absolute('turtle1', 2.0, 5.544445, 0.0)
    sim.step(0.0)
    sim.step(0.016)
    on_trail = world_to_screen(4.0, 5.544445)
    assert sim.canvas.color_at(on_trail) == (255, 0, 0)
    params['background_r'] = 255
    sim.clear()
    assert log.events[-1] == (LogLevel.INFO, 'Clearing turtlesim.')
    assert sim.canvas.color_at(on_trail) == (255, 86, 255)
    assert sim.names == ['turtle1']
    assert sim.turtles()[0][1].pen.colour == (255, 0, 0)


def test_reset_restores_turtle1_default_pen_and_rereads_params(make_sim, log, params):
    sim = make_sim()
    sim.spawn('extra', 1.0, 1.0, 0.0)
    sim.set_pen('turtle1', 1, 2, 3, 4, 0)
    sim.teleport_absolute('turtle1', 1.0, 1.0, 1.0)
    params['background_b'] = 0
    log.events.clear()
    assert sim.reset() == 'turtle1'
    assert log.texts() == [
        'Resetting turtlesim.',
        'Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]',
    ]
    name, turtle = sim.turtles()[0]
    assert (name, turtle.pen.colour, turtle.pen.width, turtle.pen_on) == (
        'turtle1', (179, 184, 255), 3, True)
    sim.step(0.0)
    result = dict(sim.step(0.016))['turtle1']
    assert (result.pose.x, result.pose.theta) == pytest.approx((5.544445, 0.0), abs=1e-5)
    assert result.color == (69, 86, 0)


def test_background_params_are_read_only_at_start_clear_and_reset(make_sim, params):
    params.update(background_r=10, background_g=20.5, background_b='x')
    sim = make_sim()
    assert sim.canvas.color_at((1.0, 1.0)) == (10, 21, 255)
    params['background_r'] = 99
    sim.step(0.0)
    sim.step(0.016)
    assert sim.canvas.color_at((1.0, 1.0)) == (10, 21, 255)


@pytest.mark.parametrize('value, expected', [
    (7, 7), (2.4, 2), (2.5, 3), (-2.3, -3), (-2.7, -3), (True, 69), ('12', 69), (None, 69),
    (NAN, 69),
])
def test_param_as_int_follows_roscpp(value, expected):
    assert param_as_int(value, 69) == expected


def test_background_channels_are_masked_to_8_bits():
    values = {'background_r': 256 + 5, 'background_g': -1, 'background_b': 300.0}
    assert read_background(values.get) == (5, 255, 44)
