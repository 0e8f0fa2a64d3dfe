"""Drive connection via PTO (pulse train output), derived from the S7-1200 Motion Control V6 manual and the V7
update.

§2.1.1 (pulse output limit frequencies, low limit 1 Hz), §2.1.3 / §5.4.3.2 (signal types; A/B quadruple:
every edge is a step), §5.4.4.1 (Actor.DirectionMode, direction output), §5.4.4.4 (start/stop velocity,
ramp-up time = (max velocity - start/stop velocity) / acceleration), §12.1 (several axes on one PTO),
§12.5 (short positioning), §12.8 (16#8005, 16#8008, 16#8407, 16#8606, 16#8607, 16#861A, V7 16#864A),
V7 §12.9 Actor.PTOSliceTime.  Project decisions respected: docs/decisions.md rows 17, 47, 48, 49.

Axis: 1000 pulses per motor revolution, 10 mm per revolution, so 1 pulse = 0.01 mm and 100 kHz = 1000 mm/s.
"""
from __future__ import annotations

import pytest

from plcmotion import ConfigurationError, Controller
from plcmotion.kernel.faults import config_fault
from plcmotion.s7_1200 import (
    MC_CommandTable,
    MC_Halt,
    MC_Home,
    MC_MoveAbsolute,
    MC_MoveJog,
    MC_MoveRelative,
    MC_MoveVelocity,
    MC_Power,
    MC_Reset,
    MC_WriteParam,
    codes,
)
from plcmotion.s7_1200.variables import Int, Real

PULSE = 0.01          # mm per pulse with the start values (10 mm / 1000 pulses)


def params(*, vmax: float = 100.0, vmin: float = 1.0, acc: float = 100.0, dec: float = 100.0,
           actor: dict | None = None, **extra) -> dict:
    p = {"Actor": {"Type": 2, **(actor or {})},
         "DynamicLimits": {"MaxVelocity": vmax, "MinVelocity": vmin},
         "DynamicDefaults": {"Acceleration": acc, "Deceleration": dec, "EmergencyDeceleration": 10 * dec,
                             "Jerk": 0.0}}
    p.update(extra)
    return p


class Pto:
    def __init__(self, cfg: dict | None = None, *, servo: float = 0.001, app: float = 0.004, enable: bool = True,
                 version: int = 6):
        self.ctl = Controller(servo_cycle=servo, app_cycle=app, technology_version=version)
        self.servo = servo
        self.axis = self.ctl.add_positioning_axis("Axis_1", cfg or params())
        self.power = MC_Power(Axis=self.axis, Enable=enable)
        self.fbs: list = [self.power]
        self.trace: list[tuple[float, float, float]] = []
        self.ctl.on_post_servo(lambda t: self.trace.append((t, self.axis.Position, self.axis.Velocity)))
        if enable:
            self.until(lambda: self.power.Status, 20)

    def add(self, fb):
        if getattr(fb, "Axis", None) is None:
            fb.Axis = self.axis
        self.fbs.append(fb)
        return fb

    def scan(self) -> None:
        for fb in self.fbs:
            fb()
        self.ctl.step()

    def until(self, cond, max_scans: int = 2000, what: str = "condition") -> None:
        for _ in range(max_scans):
            self.scan()
            if cond():
                return
        raise AssertionError(f"{what} not reached (t = {self.ctl.time:.4f} s)")


def config_errors(cfg: dict) -> set[tuple[int, int]]:
    """(ErrorID, ErrorInfo) of the configuration errors (§12.8 16#86xx) of an axis configuration."""
    try:
        Controller().add_positioning_axis("Axis_1", cfg)
    except ConfigurationError as exc:
        return {codes(config_fault(i.path, i.reason)) for i in exc.issues}
    return set()


def moving_samples(trace):
    return [(t, p, v) for t, p, v in trace if v != 0.0]


# ==========================================================================================================
# start/stop velocity
@pytest.mark.parametrize("how", ["MC_MoveRelative", "MC_MoveVelocity+MC_Halt", "MC_MoveJog"])
def test_s7_1200_5_4_4_4_profile_starts_and_ends_at_start_stop_velocity(how):
    """§5.4.4.4: the start/stop velocity is the minimum permissible velocity of a PTO axis; the ramps run
    between the start/stop velocity and the maximum velocity (ramp time = (max - start/stop) / acceleration),
    §12.6: the first pulse is output at the start/stop velocity.  The setpoint velocity jumps 0 -> 10 mm/s at
    the start and 10 mm/s -> 0 at the end, never lying in between."""
    b = Pto(params(vmin=10.0))
    if how == "MC_MoveRelative":
        fb = b.add(MC_MoveRelative(Execute=True, Distance=20.0, Velocity=50.0))
        b.until(lambda: fb.Done)
    elif how == "MC_MoveJog":
        fb = b.add(MC_MoveJog(JogForward=True, Velocity=50.0))
        b.until(lambda: fb.InVelocity)
        fb.JogForward = False
        b.until(lambda: not fb.Busy)
    else:
        fb = b.add(MC_MoveVelocity(Execute=True, Velocity=50.0))
        b.until(lambda: fb.InVelocity)
        halt = b.add(MC_Halt(Execute=True))
        b.until(lambda: halt.Done)
    moving = moving_samples(b.trace)
    assert moving and all(abs(v) >= 10.0 - 1e-9 for _, _, v in moving)
    assert abs(moving[0][2]) <= 10.0 + 100.0 * b.servo + 1e-9, "starts at the start/stop velocity"
    assert abs(moving[-1][2]) <= 10.0 + 100.0 * b.servo + 1e-9, "ends at the start/stop velocity"
    assert b.axis.Velocity == 0.0


def test_s7_1200_5_4_4_4_ramp_up_time_from_start_stop_velocity():
    """§5.4.4.4: "Ramp-up time = (maximum velocity - start/stop velocity) / acceleration" -- 100 mm/s with
    start/stop 10 mm/s and 100 mm/s^2 is reached after 0.9 s (not 1.0 s)."""
    b = Pto(params(vmin=10.0))
    t0 = b.ctl.time
    mv = b.add(MC_MoveVelocity(Execute=True, Velocity=100.0))
    b.until(lambda: mv.InVelocity)
    t_reached = next(t for t, _, v in b.trace if v == pytest.approx(100.0))
    assert t_reached - t0 == pytest.approx(0.9, abs=2 * b.servo)


# ==========================================================================================================
# limit frequency of the pulse output
@pytest.mark.parametrize("f_lim", [20000.0, 100000.0, 200000.0, 1000000.0])
def test_s7_1200_2_1_1_max_velocity_up_to_limit_frequency(f_lim):
    """§2.1.1 pulse output limit frequencies (20 kHz, 100 kHz, 200 kHz, 1 MHz); §5.4.4.4 "Maximum velocity
    ... PTO: 1 ... limit frequency": a MaxVelocity above the limit frequency is the configuration error
    16#8607/16#0003 "Value is higher than the high hardware limit"."""
    v_lim = f_lim * PULSE
    assert config_errors(params(vmax=v_lim, **{"Plant.PTOLimitFrequency": f_lim})) == set()
    assert (0x8607, 0x0003) in config_errors(params(vmax=v_lim * 1.001, **{"Plant.PTOLimitFrequency": f_lim}))


@pytest.mark.parametrize("signal_type, factor", [(2, 1), (3, 1), (4, 1), (5, 4)])
def test_s7_1200_2_1_3_quadruple_a_b_allows_four_times_the_step_rate(signal_type, factor):
    """§2.1.3 / §5.4.3.2: "PTO (A/B phase-shifted - quadruple)": every edge of A and B is a step, so the output
    frequency is a quarter of the step rate -- with a 100 kHz output the axis may run at 4 x 100 k steps/s.
    The other signal types output one period per step."""
    v_lim = 100000.0 * PULSE * factor
    cfg = params(vmax=v_lim, actor={"Interface": {"PTO_SignalType": signal_type}})
    assert config_errors(cfg) == set()
    cfg = params(vmax=v_lim * 1.01, actor={"Interface": {"PTO_SignalType": signal_type}})
    assert (0x8607, 0x0003) in config_errors(cfg)


def test_s7_1200_2_1_1_start_stop_velocity_at_least_1_hz():
    """§2.1.1 "The low limit frequency is always 1 Hz"; §12.8 16#8606/16#0004 start/stop velocity "lower than
    the low hardware limit" (0.005 mm/s = 0.5 pulses/s); 16#8606/16#0007 start/stop above the maximum."""
    assert config_errors(params(vmin=PULSE)) == set()
    assert (0x8606, 0x0004) in config_errors(params(vmin=0.5 * PULSE))
    assert (0x8606, 0x0007) in config_errors(params(vmin=50.0, vmax=40.0))


def test_s7_1200_12_8_8607_max_velocity_written_above_limit_frequency_refuses_enable():
    """MaxVelocity is writable with MC_WriteParam while the axis is disabled, effective when it is enabled
    (§12.9.10 "WP", effective code 2); a value above the limit frequency (100 kHz = 1000 mm/s) is the
    configuration error 16#8607/16#0003 at MC_Power and the axis is not enabled."""
    b = Pto(enable=False)
    wp = MC_WriteParam(Parameter=b.axis.ref("DynamicLimits.MaxVelocity"), Value=Real(1500.0), Execute=True)
    wp()
    assert wp.Done
    b.power.Enable = True
    for _ in range(5):
        b.scan()
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (0x8607, 0x0003)
    assert not b.power.Status and not b.axis.StatusBits.Enable


# ==========================================================================================================
# §12.5 short positioning
def _short(distance: float):
    b = Pto(params(vmin=10.0, acc=1.0e5, dec=1.0e5), servo=0.0001, app=0.001)
    mr = b.add(MC_MoveRelative(Execute=True, Distance=distance, Velocity=100.0))
    b.until(lambda: mr.Done, 200)
    moving = moving_samples(b.trace)
    duration = moving[-1][0] - moving[0][0] + b.servo
    return b, moving, duration


def test_s7_1200_12_5_short_positioning_runs_at_pulses_times_500_hz():
    """§12.5: a positioning whose planned duration is < 2 ms runs at "Reduced velocity = Number of pulses to be
    output * 500 Hz" for the entire duration: 0.1 mm = 10 pulses (planned about 1.8 ms with 10^5 mm/s^2)
    -> 5000 pulses/s = 50 mm/s, i.e. the motion lasts 2 ms."""
    b, moving, duration = _short(0.1)
    assert all(v == pytest.approx(10 * 500.0 * PULSE) for _, _, v in moving)
    assert duration == pytest.approx(0.002, abs=1.5 * b.servo)
    assert b.axis.Position == pytest.approx(0.1) and b.axis.ActualPosition == pytest.approx(0.1)


def test_s7_1200_12_5_no_reduction_from_2_ms():
    """§12.5: "Velocity is not reduced if the planned positioning duration is >= 2 ms" -- 0.2 mm with the same
    dynamics takes about 2.8 ms and reaches the commanded 100 mm/s."""
    b, moving, duration = _short(0.2)
    assert max(v for _, _, v in moving) == pytest.approx(100.0)
    assert duration > 0.0025
    assert b.axis.Position == pytest.approx(0.2)


# ==========================================================================================================
# permitted direction of rotation
def _assert_error(fb, error_id, error_info):
    assert fb.Error, fb.outputs
    assert (fb.ErrorID, fb.ErrorInfo) == (error_id, error_info)


@pytest.mark.parametrize("mode, make", [
    (1, lambda: MC_MoveRelative(Execute=True, Distance=-10.0, Velocity=20.0)),
    (1, lambda: MC_MoveVelocity(Execute=True, Velocity=-20.0)),
    (1, lambda: MC_MoveVelocity(Execute=True, Velocity=20.0, Direction=2)),
    (1, lambda: MC_MoveJog(JogBackward=True, Velocity=20.0)),
    (1, lambda: MC_MoveAbsolute(Execute=True, Position=-10.0, Velocity=20.0)),
    (2, lambda: MC_MoveRelative(Execute=True, Distance=10.0, Velocity=20.0)),
    (2, lambda: MC_MoveJog(JogForward=True, Velocity=20.0)),
], ids=["rel-", "vel-", "vel-dir2", "jog-", "abs-", "mode2-rel+", "mode2-jog+"])
def test_s7_1200_5_4_4_1_direction_not_permitted_8008_002E(mode, make):
    """§5.4.4.1 "Permitted direction of rotation" (Actor.DirectionMode 1 positive, 2 negative); §12.8
    16#8008/16#002E "The selected motion direction is not allowed" -- an operating error with axis stop
    (§9.6: at the instruction and at MC_Power, ErrorBits.DirectionFault); the axis does not move."""
    b = Pto(params(actor={"DirectionMode": mode}))
    MC_Home(Axis=b.axis, Mode=0, Position=0.0, Execute=True)()          # for MC_MoveAbsolute
    fb = b.add(make())
    for _ in range(5):
        b.scan()
    _assert_error(fb, 0x8008, 0x002E)
    _assert_error(b.power, 0x8008, 0x002E)
    assert b.axis.ErrorBits.DirectionFault and b.axis.StatusBits.Error
    assert b.axis.Position == 0.0
    b.fbs.remove(fb)
    reset = b.add(MC_Reset(Execute=True))
    b.scan()
    assert reset.Done and not b.axis.StatusBits.Error
    ok = b.add(MC_MoveRelative(Execute=True, Distance=5.0 if mode == 1 else -5.0, Velocity=20.0))
    b.until(lambda: ok.Done)
    assert b.axis.Position == pytest.approx(5.0 if mode == 1 else -5.0)


def test_s7_1200_5_4_4_1_reversal_not_possible_8008_002F():
    """§12.8 16#8008/16#002F "A reversing motion is not possible with the selected motion direction": with
    only the positive direction permitted, the axis moving at 50 mm/s (braking distance 12.5 mm) cannot reach
    a target 1 mm ahead without reversing; it is stopped with the configured deceleration (decision 17) and
    never moves backwards."""
    b = Pto(params(actor={"DirectionMode": 1}))
    mv = b.add(MC_MoveVelocity(Execute=True, Velocity=50.0))
    b.until(lambda: mv.InVelocity)
    mr = b.add(MC_MoveRelative(Execute=True, Distance=1.0, Velocity=50.0))
    b.until(lambda: mr.Error or mr.Done, 10)
    _assert_error(mr, 0x8008, 0x002F)
    b.until(lambda: b.axis.Velocity == 0.0, 500)
    _assert_error(b.power, 0x8008, 0x002F)
    vs = [v for _, _, v in b.trace]
    assert min(vs) >= 0.0
    ps = [p for _, p, _ in b.trace]
    assert all(p2 >= p1 - 1e-12 for p1, p2 in zip(ps, ps[1:]))


@pytest.mark.parametrize("direction_mode, ok", [(0, False), (1, True), (2, True)])
def test_s7_1200_12_8_861A_002D_both_directions_without_direction_output(direction_mode, ok):
    """§2.1.1 / §5.4.3.2: with the direction output deactivated the direction is restricted; §12.8
    16#861A/16#002D "'Both directions' not allowed when direction output is deactivated"."""
    cfg = params(actor={"DirectionMode": direction_mode,
                        "Interface": {"PTO_SignalType": 2, "PTO_OutputBEnable": False}})
    errors = config_errors(cfg)
    assert (errors == set()) if ok else ((0x861A, 0x002D) in errors)
    # with the direction output both directions are fine
    assert config_errors(params(actor={"DirectionMode": 0, "Interface": {"PTO_OutputBEnable": True}})) == set()


def test_s7_1200_12_8_861A_written_both_directions_refused_at_enable():
    """Actor.DirectionMode is written with MC_WriteParam while disabled, effective at the enable (§12.9.5
    "WP", effective code 2): "both directions" without direction output -> 16#861A/16#002D at MC_Power."""
    b = Pto(params(actor={"DirectionMode": 1, "Interface": {"PTO_OutputBEnable": False}}), enable=False)
    wp = MC_WriteParam(Parameter=b.axis.ref("Actor.DirectionMode"), Value=Int(0), Execute=True)
    wp()
    assert wp.Done
    b.power.Enable = True
    for _ in range(3):
        b.scan()
    _assert_error(b.power, 0x861A, 0x002D)
    assert not b.power.Status


def test_s7_1200_12_8_861A_0011_invalid_selection():
    """§12.8 16#861A/16#0011 "The selection value is invalid" (Actor.DirectionMode 0..2)."""
    assert (0x861A, 0x0011) in config_errors(params(actor={"DirectionMode": 3}))


# ==========================================================================================================
# §12.1 several axes on one PTO
def two_axes():
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    ax1 = ctl.add_positioning_axis("Axis_1", params(vmax=100.0, actor={"Interface": {"PTO": 1}}))
    ax2 = ctl.add_positioning_axis("Axis_2", params(vmax=200.0, vmin=2.0, actor={"Interface": {"PTO": 1}}))
    return ctl, ax1, ax2


def test_s7_1200_12_1_only_one_axis_at_a_time_uses_the_pto():
    """§12.1: "Only one axis at a time may use the PTO"; the axis using it shows StatusBits.Activated = TRUE
    and ErrorBits.HWUsed = FALSE; the instructions of the other axis indicate errors: enabling it while the
    active one is enabled -> 16#8407/16#0001, a motion command -> 16#8005/16#0001 "PTO/HSC are already being
    used by another axis"; its tags show Activated = FALSE, HWUsed = TRUE."""
    ctl, ax1, ax2 = two_axes()
    p2 = MC_Power(Axis=ax2, Enable=True)
    p1 = MC_Power(Axis=ax1, Enable=True)
    mv2 = MC_MoveVelocity(Axis=ax2, Execute=True, Velocity=50.0)
    mr1 = MC_MoveRelative(Axis=ax1, Execute=True, Distance=5.0, Velocity=20.0)
    for _ in range(3):
        p2()
        ctl.step()
    assert p2.Status and ax2.StatusBits.Activated and not ax2.ErrorBits.HWUsed
    for _ in range(200):
        p2()
        p1()
        mv2()
        mr1()
        ctl.step()
    _assert_error(p1, 0x8407, 0x0001)
    _assert_error(mr1, 0x8005, 0x0001)
    assert not p1.Status and not ax1.StatusBits.Enable
    assert not ax1.StatusBits.Activated and ax1.ErrorBits.HWUsed
    assert ax2.StatusBits.Activated and not ax2.ErrorBits.HWUsed and not p2.Error
    assert mv2.InVelocity and mv2.Busy and ax2.Velocity == pytest.approx(50.0)
    assert ax1.Position == 0.0


def test_s7_1200_12_1_switchover_procedure():
    """§12.1 switchover from "Positioning axis_2" to "Positioning axis_1": (1) end the motions of axis_2, (2)
    MC_Power Enable = FALSE, (3) Status = FALSE AND StatusBits.Enable = FALSE, (4) stop calling axis_2's
    instructions, (5) at the first call of axis_1's MC_Power axis_2 is deactivated and axis_1 activated, (6)
    Enable = TRUE, (7) Status = TRUE AND StatusBits.Enable = TRUE.  Axis_1 then runs with its own
    configuration (MaxVelocity 100 mm/s)."""
    ctl, ax1, ax2 = two_axes()
    p2 = MC_Power(Axis=ax2, Enable=True)
    for _ in range(3):
        p2()
        ctl.step()
    mr2 = MC_MoveRelative(Axis=ax2, Execute=True, Distance=10.0, Velocity=150.0)
    for _ in range(500):
        p2()
        mr2()
        ctl.step()
        if mr2.Done:
            break
    assert mr2.Done                                                             # (1)
    p2.Enable = False                                                           # (2)
    for _ in range(100):
        p2()
        ctl.step()
        if not p2.Status and not ax2.StatusBits.Enable:                        # (3)
            break
    assert not p2.Status and not ax2.StatusBits.Enable
    assert ax2.StatusBits.Activated                                             # still holds the PTO
    p1 = MC_Power(Axis=ax1, Enable=False)                                       # (4), (5)
    p1()
    assert ax1.StatusBits.Activated and not ax2.StatusBits.Activated and not p1.Error
    p1.Enable = True                                                            # (6)
    for _ in range(10):
        p1()
        ctl.step()
        if p1.Status and ax1.StatusBits.Enable:                                 # (7)
            break
    assert p1.Status and ax1.StatusBits.Enable and not p1.Error
    assert ax1.StatusBits.Activated and not ax1.ErrorBits.HWUsed
    assert not ax2.StatusBits.Activated and ax2.ErrorBits.HWUsed
    too_fast = MC_MoveVelocity(Axis=ax1, Execute=True, Velocity=150.0)        # axis_1's own MaxVelocity
    too_fast()
    _assert_error(too_fast, 0x8402, 0x0008)
    mr1 = MC_MoveRelative(Axis=ax1, Execute=True, Distance=5.0, Velocity=50.0)
    for _ in range(500):
        p1()
        mr1()
        ctl.step()
        if mr1.Done:
            break
    assert mr1.Done and ax1.Position == pytest.approx(5.0)
    # switching back while axis_1 is enabled is refused
    p2.Enable = True
    p2()
    _assert_error(p2, 0x8407, 0x0001)
    assert ax1.StatusBits.Activated and p1.Status


def test_s7_1200_12_1_axes_on_different_ptos_do_not_interfere():
    """§12.1 applies to axes referencing the same PTO; axes on PTO1 and PTO2 are enabled together."""
    ctl = Controller()
    ax1 = ctl.add_positioning_axis("Axis_1", params(actor={"Interface": {"PTO": 1}}))
    ax2 = ctl.add_positioning_axis("Axis_2", params(actor={"Interface": {"PTO": 2}}))
    p1, p2 = MC_Power(Axis=ax1, Enable=True), MC_Power(Axis=ax2, Enable=True)
    for _ in range(3):
        p1()
        p2()
        ctl.step()
    assert p1.Status and p2.Status and not p1.Error and not p2.Error
    assert ax1.StatusBits.Activated and ax2.StatusBits.Activated
    assert not ax1.ErrorBits.HWUsed and not ax2.ErrorBits.HWUsed


# ==========================================================================================================
# V7 Actor.PTOSliceTime
@pytest.mark.parametrize("value, ok_or_codes", [(2, None), (20, None), (21, (0x864A, 0x006D)),
                                                 (25, (0x864A, 0x006D)), (1, (0x864A, 0x006E)),
                                                 (0, (0x864A, 0x006E))])
def test_s7_1200_v7_pto_slice_time_range(value, ok_or_codes):
    """V7 §12.9 Actor.PTOSliceTime 2..20 ms; V7 §12.8 16#864A "invalid Actor.PTOSliceTime": 16#006D value
    > 20 ms, 16#006E value < 2 ms (configuration errors)."""
    errors = config_errors(params(actor={"PTOSliceTime": value}))
    if ok_or_codes is None:
        assert errors == set()
    else:
        assert ok_or_codes in errors


def test_s7_1200_v7_pto_slice_time_written_invalid_refuses_enable():
    """V7: Actor.PTOSliceTime is "R, WP_PTO; effective 2" -- written with MC_WriteParam while disabled, checked
    when the axis is enabled: 25 ms -> configuration error 16#864A/16#006D at MC_Power."""
    b = Pto(enable=False)
    wp = MC_WriteParam(Parameter=b.axis.ref("Actor.PTOSliceTime"), Value=Int(25), Execute=True)
    wp()
    assert wp.Done
    b.power.Enable = True
    for _ in range(3):
        b.scan()
    _assert_error(b.power, 0x864A, 0x006D)
    assert not b.power.Status


def _first_change(trace, after: float, value: float) -> float:
    return next(t for t, _, v in trace if t > after and v != pytest.approx(value))


def test_s7_1200_v7_pto_slice_time_command_starts_at_segment_boundary():
    """V7 §12.9 Actor.PTOSliceTime: motion commands are processed in segments, a new command becomes effective
    at the segment boundary (decision 49): with 10 ms a MC_MoveVelocity issued at t = 12 ms starts at 20 ms,
    an override issued at 304 ms changes the velocity from 310 ms on."""
    b = Pto(params(actor={"PTOSliceTime": 10}), version=7)      # a V7.0 technology object
    while b.ctl.time < 0.012 - 1e-9:
        b.scan()
    assert b.ctl.time == pytest.approx(0.012)
    mv = b.add(MC_MoveVelocity(Execute=True, Velocity=20.0))
    b.scan()
    b.scan()
    t_start = next(t for t, _, v in b.trace if v != 0.0)
    assert 0.020 - 1e-9 <= t_start <= 0.021 + 1e-9, t_start
    while b.ctl.time < 0.304 - 1e-9:
        b.scan()
    assert mv.InVelocity and b.ctl.time == pytest.approx(0.304)
    b.fbs.remove(mv)
    mv2 = b.add(MC_MoveVelocity(Execute=True, Velocity=50.0))
    b.scan()
    b.scan()
    b.scan()
    t_change = _first_change(b.trace, 0.304, 20.0)
    assert 0.310 - 1e-9 <= t_change <= 0.311 + 1e-9
    assert mv2.Busy


def test_s7_1200_v7_pto_slice_time_default_takes_effect_within_2_ms():
    """V7: the start value of Actor.PTOSliceTime is 2 ms -- a command takes effect within 2 ms."""
    b = Pto(version=7)
    b.scan()
    t0 = b.ctl.time
    b.add(MC_MoveVelocity(Execute=True, Velocity=20.0))
    b.scan()
    t_start = next(t for t, _, v in b.trace if v != 0.0)
    assert t0 < t_start <= t0 + 0.002 + 1e-9


def test_s7_1200_v6_has_no_pto_slice_time():
    """V6 has no segment time: a command on a V6 PTO axis takes effect in the next servo cycle even with
    Actor.PTOSliceTime configured (the tag exists only in V7)."""
    b = Pto(params(actor={"PTOSliceTime": 10}), version=6)
    while b.ctl.time < 0.012 - 1e-9:
        b.scan()
    b.add(MC_MoveVelocity(Execute=True, Velocity=20.0))
    b.scan()
    t_start = next(t for t, _, v in b.trace if v != 0.0)
    assert t_start == pytest.approx(0.013)


def test_s7_1200_v7_pto_slice_time_applies_to_command_table():
    """Decision 49: "a new command on a PTO axis starts at the next multiple of the slice time" -- MC_CommandTable
    is such a command (§11.1.9: it aborts and is aborted like the other motion commands): with 10 ms a table
    executed at t = 12 ms starts moving at 20 ms."""
    b = Pto(params(actor={"PTOSliceTime": 10}), version=7)
    while b.ctl.time < 0.012 - 1e-9:
        b.scan()
    table = b.ctl.add_command_table("Table_1", [{"Type": 7, "Velocity": 20.0, "Duration": 0.1}])
    b.add(MC_CommandTable(CommandTable=table, Execute=True, EndStep=1))
    b.scan()
    b.scan()
    t_start = next(t for t, _, v in b.trace if v != 0.0)
    assert 0.020 - 1e-9 <= t_start <= 0.021 + 1e-9, t_start
