"""S7-1500T V5 §3.3.4 / §3.3.6 / §6.1.5.8 / §A.1.10 / §A.1.32: extrapolation of actual leading values."""
import pytest

from _lh import encoder_rig


def _settle(ctl, gears, t=0.5):
    ctl.run_until(lambda: all(g.InGear for g in gears), timeout=2.0)
    ctl.run(t)


def test_s7_1500_leading_axis_dependent_time_is_ti_tipo_plus_position_filters_s3_3_6():
    ctl, enc, _, gears, _ = encoder_rig({"PositionFilter": {"T1": 0.003, "T2": 0.002}}, plant={"Velocity": 100.0})
    _settle(ctl, gears, 0.05)
    # T_i + T_Ipo (one servo cycle each, decision 29) + T1 + T2
    assert enc.Extrapolation.LeadingAxisDependentTime == pytest.approx(0.001 + 0.001 + 0.003 + 0.002)


@pytest.mark.parametrize("sde", [0, 1])
def test_s7_1500_extrapolated_position_is_filtered_plus_velocity_times_effective_time_s3_3_4(sde):
    """Effective extrapolation time = (LeadingAxisDependentTime if SystemDefinedExtrapolation = 1)
    + FollowingAxisDependentTime + CrossPlcSynchronousOperation.LocalLeadingValueDelayTime."""
    ctl, enc, _, gears, _ = encoder_rig(
        {"PositionFilter": {"T1": 0.002}, "VelocityFilter": {"T1": 0.005},
         "FollowingAxisDependentTime": 0.005, "Settings": {"SystemDefinedExtrapolation": sde}},
        plant={"Velocity": 150.0}, extra={"CrossPlcSynchronousOperation": {"LocalLeadingValueDelayTime": 0.003}})
    _settle(ctl, gears)
    se = enc.StatusExtrapolation
    t_eff = 0.005 + 0.003 + (enc.Extrapolation.LeadingAxisDependentTime if sde else 0.0)
    assert se.ExtrapolatedPosition == pytest.approx(se.FilteredPosition + se.FilteredVelocity * t_eff, abs=1e-6)


def test_s7_1500_following_axis_dependent_time_changed_at_runtime_takes_effect_s3_3_4_dir():
    ctl, enc, _, gears, _ = encoder_rig({"Settings": {"SystemDefinedExtrapolation": 0}}, plant={"Velocity": 100.0})
    _settle(ctl, gears, 0.2)
    se = enc.StatusExtrapolation
    assert se.ExtrapolatedPosition == pytest.approx(se.FilteredPosition, abs=1e-6)
    enc.write_tag("Extrapolation.FollowingAxisDependentTime", 0.002)       # DIR tag, small step (NOTICE)
    ctl.run(0.02)
    assert se.ExtrapolatedPosition == pytest.approx(se.FilteredPosition + se.FilteredVelocity * 0.002, abs=1e-6)


def test_s7_1500_constant_velocity_delay_is_compensated_s3_3_4():
    v = 200.0
    ctl, enc, (s,), gears, _ = encoder_rig(
        {"PositionFilter": {"T1": 0.002}, "VelocityFilter": {"T1": 0.01, "T2": 0.01}, "FollowingAxisDependentTime": 0.01},
    )
    fn = (lambda t: v * t)
    enc.drive_plant(fn)
    _settle(ctl, gears)
    for _ in range(5):
        ctl.run(0.05)
        # the LV is where the machine will be after T_Ipo + FollowingAxisDependentTime (see the product's
        # own acceptance test: plant + v * T_Ipo with FollowingAxisDependentTime = 0)
        assert enc.StatusExtrapolation.ExtrapolatedPosition == pytest.approx(fn(ctl.time + 0.011), abs=0.01)


def test_s7_1500_constant_acceleration_delay_is_compensated_s3_3_4():
    """§3.3.4: 'Delay times at constant velocity or at constant acceleration or deceleration can be
    compensated for with the extrapolation.'  Only a change of acceleration (jerk) displaces the follower."""
    a = 2000.0
    ctl, enc, (s,), gears, _ = encoder_rig(
        {"PositionFilter": {"T1": 0.002}, "VelocityFilter": {"T1": 0.01, "T2": 0.01}, "FollowingAxisDependentTime": 0.01})
    fn = (lambda t: 0.5 * a * t * t)
    enc.drive_plant(fn)
    _settle(ctl, gears)
    errors = []
    for _ in range(5):
        ctl.run(0.05)
        errors.append(enc.StatusExtrapolation.ExtrapolatedPosition - fn(ctl.time + 0.011))
    # same reference as at constant velocity; the manual says this delay is compensated as well
    assert max(abs(e) for e in errors) < 0.05, f"steady-state error at constant acceleration: {errors}"


def test_s7_1500_effective_leading_value_acceleration_of_an_accelerating_actual_value_s3_5_1():
    """§3.5.1/§A.1.33: EffectiveLeadingValue.Acceleration is the acceleration of the effective leading value."""
    a = 2000.0
    ctl, enc, (s,), gears, _ = encoder_rig({"VelocityFilter": {"T1": 0.005}})
    enc.drive_plant(lambda t: 0.5 * a * t * t)
    _settle(ctl, gears, 0.3)
    assert s.StatusSynchronizedMotion.EffectiveLeadingValue.Acceleration == pytest.approx(a, rel=0.1)


@pytest.mark.parametrize("mode", [0, 1])
def test_s7_1500_extrapolated_velocity_mode_s3_3_4(mode):
    a = 1000.0
    ctl, enc, (s,), gears, _ = encoder_rig(
        {"VelocityFilter": {"T1": 0.01}, "FollowingAxisDependentTime": 0.01,
         "Settings": {"ExtrapolatedVelocityMode": mode}})
    enc.drive_plant(lambda t: 0.5 * a * t * t)
    _settle(ctl, gears, 0.3)
    se = enc.StatusExtrapolation
    p0, t0 = se.ExtrapolatedPosition, ctl.time
    ctl.run(0.004)
    p1, t1 = se.ExtrapolatedPosition, ctl.time
    if mode == 0:
        assert se.ExtrapolatedVelocity == pytest.approx(se.FilteredVelocity, abs=1e-9)
    else:
        # differentiation of the extrapolated LV position
        assert se.ExtrapolatedVelocity == pytest.approx((p1 - p0) / (t1 - t0), rel=0.01)


def test_s7_1500_tolerance_band_play_operator_s3_3_4():
    """Tolerance band: no new output while the filtered velocity stays within the band; when it moves
    more than half the band from the last output, the new output is the velocity minus (plus) half the band."""
    ctl, enc, (s,), gears, _ = encoder_rig({"VelocityTolerance": {"Range": 10.0},
                                            "PositionFilter": {"T1": 0.0, "T2": 0.0},
                                            "VelocityFilter": {"T1": 0.0, "T2": 0.0},
                                            "Settings": {"SystemDefinedExtrapolation": 0}},
                                           plant={"Velocity": 100.0}, app_cycle=0.001)
    _settle(ctl, gears, 0.1)
    se = enc.StatusExtrapolation
    out = se.FilteredVelocity
    assert abs(out - 100.0) <= 5.0 + 1e-6
    for v in (103.0, 108.0, 104.0, 99.0, 90.0, 97.0, 94.0):
        enc.set_plant_velocity(v)
        ctl.run(0.01)
        expect = min(max(out, v - 5.0), v + 5.0)
        assert se.FilteredVelocity == pytest.approx(expect, abs=1e-3), (v, se.FilteredVelocity)
        out = se.FilteredVelocity


def _hysteresis_rig(value):
    ctl, enc, (s,), gears, _ = encoder_rig({"Hysteresis": {"Value": value},
                                            "Settings": {"SystemDefinedExtrapolation": 0}},
                                           app_cycle=0.001)
    return ctl, enc, s, gears


def test_s7_1500_hysteresis_suppresses_reversal_smaller_than_value_s3_3_4():
    ctl, enc, s, gears = _hysteresis_rig(2.0)
    # forward 10 mm, back 1.5 mm (< hysteresis), forward again
    prof = lambda t: 100 * t if t < 0.1 else 10 - 100 * (t - 0.1) if t < 0.115 else 8.5 + 100 * (t - 0.115)
    enc.drive_plant(prof)
    ctl.run_until(lambda: gears[0].InGear, timeout=1.0)
    se = enc.StatusExtrapolation
    last = se.ExtrapolatedPosition
    while ctl.time < 0.2:
        ctl.step()
        assert se.ExtrapolatedPosition >= last - 1e-9, "leading value reversed within the hysteresis"
        last = se.ExtrapolatedPosition


def test_s7_1500_hysteresis_lets_a_reversal_larger_than_value_through_s3_3_4():
    ctl, enc, s, gears = _hysteresis_rig(2.0)
    prof = lambda t: 100 * t if t < 0.1 else 10 - 100 * (t - 0.1)
    enc.drive_plant(prof)
    ctl.run_until(lambda: ctl.time >= 0.15)
    # the position moved back by 5 mm > 2 mm: the reversal has taken effect
    assert enc.StatusExtrapolation.ExtrapolatedPosition < 9.0


def test_s7_1500_hysteresis_does_not_displace_the_leading_value_without_reversal_s3_3_4():
    """The hysteresis acts on a change of direction only ('A change of direction only takes effect when
    ...'); in steady one-way motion the LV is the extrapolated position."""
    ctl, enc, s, gears = _hysteresis_rig(2.0)
    enc.set_plant_velocity(100.0)
    ctl.run_until(lambda: gears[0].InGear, timeout=1.0)
    ctl.run(0.2)
    se = enc.StatusExtrapolation
    assert se.ExtrapolatedPosition == pytest.approx(se.FilteredPosition, abs=1e-3)
