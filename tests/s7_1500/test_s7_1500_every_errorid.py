"""Every ErrorID the S7-1500 instructions give, provoked in its situation through instruction calls over
application cycles, with the CPU's number from the S7-1500/S7-1500T Motion Control ErrorID list (the
synchronous operation manual S7-1500T V5 prints none; the situations are those of its §9.1 and §9.2 input
tables and requirements).  16#8001 means a technology alarm is behind the error: every 16#8001 case also
checks the alarm in ``<TO>.ErrorDetail.Number`` / ``.Reaction`` (the CPU's alarm list, shared reference
s7-1500-errorids.md §4.2).  Instruction errors need no acknowledgement, and a refused job leaves running
jobs alone."""
from __future__ import annotations

import math
from typing import Any, Callable

import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_CamIn, MC_GearIn, MC_GearInPos, MC_GetCamFollowingValue, MC_GetCamLeadingValue,
                               MC_Halt, MC_Home, MC_InterpolateCam, MC_LeadingValueAdditive, MC_MoveAbsolute,
                               MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed, MC_MoveVelocity, MC_PhasingRelative,
                               MC_Power, MC_Reset, MC_Stop, MC_SynchronizedMotionSimulation)
from plcmotion.s7_1500 import errors as E

from _s7_1500_rig import VIRTUAL, Rig

HUMP = [(0, 0), (90, 40), (180, 100), (270, 40), (360, 0)]
NAN, INF = math.nan, math.inf


def _final(fb: Any) -> bool:
    return bool(fb.Error or getattr(fb, "Done", False) or getattr(fb, "CommandAborted", False))


class Cell:
    """A Master (virtual) and a Slave (virtual synchronous axis) of an S7-1500T, both enabled by the rig's
    MC_Power, a cam, and instructions the program calls every application cycle."""

    def __init__(self, family: str = "S7-1500T", cam: list | None = HUMP):
        self.rig = Rig(family=family)
        self.ctl, self.m, self.s = self.rig.ctl, self.rig.master, self.rig.slave
        self.cam = self.ctl.add_cam("Cam", cam) if cam is not None and family == "S7-1500T" else None
        self.rig.run_until(self.rig.enabled, 1.0)

    def call(self, fb: Any, **inputs: Any) -> Any:
        """Call ``fb`` with ``inputs`` every cycle from now on (a rising edge at Execute/Enable if given)."""
        self.rig.steps.append(lambda: fb(**inputs))
        return fb

    def until(self, cond: Callable[[], bool], timeout: float = 2.0) -> None:
        self.rig.run_until(cond, timeout)

    def job(self, fb: Any, timeout: float = 2.0, **inputs: Any) -> Any:
        """Start a job and run until its instruction shows a final state."""
        self.call(fb, **inputs)
        self.until(lambda: _final(fb), timeout)
        return fb

    def refused(self, fb: Any, **inputs: Any) -> Any:
        """Call an instruction without Execute (MC_Power, MC_MoveJog, Enable types) until it shows Error."""
        self.call(fb, **inputs)
        self.until(lambda: fb.Error)
        return fb

    def interpolated(self) -> None:
        self.job(MC_InterpolateCam(), Cam=self.cam, Execute=True)

    def move_master(self, velocity: float = 100.0) -> MC_MoveVelocity:
        mv = self.call(MC_MoveVelocity(), Axis=self.m, Execute=True, Velocity=velocity)
        self.until(lambda: mv.InVelocity)
        return mv

    def camming(self) -> MC_CamIn:
        """Camming with MC_CamIn's defaults: synchronous at once (decisions #19)."""
        self.interpolated()
        ci = self.call(MC_CamIn(), Master=self.m, Slave=self.s, Cam=self.cam, Execute=True)
        self.until(lambda: ci.InSync)
        return ci

    def gearing(self) -> MC_GearIn:
        g = self.call(MC_GearIn(), Master=self.m, Slave=self.s, Execute=True)
        self.until(lambda: g.InGear)
        return g

    def extra_axis(self) -> Any:
        """A further axis nobody enables."""
        return self.ctl.add_positioning_axis("Extra", VIRTUAL)


# --- one scenario per situation: returns the instruction that shows the ErrorID -----------------------------
def _single(cls: type, **inputs: Any) -> Callable[[], Any]:
    """A single-axis instruction on the enabled Master."""
    def run() -> Any:
        c = Cell(cam=None)
        return c.job(cls(), Axis=c.m, Execute=True, **inputs)
    return run


def _sync(cls: type, **inputs: Any) -> Callable[[], Any]:
    """A synchronous operation instruction on Master/Slave (MC_CamIn with the cam, interpolated)."""
    def run() -> Any:
        c = Cell()
        if cls is MC_CamIn:
            c.interpolated()
            inputs.setdefault("Cam", c.cam)
        return c.job(cls(), Master=c.m, Slave=c.s, Execute=True, **inputs)
    return run


def _cam(cls: type, interpolate: bool = True, points: list | None = HUMP, **inputs: Any) -> Callable[[], Any]:
    def run() -> Any:
        c = Cell(cam=points)
        if interpolate:
            c.interpolated()
        return c.job(cls(), Cam=c.cam, Execute=True, **inputs)
    return run


def s_master_not_a_leading_value() -> Any:
    c = Cell(cam=None)
    other = c.ctl.add_positioning_axis("Other", VIRTUAL)
    return c.job(MC_GearIn(), Master=other, Slave=c.s, Execute=True)


def s_cam_in_not_interpolated() -> Any:
    c = Cell()
    return c.job(MC_CamIn(), Master=c.m, Slave=c.s, Cam=c.cam, Execute=True)


def s_positioning_axis_as_slave() -> Any:
    c = Cell(cam=None)
    return c.job(MC_GearIn(), Master=c.m, Slave=c.m, Execute=True)


def s_axis_at_the_cam_input() -> Any:
    c = Cell()
    return c.job(MC_InterpolateCam(), Cam=c.m, Execute=True)


def s_t_function_on_s7_1500() -> Any:
    c = Cell(family="S7-1500", cam=None)
    return c.job(MC_GearInPos(), Master=c.m, Slave=c.s, Execute=True, MasterSyncPosition=500.0)


def s_jog_both() -> Any:
    c = Cell(cam=None)
    return c.refused(MC_MoveJog(), Axis=c.m, JogForward=True, JogBackward=True)


def s_stop_mode() -> Any:
    c = Cell(cam=None)
    extra = c.extra_axis()
    return c.refused(MC_Power(), Axis=extra, Enable=True, StopMode=7)


def s_second_power() -> Any:
    c = Cell(cam=None)
    return c.refused(MC_Power(), Axis=c.m, Enable=True)


def s_direct_homing_during_active_homing() -> Any:
    c = Cell(cam=None)
    c.move_master()
    active = c.call(MC_Home(), Axis=c.m, Execute=True, Mode=3, Position=0.0)   # brakes first (decisions #41)
    c.until(lambda: active.Busy)
    direct = c.job(MC_Home(), Axis=c.m, Execute=True, Mode=0, Position=0.0)
    assert active.Busy
    return direct


def s_relative_target_out_of_range() -> Any:
    c = Cell(cam=None)
    c.job(MC_MoveRelative(), Axis=c.m, Execute=True, Distance=10.0)
    return c.job(MC_MoveRelative(), Axis=c.m, Execute=True, Distance=1.0e12)     # 10 + 1.0E12 > 1.0E12


def s_additive_position() -> Any:
    c = Cell(cam=None)
    return c.refused(MC_LeadingValueAdditive(), Axis=c.s, Enable=True, Position=NAN)


def s_job_in_stop() -> Any:
    c = Cell(cam=None)
    c.ctl.stop()
    move = MC_MoveRelative()
    move(Axis=c.m, Execute=True, Distance=1.0)        # the instruction called outside RUN (no program runs)
    c.ctl.step()
    return move()


def s_restart_while_enabled() -> Any:
    c = Cell(cam=None)
    return c.job(MC_Reset(), Axis=c.m, Execute=True, Restart=True)


def s_restart_cam_in_use() -> Any:
    c = Cell()
    c.camming()
    return c.job(MC_Reset(), Axis=c.cam, Execute=True, Restart=True)


def s_not_enabled() -> Any:
    c = Cell(cam=None)
    return c.job(MC_MoveRelative(), Axis=c.extra_axis(), Execute=True, Distance=1.0)


def s_stop_holds() -> Any:
    c = Cell(cam=None)
    stop = c.call(MC_Stop(), Axis=c.m, Execute=True, Mode=2)
    c.until(lambda: stop.Done)
    return c.job(MC_MoveRelative(), Axis=c.m, Execute=True, Distance=1.0)


def s_weaker_stop() -> Any:
    c = Cell(cam=None)
    c.move_master()
    c.call(MC_Stop(), Axis=c.m, Execute=True, Mode=0)                  # emergency stop ramp: the stronger
    c.ctl.step()
    return c.job(MC_Stop(), Axis=c.m, Execute=True, Mode=2)


def s_absolute_mode_on_incremental() -> Any:
    return _single(MC_Home, Mode=6)()


def s_homing_mode_on_absolute() -> Any:
    ctl = Controller(family="S7-1500")
    axis = ctl.add_positioning_axis("Axis", {"Sensor[1]": {"Type": 1, "Parameter": {"DeterminableRevolutions": 4096}}})
    power, home = MC_Power(), MC_Home()
    ctl.program(lambda: (power(Axis=axis, Enable=True), home(Axis=axis, Execute=power.Status, Mode=3)))
    ctl.run_until(lambda: _final(home), timeout=2.0)
    return home


def s_configuration_still_invalid() -> Any:
    c = Cell(cam=None)
    c.m.set_tag("DynamicDefaults.Acceleration", 1.0e13)              # beyond its range: configuration alarm
    c.ctl.run(0.05)
    return c.job(MC_Reset(), Axis=c.m, Execute=True)


def s_reset_without_restart() -> Any:
    """Alarm 101 (configuration error, restart needed): the value is valid again, but only a restart of the
    technology object clears the alarm; MC_Reset with Restart = FALSE cannot acknowledge it."""
    c = Cell(cam=None)
    c.m.write_tag("PositionControl.Kv", 0.0)
    c.ctl.run(0.05)
    c.m.write_tag("PositionControl.Kv", 10.0)
    return c.job(MC_Reset(), Axis=c.m, Execute=True, Restart=False)


def s_coupling_cycle() -> Any:
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    a = ctl.add_synchronous_axis("A", VIRTUAL, leading_values=["M", "B"])
    b = ctl.add_synchronous_axis("B", VIRTUAL, leading_values=["M", "A"])
    powers = [MC_Power() for _ in range(3)]
    ga, gb = MC_GearIn(), MC_GearIn()

    @ctl.program
    def main() -> None:
        for p, ax in zip(powers, (m, a, b)):
            p(Axis=ax, Enable=True)
        ok = all(p.Status for p in powers)
        ga(Master=m, Slave=a, Execute=ok)
        gb(Master=a, Slave=b, Execute=ga.InGear)
        ga2(Master=b, Slave=a, Execute=gb.InGear)
    ga2 = MC_GearIn()
    ctl.run_until(lambda: _final(ga2), timeout=2.0)
    return ga2


def s_start_distance_too_short() -> Any:
    c = Cell(cam=None)                              # the Master stands at 0, 5 from the synchronous position
    return c.job(MC_GearInPos(), Master=c.m, Slave=c.s, Execute=True, MasterSyncPosition=5.0,
                 MasterStartDistance=100.0, SyncProfileReference=1)


def s_phasing_without_gearing() -> Any:
    c = Cell(cam=None)
    return c.job(MC_PhasingRelative(), Master=c.m, Slave=c.s, Execute=True, PhaseShift=1.0)


def s_simulation_without_sync() -> Any:
    c = Cell(cam=None)
    return c.refused(MC_SynchronizedMotionSimulation(), Slave=c.s, Enable=True)


def s_gear_in_while_simulated() -> Any:
    c = Cell(cam=None)
    c.gearing()
    sim = c.call(MC_SynchronizedMotionSimulation(), Slave=c.s, Enable=True)
    c.until(lambda: sim.InSimulation)
    return c.job(MC_GearIn(), Master=c.m, Slave=c.s, Execute=True, RatioNumerator=2)


def s_active_homing_during_camming() -> Any:
    c = Cell()
    ci = c.camming()
    home = c.job(MC_Home(), Axis=c.s, Execute=True, Mode=3)
    assert ci.InSync and ci.Busy
    return home


def s_phasing_while_camming() -> Any:
    c = Cell()
    c.camming()
    return c.job(MC_PhasingRelative(), Master=c.m, Slave=c.s, Execute=True, PhaseShift=1.0)


def s_phasing_while_synchronizing() -> Any:
    c = Cell(cam=None)
    c.move_master(200.0)
    g = c.call(MC_GearIn(), Master=c.m, Slave=c.s, Execute=True, Acceleration=10.0, Deceleration=10.0)
    c.until(lambda: g.Busy)
    ph = c.job(MC_PhasingRelative(), Master=c.m, Slave=c.s, Execute=True, PhaseShift=1.0)
    assert g.Busy and not g.InGear
    return ph


def s_empty_cam() -> Any:
    c = Cell(cam=[(0, 0), (360, 0)])
    c.cam.set_tag("ValidPoint[1]", False)
    c.cam.set_tag("ValidPoint[2]", False)
    return c.job(MC_InterpolateCam(), Cam=c.cam, Execute=True)


def s_cam_in_use() -> Any:
    c = Cell()
    c.camming()
    return c.job(MC_InterpolateCam(), Cam=c.cam, Execute=True)


def s_internal(monkeypatch: pytest.MonkeyPatch) -> Any:
    from plcmotion.s7_1500.technology import cam_to

    def defect(*args: Any, **kw: Any) -> Any:
        raise ZeroDivisionError("planted defect")
    monkeypatch.setattr(cam_to, "interpolate", defect)
    return _cam(MC_InterpolateCam, interpolate=False)()


#: (ErrorID, instruction, situation) - each producible code at least once, 16#8001 for each alarm behind a refusal
CASES: list[tuple[int, str, Callable[..., Any]]] = [
    (0x8001, "absolute positioning of an unhomed axis (alarm 321)", _single(MC_MoveAbsolute, Position=10.0)),
    (0x8001, "leading axis not configured as a leading value (alarm 601)", s_master_not_a_leading_value),
    (0x8001, "camming with a cam not interpolated (alarm 612)", s_cam_in_not_interpolated),
    (0x8002, "a positioning axis as Slave", s_positioning_axis_as_slave),
    (0x8002, "an axis at the Cam input", s_axis_at_the_cam_input),
    (0x8002, "MC_GearInPos on an S7-1500 (S7-1500T function)", s_t_function_on_s7_1500),
    (0x8003, "Velocity = 0.0", _single(MC_MoveRelative, Distance=10.0, Velocity=0.0)),
    (0x8003, "VelocityDiff = 0.0", _single(MC_MoveSuperimposed, Distance=1.0, VelocityDiff=0.0)),
    (0x8004, "Acceleration = 0.0", _single(MC_MoveRelative, Distance=10.0, Acceleration=0.0)),
    (0x8004, "Acceleration NaN at MC_GearIn", _sync(MC_GearIn, Acceleration=NAN)),
    (0x8005, "Deceleration = 0.0", _single(MC_Halt, Deceleration=0.0)),
    (0x8006, "Jerk NaN", _single(MC_MoveRelative, Distance=10.0, Jerk=NAN)),
    (0x8007, "JogForward and JogBackward together", s_jog_both),
    (0x8007, "Direction 3 at MC_MoveVelocity", _single(MC_MoveVelocity, Velocity=10.0, Direction=3)),
    (0x8008, "Distance NaN", _single(MC_MoveRelative, Distance=NAN)),
    (0x8008, "relative target beyond 1.0E12", s_relative_target_out_of_range),
    (0x8009, "MC_Home Position infinite", _single(MC_Home, Mode=0, Position=INF)),
    (0x8009, "MC_MoveAbsolute Position NaN", _single(MC_MoveAbsolute, Position=NAN)),
    (0x8009, "MC_LeadingValueAdditive Position NaN", s_additive_position),
    (0x800A, "MC_Home Mode 4", _single(MC_Home, Mode=4)),
    (0x800A, "MC_Stop Mode 1", _single(MC_Stop, Mode=1)),
    (0x800B, "MC_Power StopMode 7", s_stop_mode),
    (0x800C, "a second MC_Power enabling the axis", s_second_power),
    (0x800D, "direct homing while an active homing runs", s_direct_homing_during_active_homing),
    (0x800D, "a job outside RUN", s_job_in_stop),
    (0x800E, "restart of an enabled axis", s_restart_while_enabled),
    (0x800E, "restart of a cam in use", s_restart_cam_in_use),
    (0x800F, "a motion job on a disabled axis", s_not_enabled),
    (0x800F, "a job while MC_Stop holds the axis", s_stop_holds),
    (0x800F, "a weaker MC_Stop", s_weaker_stop),
    (0x8010, "MC_Home Mode 6 with an incremental encoder", s_absolute_mode_on_incremental),
    (0x8011, "MC_Home Mode 3 with an absolute encoder", s_homing_mode_on_absolute),
    (0x8015, "MC_Reset while the configuration is still invalid", s_configuration_still_invalid),
    (0x8015, "MC_Reset without Restart on an alarm that needs a restart", s_reset_without_restart),
    (0x8017, "RatioNumerator 0", _sync(MC_GearIn, RatioNumerator=0)),
    (0x8018, "RatioDenominator 0", _sync(MC_GearIn, RatioDenominator=0)),
    (0x8019, "a coupling that closes a cycle", s_coupling_cycle),
    (0x8021, "MasterOffset NaN", _sync(MC_CamIn, MasterOffset=NAN)),
    (0x8022, "SlaveOffset infinite", _sync(MC_CamIn, SlaveOffset=INF)),
    (0x8023, "MasterScaling 0.0", _sync(MC_CamIn, MasterScaling=0.0)),
    (0x8024, "SlaveScaling NaN", _sync(MC_CamIn, SlaveScaling=NAN)),
    (0x8026, "MasterStartDistance < 0", _sync(MC_GearInPos, MasterStartDistance=-1.0, SyncProfileReference=1)),
    (0x8026, "leading axis closer than MasterStartDistance", s_start_distance_too_short),
    (0x8027, "ApplicationMode 3", _sync(MC_CamIn, ApplicationMode=3)),
    (0x8034, "MasterSyncPosition NaN", _sync(MC_GearInPos, MasterSyncPosition=NAN)),
    (0x8035, "SlaveSyncPosition infinite", _sync(MC_GearInPos, SlaveSyncPosition=INF)),
    (0x8036, "SyncProfileReference 2 at MC_GearInPos", _sync(MC_GearInPos, SyncProfileReference=2)),
    (0x8062, "ApproachLeadingValue NaN", _cam(MC_GetCamLeadingValue, FollowingValue=50.0, ApproachLeadingValue=NAN)),
    (0x8063, "a following value the cam never takes", _cam(MC_GetCamLeadingValue, FollowingValue=150.0)),
    (0x8063, "MC_GetCamLeadingValue on a cam not interpolated", _cam(MC_GetCamLeadingValue, False, FollowingValue=50.0)),
    (0x8064, "LeadingValue outside the cam", _cam(MC_GetCamFollowingValue, LeadingValue=400.0)),
    (0x8064, "MC_GetCamFollowingValue on a cam not interpolated", _cam(MC_GetCamFollowingValue, False, LeadingValue=5.0)),
    (0x8070, "PhaseShift NaN", _sync(MC_PhasingRelative, PhaseShift=NAN)),
    (0x8075, "phasing without synchronous operation", s_phasing_without_gearing),
    (0x8075, "simulation without synchronous operation", s_simulation_without_sync),
    (0x8076, "MC_GearIn while the synchronous operation is simulated", s_gear_in_while_simulated),
    (0x80A1, "active homing while camming", s_active_homing_during_camming),
    (0x80A8, "phasing while camming", s_phasing_while_camming),
    (0x80A9, "phasing while the gearing synchronizes", s_phasing_while_synchronizing),
    (0x80AA, "a cam without valid points", s_empty_cam),
    (0x80AB, "interpolation of a cam in use", s_cam_in_use),
    (0x80AC, "a cam with a single point", _cam(MC_InterpolateCam, False, points=[(0, 0)])),
    (0x80AD, "MasterSyncPosition beyond the cam", _sync(MC_CamIn, MasterSyncPosition=400.0, MasterStartDistance=10.0)),
    (0x8FFF, "a defect in the interpolation", s_internal),
]


#: the technology alarm behind each 16#8001 case: (ErrorDetail.Number, ErrorDetail.Reaction, ErrorWord bit) of
#: the CPU's alarm list - 321 emergency stop ramp (3) X3, 601 maximum dynamic values (2) X14, 612 remove enable
#: (4) X2; the MC_Reset 16#8015 case keeps alarm 101 (remove enable, X1) pending
ALARM_BEHIND = {
    "absolute positioning of an unhomed axis (alarm 321)": (321, 3, 3),
    "leading axis not configured as a leading value (alarm 601)": (601, 2, 14),
    "camming with a cam not interpolated (alarm 612)": (612, 4, 2),
    "MC_Reset without Restart on an alarm that needs a restart": (101, 4, 1),
}


@pytest.mark.parametrize("error_id, situation, scenario", CASES, ids=[f"{c[0]:04X}-{c[1]}" for c in CASES])
def test_s7_1500_every_errorid_in_its_situation(error_id, situation, scenario, monkeypatch):
    """Motion Control ErrorID list / S7-1500T V5 §9.1, §9.2: the instruction ends with Error, the CPU's ErrorID,
    Busy FALSE, and the code belongs to that instruction's list.  With 16#8001 the alarm behind it is in the
    technology object's ErrorDetail (and its ErrorWord bit); an instruction error leaves ErrorDetail at 0."""
    fb = scenario(monkeypatch) if scenario is s_internal else scenario()
    assert fb.Error and fb.ErrorID == error_id, (situation, hex(fb.ErrorID), fb.outputs)
    assert not fb.Busy or "Enable" in type(fb).INPUTS        # MC_Power is Busy while Enable is TRUE
    assert error_id in E.INSTRUCTION_CODES[type(fb).__name__], (type(fb).__name__, hex(error_id))
    to = getattr(fb, "Slave", None) or getattr(fb, "Axis", None)
    detail = getattr(to, "ErrorDetail", None)
    if error_id == E.TO_ALARM or situation in ALARM_BEHIND:
        number, reaction, bit = ALARM_BEHIND[situation]
        assert (detail.Number, detail.Reaction) == (number, reaction), (situation, detail.Number, detail.Reaction)
        assert int(to.ErrorWord) & (1 << bit) and to.StatusWord.Error
    elif detail is not None and error_id not in (E.CONFIG_NOT_ACKNOWLEDGEABLE, E.INTERNAL):
        assert (detail.Number, detail.Reaction) == (0, 0), (situation, detail.Number)


def test_s7_1500_every_producible_errorid_has_a_situation():
    """Each code of the table that some instruction can give is provoked above; the others say why not."""
    tested = {c[0] for c in CASES}
    for code in E.CODES:
        if code.unreachable:
            assert code.number not in tested and not E.instructions_of(code.number)
        else:
            assert code.number in tested, hex(code.number)


def test_s7_1500_instruction_errors_need_no_acknowledgement():
    """ErrorID list, "instruction errors": fixing the input and a new rising edge start the job; no MC_Reset,
    no alarm at the axis."""
    c = Cell(cam=None)
    inputs = {"Axis": c.m, "Execute": True, "Distance": 10.0, "Velocity": 0.0}
    move = MC_MoveRelative()
    c.rig.steps.append(lambda: move(**inputs))          # the inputs as the program sets them each cycle
    c.until(lambda: move.Error)
    assert move.ErrorID == E.VELOCITY and not c.m.StatusWord.Error and not c.m.alarms
    inputs.update(Execute=False, Velocity=50.0)
    c.ctl.step()
    inputs["Execute"] = True
    c.until(lambda: move.Done, 2.0)
    assert c.m.Position == pytest.approx(10.0)


REFUSALS = [
    ("invalid Velocity", lambda c: (MC_MoveRelative(), {"Axis": c.m, "Distance": 1.0, "Velocity": NAN}), 0x8003),
    ("MC_Home Mode 6", lambda c: (MC_Home(), {"Axis": c.m, "Mode": 6}), 0x8010),
    ("MC_Stop Mode 1", lambda c: (MC_Stop(), {"Axis": c.m, "Mode": 1}), 0x800A),
    ("Slave not a synchronous axis", lambda c: (MC_GearIn(), {"Master": c.s, "Slave": c.m}), 0x8002),
    ("phasing without gearing", lambda c: (MC_PhasingRelative(), {"Master": c.s, "Slave": c.s, "PhaseShift": 1.0}),
     0x8075),
    ("MC_Reset Restart", lambda c: (MC_Reset(), {"Axis": c.m, "Restart": True}), 0x800E),
]


@pytest.mark.parametrize("name, make, error_id", REFUSALS, ids=[r[0] for r in REFUSALS])
def test_s7_1500_a_refused_job_leaves_the_running_job_alone(name, make, error_id):
    """ErrorID list: "a rejected job does not disturb jobs that are already running" - the Master keeps moving
    with its MC_MoveVelocity (Busy, InVelocity, no CommandAborted, same velocity) while another instruction is
    refused."""
    c = Cell(cam=None)
    mv = c.move_master(100.0)
    fb, inputs = make(c)
    c.job(fb, Execute=True, **inputs)
    assert fb.Error and fb.ErrorID == error_id, hex(fb.ErrorID)
    c.rig.run(0.2)
    assert mv.Busy and mv.InVelocity and not mv.CommandAborted and not mv.Error
    assert c.m.Velocity == pytest.approx(100.0) and not c.m.StatusWord.Error
