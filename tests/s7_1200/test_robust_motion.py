"""Issue 8, defects 1 and 5: dynamics changed during a motion never make the axis run away, planning
never lets an exception out of an instruction, and REAL inputs beyond the REAL range give the manual's
ErrorIDs (S7-1200 V6 §11.1.10 MC_ChangeDynamic, §12.9.11 effective code 10, §12.8 ErrorIDs).
"""
from __future__ import annotations

import math
from fractions import Fraction

import pytest

from _s7_1200_rig import MC_MoveRelative, MC_MoveVelocity, Rig
from plcmotion import Controller
from plcmotion.fb import ProgramError
from plcmotion.s7_1200 import MC_ChangeDynamic, MC_Home, MC_MoveAbsolute, MC_Power, MC_WriteParam
from plcmotion.s7_1200.variables import Real

SERVO_ACTORS = [pytest.param(1, id="PROFIdrive"), pytest.param(0, id="analog")]
ALL_ACTORS = SERVO_ACTORS + [pytest.param(2, id="PTO")]


def _change_dynamic(rig: Rig, **times: float) -> MC_ChangeDynamic:
    """MC_ChangeDynamic with all four Change... inputs TRUE, called once with a rising edge."""
    fb = MC_ChangeDynamic(Axis=rig.axis, ChangeRampUp=True, ChangeRampDown=True, ChangeEmergency=True,
                          ChangeJerkTime=True, **times)
    fb(Execute=True)
    assert fb.Done and not fb.Error
    return fb


# --- defect 1: runaway above MaxVelocity ------------------------------------------------------------------
@pytest.mark.parametrize("actor", ALL_ACTORS)
def test_s7_1200_change_dynamic_8ms_into_a_move_relative_keeps_velocity_and_target_defect1(actor):
    """Issue 8 defect 1, first example: MaxVelocity 50, Acceleration 500, no jerk limit,
    MC_MoveRelative(445.3, 10), 8 ms later MC_ChangeDynamic with all Change inputs and RampDownTime 9.2:
    it was peak 797 and 16#800D at 623.  The velocity stays within the job's 10 and the move ends at
    445.3 without passing it."""
    rig = Rig(actor, max_v=50.0, acc=500.0, dec=500.0, jerk=0.0)
    rig.add("move", MC_MoveRelative(), Distance=445.3, Velocity=10.0, Execute=True)
    start = rig.axis.Position
    rig.scans(2)                                         # 8 ms
    _change_dynamic(rig, RampDownTime=9.2)
    peak, highest = 0.0, -math.inf
    for _ in range(40_000):
        snap = rig.scan()
        peak = max(peak, abs(rig.axis.Velocity))
        highest = max(highest, rig.axis.Position)
        if snap["move"]["Done"] or snap["move"]["Error"]:
            break
    assert snap["move"]["Done"], snap["move"]
    assert peak <= 10.0 * (1 + 1e-9) <= 50.0
    assert rig.axis.Position == pytest.approx(start + 445.3, abs=1e-6)
    assert highest <= start + 445.3 + 1e-6


@pytest.mark.parametrize("actor", ALL_ACTORS)
def test_s7_1200_jerk_write_and_move_velocity_in_the_same_cycle_defect1(actor):
    """Issue 8 defect 1, second example: DynamicDefaults.Jerk written from 1e7 to 1e4 and
    MC_MoveVelocity(40) started in the same cycle.  The issue's peak of 1797 reproduces with
    Acceleration/Deceleration 1e5 (with 500 the acceleration reached is small enough for the new jerk).
    The velocity never passes 40 and reaches it."""
    rig = Rig(actor, max_v=50.0, acc=1e5, dec=1e5, jerk=1e7)
    rig.add("move", MC_MoveVelocity(), Velocity=40.0, Execute=True)
    rig.axis.DynamicDefaults.Jerk = 1e4
    peak = 0.0
    for _ in range(200):
        snap = rig.scan()
        peak = max(peak, abs(rig.axis.Velocity))
    assert snap["move"]["InVelocity"]
    assert peak <= 40.0 * (1 + 1e-9)
    assert rig.axis.Velocity == pytest.approx(40.0)


@pytest.mark.parametrize("actor", SERVO_ACTORS)
def test_s7_1200_lower_jerk_while_braking_does_not_reverse_defect1(actor):
    """A much smaller jerk written while MC_Halt brakes: the halt still ends at standstill without running
    backwards (the old plan would have swung to about -1000 mm/s)."""
    rig = Rig(actor, max_v=50.0, acc=500.0, dec=500.0, jerk=1e5)
    rig.add("move", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    rig.scans(50)
    from _s7_1200_rig import MC_Halt
    rig.add("halt", MC_Halt(), Execute=True)
    rig.scans(2)
    rig.axis.DynamicDefaults.Jerk = 100.0
    lowest = math.inf
    for _ in range(5000):
        snap = rig.scan()
        lowest = min(lowest, rig.axis.Velocity)
        if snap["halt"]["Done"]:
            break
    assert snap["halt"]["Done"]
    assert lowest >= -1e-9


def _move_relative_takes_over_move_velocity(write_tag: bool) -> dict:
    """Fuzz seed 100893: analog axis, MC_MoveVelocity accelerating (jerk 6723.6, Acceleration 52.8,
    MaxVelocity 11.35) taken over 8 ms later by MC_MoveRelative(33.66, Velocity 0.31); ``write_tag``: a
    non-dynamic tag (PositionLimits_SW.MinPosition, SW limits inactive) written in the same cycle, which
    re-plans the new job from a state that already overshoots its velocity."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, technology_version=6)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor.Type": 0, "DynamicLimits.MaxVelocity": 11.35, "DynamicDefaults.Acceleration": 52.8,
        "DynamicDefaults.Deceleration": 61.89, "DynamicDefaults.EmergencyDeceleration": 175.58,
        "DynamicDefaults.Jerk": 6723.6})
    power = MC_Power(Axis=axis, Enable=True)
    run = MC_MoveVelocity(Axis=axis, Velocity=10.0)
    rel = MC_MoveRelative(Axis=axis, Distance=33.66, Velocity=0.31)
    peak = {"v": 0.0, "j": 0.0}

    @ctl.on_post_servo
    def _peaks(t):
        i = axis.index
        peak["v"] = max(peak["v"], abs(float(ctl.bank.sp_v[i])))
        peak["j"] = max(peak["j"], abs(float(ctl.bank.sp_j[i])))

    def scan(n: int = 1) -> None:
        for _ in range(n):
            power(), run(), rel()
            ctl.step()

    scan(3)
    run.Execute = True
    scan(2)                                              # 8 ms of acceleration
    start = axis.Position
    if write_tag:
        axis.set_tag("PositionLimits_SW.MinPosition", 163.59)
    rel.Execute = True
    scan(10)
    ctl.run(110.0)                                       # 33.66 at 0.31: about 109 s; the kernel goes on
    for _ in range(500):
        scan()
        if rel.Done or rel.Error:
            break
    return dict(peak, done=rel.Done, error=rel.ErrorID, run_aborted=run.CommandAborted,
                end=axis.Position - start)


@pytest.mark.parametrize("write_tag", [False, True], ids=["plain", "tag-write"])
def test_s7_1200_move_relative_taking_over_move_velocity_keeps_the_configured_jerk_defect1(write_tag):
    """S7-1200 V6 §11.1.6.1 (MC_MoveRelative aborts a running MC_MoveVelocity), §2.4/§5.4.4.4 (the jerk is
    a configured limit of the motion, MaxVelocity the hard bound): the new profile may overshoot the new
    velocity 0.31 briefly with the configured jerk (as before issue 8), but neither the settling of defect
    1's fix nor a re-plan after a tag write may raise the jerk above 6723.6 (it was 22374.9)."""
    r = _move_relative_takes_over_move_velocity(write_tag)
    assert r["done"] and r["error"] == 0 and r["run_aborted"], r
    assert r["j"] <= 6723.6 * (1 + 1e-9), r
    assert r["v"] <= 11.35 * (1 + 1e-9), r
    assert r["end"] == pytest.approx(33.66, abs=1e-6), r


# --- defect 5: nothing escapes an instruction -------------------------------------------------------------
@pytest.mark.parametrize("actor", SERVO_ACTORS)
@pytest.mark.parametrize("times", [dict(RampUpTime=5.0, RampDownTime=5.0, EmergencyRampTime=1e12, JerkTime=1e3),
                                   dict(RampUpTime=1e3, RampDownTime=1e3, EmergencyRampTime=1e6, JerkTime=1e3)])
def test_s7_1200_power_off_with_stop_mode_2_after_large_ramp_times_defect5(actor, times):
    """Issue 8 defect 5: MC_ChangeDynamic with large ramp and jerk times during a move, then
    MC_Power(Enable = FALSE) with StopMode 2 (emergency stop with jerk, S7-1200 V6 §11.1.1): a ruckig
    planning error escaped MC_Power.  Now the axis brakes (never faster, never backwards) without error."""
    rig = Rig(actor, max_v=50.0, acc=500.0, dec=500.0, jerk=1e4)
    rig.power.StopMode = 2
    rig.add("move", MC_MoveRelative(), Distance=445.3, Velocity=40.0, Execute=True)
    rig.scans(3)
    _change_dynamic(rig, **times)
    rig.scan()
    rig.power.Enable = False
    speeds = [abs(rig.scan().vel) for _ in range(50)]
    assert not rig.power.Error and rig.axis.alarms == []
    assert all(b <= a + 1e-9 for a, b in zip(speeds, speeds[1:]))
    assert all(math.isfinite(rig.axis.Position) for _ in [0])


def test_s7_1200_kernel_exception_becomes_internal_error_not_an_exception_defect5(monkeypatch):
    """Issue 8 defect 5: an unexpected exception of the kernel while an instruction hands it a job is
    the internal error 16#8FFF (S7-1200 V6 §12.8) at the instruction, the axis is stopped, and MC_Power
    shows the alarm; the user program sees no exception."""
    rig = Rig(1, max_v=50.0)
    rig.add("move", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    rig.scans(10)

    def broken(job):
        raise RuntimeError("kernel defect")

    monkeypatch.setattr(rig.axis, "submit", broken)
    fb = MC_MoveRelative(Axis=rig.axis, Distance=1.0, Velocity=5.0)
    fb(Execute=True)
    assert fb.Error and fb.ErrorID == 0x8FFF and not fb.Busy
    assert rig.axis.StatusBits.Error and rig.axis.ErrorBits.SystemFault
    rig.scan()
    assert rig.power.Error and rig.power.ErrorID == 0x8FFF
    assert not rig.axis.StatusBits.Enable
    fb(Execute=True)
    assert fb.Error and fb.ErrorID == 0x8FFF                  # latched while Execute stays TRUE
    fb(Execute=False)
    assert not fb.Error                                       # then shown for one call only


def test_s7_1200_program_errors_still_raise_defect5():
    """A non-boolean at a BOOL input and an unknown input name stay programming errors (docs/index.md)."""
    rig = Rig(1)
    with pytest.raises(ProgramError):
        MC_MoveRelative(Axis=rig.axis)(Execute="yes")
    with pytest.raises(TypeError):
        MC_MoveRelative(Axis=rig.axis)(Bogus=1)


# --- defect 5 (third part): integers beyond the REAL range -------------------------------------------------
HUGE = 10 ** 400


@pytest.mark.parametrize("make, error", [
    (lambda: MC_MoveRelative(Distance=HUGE), (0x8401, 0x0005)),
    (lambda: MC_MoveRelative(Distance=-HUGE), (0x8401, 0x0006)),
    (lambda: MC_MoveRelative(Distance=1.0, Velocity=HUGE), (0x8402, 0x0008)),
    (lambda: MC_MoveAbsolute(Position=HUGE), (0x8400, 0x0005)),
    (lambda: MC_MoveVelocity(Velocity=-HUGE), (0x8402, 0x0008)),
    (lambda: MC_Home(Mode=0, Position=HUGE), (0x8400, 0x0005)),
    (lambda: MC_ChangeDynamic(ChangeRampUp=True, RampUpTime=HUGE), (0x840C, 0x0005)),
    (lambda: MC_ChangeDynamic(ChangeJerkTime=True, JerkTime=HUGE), (0x840F, 0x0005)),
    (lambda: MC_ChangeDynamic(ChangeEmergency=True, EmergencyRampTime=-HUGE), (0x840E, 0x000A)),
])
def test_s7_1200_real_input_beyond_real_range_gives_the_range_error_defect5(make, error):
    """S7-1200 V6 §12.8: a position beyond +-1.0E12 is 16#0005/16#0006, a velocity above the maximum
    16#0008, a MC_ChangeDynamic time above 1.0E12 16#0005 (V7 list) or <= 0 16#000A.  A Python int
    beyond the REAL range is such a value (it raised OverflowError)."""
    rig = Rig(1)
    rig.home()
    fb = make()
    fb(Axis=rig.axis, Execute=True)
    assert fb.Error and (fb.ErrorID, fb.ErrorInfo) == error


def test_s7_1200_write_param_and_tags_beyond_real_range_defect5():
    """MC_WriteParam with a REAL value beyond the REAL range: 16#8411/16#0005 (S7-1200 V6 §12.8); a tag
    assigned such a value holds +infinity, which is the tag's configuration error 16#8608 when it takes
    effect (§12.9.11, §9.6), like NaN; a command table step holds it until the step check rejects it."""
    rig = Rig(1)
    with pytest.raises(ValueError):
        Real(HUGE)                      # a typed REAL variable refuses it like Int(32768)
    # a non-integral number (a REAL constant) beyond the range: 16#8411/16#0005 and 16#0006
    for value, info in ((Fraction(HUGE, 3), 0x0005), (Fraction(-HUGE, 3), 0x0006)):
        wp = MC_WriteParam(Parameter=rig.axis.ref("DynamicDefaults.Acceleration"), Value=value)
        wp(Execute=True)
        assert wp.Error and (wp.ErrorID, wp.ErrorInfo) == (0x8411, info)
    wp = MC_WriteParam(Parameter=rig.axis.ref("DynamicDefaults.Acceleration"), Value=float("inf"))
    wp(Execute=True)
    assert wp.Error and (wp.ErrorID, wp.ErrorInfo) == (0x8411, 0x0002)

    rig.axis.DynamicDefaults.Acceleration = HUGE
    assert rig.axis.DynamicDefaults.Acceleration == math.inf
    rig.scans(2)                        # effective at the next servo cycle, shown at the next call
    assert rig.power.Error and rig.power.ErrorID == 0x8608

    ctl = Controller()
    table = ctl.add_command_table("T", [{"Type": 1, "Position": 10.0, "Velocity": 5.0}])
    table.Command[1].Position = -HUGE
    assert table.Command[1].Position == -math.inf


# --- defect 5: planning always gives a profile -------------------------------------------------------------
@pytest.mark.parametrize("dist, vmax, acc, dec, jerk", [
    (445.3, 40.0, 0.05, 0.05, 5e-8), (1e-3, 40.0, 500.0, 100.0, 1e4), (1e6, 10.0, 1e-3, 1e3, math.inf),
    (-3.0, 1.0, 2.0, 0.5, 0.1)])
def test_s7_1200_closed_form_fallback_stays_within_the_limits_defect5(dist, vmax, acc, dec, jerk):
    """Where ruckig gives up, the closed-form S-curve positioning takes over: it arrives at the target at
    standstill and never exceeds velocity, acceleration/deceleration or jerk (S7-1200 V6 §5.4.4.4)."""
    from plcmotion.kernel.profile_fallback import closed_form
    from plcmotion.kernel.profiles import _Builder
    b = _Builder(0.0, 0.0, 0.0, 0.0)
    amax, amin = (acc, -dec) if dist > 0 else (dec, -acc)
    assert closed_form(b, dist, 0.0, vmax, amax, amin, jerk)
    prof = b.finish(dist, 0.0)
    for k, seg in enumerate(prof.segments[:-1]):
        dur = prof.segments[k + 1].t - seg.t
        end_v = seg.v + dur * (seg.a + dur * seg.j / 2)
        end_a = seg.a + dur * seg.j
        assert abs(seg.v) <= vmax * (1 + 1e-9) and abs(end_v) <= vmax * (1 + 1e-9)
        assert max(abs(seg.a), abs(end_a)) <= max(acc, dec) * (1 + 1e-9)
        assert abs(seg.j) <= jerk
        assert (seg.v if seg.v else end_v) * dist >= -1e-12           # never backwards
    last = prof.segments[-2]
    dur = prof.t_end - last.t
    assert last.p + dur * (last.v + dur * (last.a / 2 + dur * last.j / 6)) == pytest.approx(dist, rel=1e-9, abs=1e-12)


def test_s7_1200_planner_gives_a_profile_where_ruckig_fails_defect5():
    """The state of issue 8 defect 5 (acceleration 130 left over, new limits a = 0.05, j = 5e-8): ruckig
    raised; the velocity ramp and the positioning are planned within the velocity limit."""
    from plcmotion.kernel.profiles import Limits, Planner
    pl = Planner()
    lim = Limits(velocity=40.0, acceleration=0.05, deceleration=0.05, jerk=5e-8)
    for prof in (pl.velocity(0.0, 0.0, 0.845, 130.0, 40.0, lim), pl.position(0.0, 0.0, 0.845, 130.0, 445.3, lim),
                 pl.stop(0.0, 0.0, 0.845, 130.0, lim)):
        for seg in prof.segments:
            assert abs(seg.v) <= 40.0 * (1 + 1e-9) and math.isfinite(seg.p)
    assert pl.position(0.0, 0.0, 0.845, 130.0, 445.3, lim).final.p == 445.3
