"""The motion timeline of a graded call, from scripted odometry: forwards, backwards, turning, a wrong duration, a
robot that never stops, a start pose that is not the origin; and trajectory thinning."""
import math

import pytest

from lab_grader.checks.motion import (
    MAX_TRAJECTORY_POINTS,
    MotionError,
    Sample,
    summarize,
    thin,
)

ODOM_HZ = 30.0
RAMP_MPS2 = 1.0     # a TurtleBot3's drive reaches its command at about 1 m/s^2


def drive(commands, start=(0.0, 0.0, 0.0), t0=100.0, ramp=RAMP_MPS2, dt_step=0.001):
    """Odometry samples at 30 Hz of a unicycle following `commands` [(duration_s, v, w), ...] from pose `start`,
    with velocities ramping at `ramp` (m/s^2 and rad/s^2), integrated in 1 ms steps: what tb3_sim's /odom says."""
    x, y, yaw = start
    v = w = 0.0
    t = t0
    samples = [Sample(t, x, y, yaw, v, w)]
    next_sample = t0 + 1.0 / ODOM_HZ
    for duration, v_cmd, w_cmd in commands:
        end = t + duration
        while t < end - 1e-12:
            v += max(-ramp * dt_step, min(ramp * dt_step, v_cmd - v))
            w += max(-ramp * dt_step, min(ramp * dt_step, w_cmd - w))
            x += v * math.cos(yaw) * dt_step
            y += v * math.sin(yaw) * dt_step
            yaw = math.atan2(math.sin(yaw + w * dt_step), math.cos(yaw + w * dt_step))
            t += dt_step
            if t >= next_sample - 1e-12:
                samples.append(Sample(round(t, 6), x, y, yaw, v, w))
                next_sample += 1.0 / ODOM_HZ
    return samples


def test_forwards_for_five_seconds():
    samples = drive([(0.5, 0, 0), (5.0, 0.1, 0), (1.5, 0, 0)])
    motion = summarize(samples, since_s=100.5)
    assert motion.forward_m == pytest.approx(0.5, abs=0.005)
    assert motion.lateral_m == pytest.approx(0.0, abs=1e-9)
    assert motion.turn_deg == pytest.approx(0.0, abs=1e-9)
    assert motion.duration_s == pytest.approx(5.0, abs=0.15)       # the ramp and the 30 Hz sampling
    assert motion.start_s == pytest.approx(100.5, abs=0.05)
    assert motion.still_at_end and motion.moved
    assert motion.excursion_m == pytest.approx(motion.displacement_m)


def test_backwards_reads_negative_forward_and_is_told_apart_from_forwards():
    motion = summarize(drive([(2.0, -0.1, 0), (1.0, 0, 0)]), since_s=100.0)
    assert motion.forward_m == pytest.approx(-0.2, abs=0.005)
    assert motion.duration_s == pytest.approx(2.0, abs=0.15)
    assert motion.still_at_end


def test_displacement_is_in_the_robot_initial_frame():
    """Facing +y from (1, 2): driving forwards is +forward, whatever the world axes say."""
    motion = summarize(drive([(2.0, 0.1, 0), (1.0, 0, 0)], start=(1.0, 2.0, math.pi / 2)), since_s=100.0)
    assert motion.forward_m == pytest.approx(0.2, abs=0.005)
    assert motion.lateral_m == pytest.approx(0.0, abs=1e-6)


def test_lateral_is_positive_to_the_left():
    samples = [Sample(0.0, 0, 0, 0, 0, 0), Sample(0.1, 0.0, 0.05, 0, 0, 0)]
    assert summarize(samples, since_s=0.0).lateral_m == pytest.approx(0.05)


def test_turning_left_is_counter_clockwise_and_hardly_moves():
    motion = summarize(drive([(3.0, 0, 0.3), (1.0, 0, 0)]), since_s=100.0)
    assert motion.turn_deg == pytest.approx(math.degrees(0.9), abs=1.0)
    assert motion.excursion_m < 1e-9
    assert motion.duration_s == pytest.approx(3.0, abs=0.4)


def test_turning_right_is_clockwise():
    motion = summarize(drive([(3.0, 0, -0.3), (1.0, 0, 0)]), since_s=100.0)
    assert motion.turn_deg == pytest.approx(-math.degrees(0.9), abs=1.0)


def test_turn_is_accumulated_past_half_a_turn():
    """Two full turns read 720 degrees, not 0: yaw is unwrapped sample by sample."""
    motion = summarize(drive([(4 * math.pi / 1.0, 0, 1.0), (2.0, 0, 0)], ramp=100.0), since_s=100.0)
    assert motion.turn_deg == pytest.approx(720.0, abs=2.0)


def test_a_wrong_duration_is_measured_as_it_is():
    motion = summarize(drive([(3.0, 0.1, 0), (1.0, 0, 0)]), since_s=100.0)
    assert motion.duration_s == pytest.approx(3.0, abs=0.15)


def test_never_stops_has_no_stop_time_and_runs_to_the_last_sample():
    samples = drive([(0.5, 0, 0), (4.0, 0.1, 0)])
    motion = summarize(samples, since_s=100.5)
    assert motion.stop_s is None and not motion.still_at_end
    assert motion.duration_s == pytest.approx(samples[-1].t - motion.start_s)
    assert motion.end_v == pytest.approx(0.1)


def test_no_motion():
    motion = summarize(drive([(2.0, 0, 0)]), since_s=100.0)
    assert not motion.moved and motion.start_s is None and motion.duration_s == 0.0
    assert motion.excursion_m == 0.0 and motion.still_at_end


def test_excursion_sees_a_robot_that_came_back():
    motion = summarize(drive([(1.0, 0.1, 0), (1.0, -0.1, 0), (1.0, 0, 0)]), since_s=100.0)
    assert abs(motion.forward_m) < 0.01
    assert motion.excursion_m > 0.09


def test_the_origin_is_the_pose_when_the_request_was_sent():
    """Motion before the request (samples before since_s) does not count."""
    samples = drive([(2.0, 0.1, 0), (1.0, 0, 0), (2.0, 0.1, 0), (1.0, 0, 0)])
    first_leg_end = max(s for s in samples if s.t <= 103.0).t
    motion = summarize(samples, since_s=first_leg_end)
    assert motion.forward_m == pytest.approx(0.2, abs=0.01)
    assert motion.start_s > 103.0


def test_no_samples_is_an_error():
    with pytest.raises(MotionError):
        summarize([], since_s=0.0)


def test_evidence_has_the_schema_fields():
    motion = summarize(drive([(1.0, 0.1, 0), (1.0, 0, 0)]), since_s=100.0)
    evidence = motion.as_evidence()
    assert {"duration_s", "forward_m", "lateral_m", "turn_deg", "still_at_end"} <= set(evidence)
    assert evidence["started_after_s"] == pytest.approx(0.033, abs=0.002)


def test_thin_keeps_at_most_400_points_with_first_and_last_and_times_since_the_request():
    samples = drive([(20.0, 0.1, 0.1)])
    assert len(samples) > MAX_TRAJECTORY_POINTS
    points = thin(samples, since_s=100.0)
    assert len(points) == MAX_TRAJECTORY_POINTS
    assert points[0][0] == 0.0 and points[-1][0] == pytest.approx(20.0, abs=0.04)
    assert points[-1][1] == round(samples[-1].x, 4)
    assert [p[0] for p in points] == sorted(p[0] for p in points)
    assert thin(samples, 100.0) == points                   # deterministic


def test_thin_keeps_short_recordings_whole():
    samples = drive([(1.0, 0.1, 0)])
    assert len(thin(samples, 100.0)) == len(samples)
