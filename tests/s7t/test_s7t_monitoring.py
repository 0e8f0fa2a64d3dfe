"""Monitoring functions of an axis provoked on the simulated plant, each with its technology DB ErrorID,
ErrorStatus bit, reaction and the acknowledgement by MC_Reset (S7-Technology V4.1 §4.5.7.2 hardware limit
switches, §4.5.7.3 software limit switches, §4.5.10 homing distance monitoring, §4.5.11 monitoring functions,
§7.1 ErrorStatus / Statusword, §7.12.1 ErrorIDs, §6.7.1 MC_Reset).

The reactions are those of ``s7t.technology.monitoring.REACTIONS`` (the manual names none per ErrorID;
decision of issue 11): "enable removed" shows as MC_Power.Status FALSE with the axis disabled, "stop" as an
axis braked to standstill that stays enabled.
"""
from __future__ import annotations

import pytest

from plcmotion.kernel.faults import Reaction
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_WriteParameter
from plcmotion.s7t.technology.monitoring import REACTIONS

from _s7t_homing_rig import ENC, Rig


def _ended(fb) -> bool:
    return fb.Done or fb.Error or fb.CommandAborted


def _homed(params: dict | None = None) -> Rig:
    r = Rig(params, input_filter=0.0)
    r.call(r.home, 0.02, Execute=True, Mode=3, Position=0.0)      # direct homing at 0 (§4.5.10.5)
    assert r.home.Done
    return r


def _tdb(r: Rig) -> tuple[int, list[int], int]:
    db = r.axis.db
    return db.ErrorID, list(db.ErrorBuffer), int(db.ErrorStatus)


def _assert_reaction(r: Rig, error_id: int) -> None:
    """The reaction of ``error_id`` as the table says, seen from outside."""
    reaction = REACTIONS[error_id]
    sw = r.axis.db.Statusword
    assert sw.Error and sw.Errorstop
    if reaction == Reaction.REMOVE_ENABLE:
        assert r.axis.state == "disabled" and not r.power.Status
    else:
        assert r.axis.state == "enabled" and sw.Standstill


def _assert_acknowledged(r: Rig) -> None:
    r.acknowledge()
    r.ctl.run(0.3)
    assert r.reset.Done
    assert _tdb(r) == (0, [0, 0, 0], 0)
    assert not r.axis.db.Statusword.Error and r.power.Status


HW_PLUS = {"Wizard.HWLimitSwitchPlusInput": "I1.0", "TypeOfAxis.HWEndPos.enable": 1, "Plant.HWLimitMaxPosition": 50.0}
LIMIT_SWITCH_ACTIVE = 1 << 14


def _into_plus_switch() -> Rig:
    r = Rig(HW_PLUS, input_filter=0.0)
    mv = MC_MoveVelocity()
    r.call(mv, 4.0, Execute=True, Velocity=20.0)
    assert mv.CommandAborted
    return r


def test_s7t_monitoring_hardware_limit_switch():
    """S7-Technology V4.1 §4.5.7.2: an axis running into its (NC) plus limit switch at 50 is stopped with
    8013 and 804B (ErrorBuffer in that order, ErrorID the latest), ErrorStatus.LimitSwitchActive,
    Statusword.HWLimitSwitchPlus; the enable is removed; the motion command ends CommandAborted.  "Retraction
    with drive": MC_Reset acknowledges the error (the axis can be enabled again) but the error message and
    LimitSwitchActive stay; the axis is driven back out of the switch; a second MC_Reset then clears them."""
    r = _into_plus_switch()
    assert _tdb(r) == (0x804B, [0x8013, 0x804B, 0], LIMIT_SWITCH_ACTIVE)
    assert r.axis.db.ErrorStatus.LimitSwitchActive and r.axis.db.Statusword.HWLimitSwitchPlus
    _assert_reaction(r, 0x8013)
    assert 50.0 <= r.mech < 52.0
    r.acknowledge()
    r.ctl.run(0.3)
    assert r.reset.Done and r.power.Status and not r.axis.db.Statusword.Errorstop
    assert _tdb(r) == (0x804B, [0x8013, 0x804B, 0], LIMIT_SWITCH_ACTIVE)
    back = MC_MoveRelative()
    r.until(back, _ended, Execute=True, Distance=-20.0, Velocity=10.0)
    assert back.Done and r.mech < 35.0
    assert r.axis.db.ErrorStatus.LimitSwitchActive           # left, but not acknowledged yet
    _assert_acknowledged(r)


def test_s7t_monitoring_hardware_limit_switch_left_with_safety_range():
    """S7-Technology V4.1 §4.5.7.2: the position where the switch was met is saved; only past it plus the
    safety range (1000 / increments per unit = 1 with the manual's example resolution of 1000/unit) has the
    axis left the switch.  0.5 back from that position (off the switch input at 50 already) MC_Reset keeps
    8013/804B and LimitSwitchActive; 1.5 back it clears them.  A motion further into the switch meanwhile
    is an error again (804B, §4.5.7.2 "a reverse motion command once again triggers an axis error")."""
    r = _into_plus_switch()
    met = r.axis.hw_retraction.position
    assert 50.0 <= met < 50.1
    r.acknowledge()
    r.ctl.run(0.3)
    assert r.power.Status
    forward = MC_MoveRelative()
    r.until(forward, _ended, Execute=True, Distance=1.0, Velocity=10.0)
    assert forward.Error or forward.CommandAborted
    assert r.axis.db.ErrorID == 0x804B and r.axis.db.ErrorStatus.LimitSwitchActive
    r.acknowledge()
    r.ctl.run(0.3)
    assert r.power.Status
    for target, cleared in ((met - 0.5, False), (met - 1.5, True)):
        back = MC_MoveRelative()
        r.until(back, _ended, Execute=True, Distance=target - r.mech, Velocity=5.0)
        r.ctl.run(0.3)
        assert back.Done and r.mech == pytest.approx(target, abs=0.01)
        assert not r.axis.db.Statusword.HWLimitSwitchPlus
        r.acknowledge()
        assert r.reset.Done
        assert (_tdb(r) == (0, [0, 0, 0], 0)) is cleared, (target, _tdb(r))
        assert r.axis.db.ErrorStatus.LimitSwitchActive is not cleared


def test_s7t_monitoring_software_limit_switch():
    """S7-Technology V4.1 §4.5.7.3: a homed axis positioning to 100 beyond the plus software limit switch
    at 50 travels up to it and stops there: 8014, ErrorStatus.SoftwareLimitPos; the positioning ends
    CommandAborted; MC_Reset acknowledges."""
    r = _homed({"swlimit": {"state": 1, "plusposition": 50.0}})
    ma = MC_MoveAbsolute()
    r.until(ma, _ended, Execute=True, Position=100.0, Velocity=50.0)
    r.ctl.run(0.3)
    assert ma.CommandAborted
    assert _tdb(r) == (0x8014, [0x8014, 0, 0], 1 << 12)
    assert r.axis.db.ActualPosition == pytest.approx(50.0, abs=0.05)
    assert r.axis.state == "enabled" and REACTIONS[0x8014] is None
    _assert_acknowledged(r)


def test_s7t_monitoring_software_limit_switch_overshot():
    """S7-Technology V4.1 §7.12.1 8015 "software limit switch overshot during motion execution", §9.4 parameter
    3 (swlimit.plusposition, effective immediately), §6.7.5 MC_WriteParameter: the plus switch is moved to
    0.2 ahead of an axis moving at 40 - less than its braking distance even with the emergency deceleration
    (40² / (2 · 1000) = 0.8).  The axis passes the switch: 8015, ErrorStatus.SoftwareLimitPos, the motion
    ends CommandAborted, enable removed; it stands less than 0.8 beyond the switch."""
    r = _homed({"swlimit": {"state": 1, "plusposition": 1000.0},
                "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": 1000.0})
    mv = MC_MoveVelocity()
    r.call(mv, 1.0, Execute=True, Velocity=40.0)
    switch = r.axis.db.CommandPosition + 0.2
    w = MC_WriteParameter()
    w(Axis=r.axis, Execute=True, ParameterNumber=3, Value=switch)
    assert w.Done
    r.call(mv, 0.5, Execute=True, Velocity=40.0)
    assert mv.CommandAborted
    assert _tdb(r) == (0x8015, [0x8015, 0, 0], 1 << 12)
    _assert_reaction(r, 0x8015)
    r.ctl.run(0.5)
    assert switch < r.axis.db.ActualPosition < switch + 0.8


def test_s7t_monitoring_following_error():
    """S7-Technology V4.1 §4.5.11.3: a blocked drive while the axis moves: the following error exceeds its
    limit: 8016, ErrorStatus.FollowingError, enable removed; acknowledged once the drive is free.  The
    warning limit is 100 % by default (plcmotion's start value): no 8017 before."""
    r = _homed()
    mv = MC_MoveVelocity()
    r.call(mv, 0.5, Execute=True, Velocity=20.0)
    r.axis.drive.disturb(blocked=True)
    r.call(mv, 3.0, Execute=True, Velocity=20.0)
    assert mv.CommandAborted
    assert _tdb(r) == (0x8016, [0x8016, 0, 0], 1 << 6)
    _assert_reaction(r, 0x8016)
    r.axis.drive.disturb(blocked=False)
    _assert_acknowledged(r)


def test_s7t_monitoring_positioning():
    """S7-Technology V4.1 §4.5.11.2 positioning monitoring: a positioning window of 0.00001 cannot be reached
    within 4 ms after the end of the setpoint interpolation: 8019, ErrorStatus.PositioningError, enable
    removed."""
    r = _homed({"TypeOfAxis.PositionMonitoring.tolerance": 1e-5, "TypeOfAxis.PositionMonitoring.posWinTolTime": 0.004})
    ma = MC_MoveAbsolute()
    r.until(ma, _ended, Execute=True, Position=10.0, Velocity=50.0)
    r.ctl.run(0.1)
    assert ma.CommandAborted
    assert _tdb(r) == (0x8019, [0x8019, 0, 0], 1 << 8)
    _assert_reaction(r, 0x8019)
    _assert_acknowledged(r)


def test_s7t_monitoring_standstill():
    """S7-Technology V4.1 §4.5.11.2 standstill monitoring: after a positioning is done, the load slips 5 and
    sticks - outside the standstill tolerance (1.0): 8018, ErrorStatus.StandstillFault, enable removed.  The
    positioning itself had ended Done."""
    r = _homed()
    ma = MC_MoveAbsolute()
    r.until(ma, _ended, Execute=True, Position=10.0, Velocity=50.0)
    assert ma.Done
    r.ctl.run(0.3)
    assert _tdb(r) == (0, [0, 0, 0], 0)
    r.axis.drive.disturb(jump=5.0, blocked=True)
    r.ctl.run(0.05)
    assert _tdb(r) == (0x8018, [0x8018, 0, 0], 1 << 7)
    _assert_reaction(r, 0x8018)
    r.axis.drive.disturb(blocked=False)
    _assert_acknowledged(r)


@pytest.mark.parametrize("params", [
    {"TypeOfAxis.Homing": {"enableBeroDistance": 1, "beroDistance": 60.0}},          # cam at 100: too far
    {f"{ENC}.enableZeroMarkDistance": 1, f"{ENC}.zeroMarkDistance": 15.0},           # 100 -> 125: too far
])
def test_s7t_monitoring_homing_distance(params):
    """S7-Technology V4.1 §4.5.10.2 "maximum distance to reference cam / to encoder zero mark": the reference
    point approach is cancelled: MC_Home CommandAborted, 801D, ErrorStatus.ReferenceNotFound; the axis
    brakes and stays enabled, not homed; MC_Reset acknowledges."""
    r = Rig(params, input_filter=0.0)
    r.until(r.home, _ended, Execute=True, Mode=1, Position=0.0)
    assert r.home.CommandAborted and not r.home.Error
    r.ctl.run(0.5)
    assert _tdb(r) == (0x801D, [0x801D, 0, 0], 1 << 16)
    assert not r.axis.db.Statusword.HomingDone and r.axis.db.Statusword.DriveEnabled
    _assert_reaction(r, 0x801D)
    assert r.mech < 125.0
    _assert_acknowledged(r)


def test_s7t_monitoring_passive_homing_distance_ends_the_motion():
    """S7-Technology V4.1 §4.5.10.3: a zero mark monitor tripping during passive homing gives 801D and ends
    the axis's current motion (the move is aborted, the axis brakes)."""
    r = Rig({f"{ENC}.enableZeroMarkDistance": 1, f"{ENC}.zeroMarkDistance": 3.0,
             "Plant.ZeroMarkOffset": 200.0, "Plant.ZeroMarkDistance": 100000.0}, input_filter=0.0)
    mv = MC_MoveVelocity()
    r.call(r.home, 0.01, Execute=True, Mode=2, Position=0.0)
    r.call(mv, 2.0, Execute=True, Velocity=20.0)
    r.home(Axis=r.axis, Execute=True)
    assert r.home.CommandAborted and mv.CommandAborted
    assert r.axis.db.ErrorID == 0x801D and r.axis.db.ErrorStatus.ReferenceNotFound
    assert 3.0 <= r.mech < 5.0


def test_s7t_monitoring_following_error_warning_limit():
    """S7-Technology V4.1 §4.5.11.3, §7.12.1: with a warning limit of 50 % the blocked axis first reports 8017
    (ErrorStatus.FollowingWarning, Statusword.Error) and goes on enabled; then 8016 removes the enable.  The
    ErrorBuffer keeps both in order."""
    r = _homed({"TypeOfAxis.NumberOfDataSets.DataSet_1.DynamicFollowing.warningLimit": 50.0})
    mv = MC_MoveVelocity()
    r.call(mv, 0.5, Execute=True, Velocity=20.0)
    r.axis.drive.disturb(blocked=True)
    while r.axis.db.ErrorID == 0:
        r.call(mv, r.ctl.app_cycle, Execute=True, Velocity=20.0)
        assert r.ctl.time < 5.0
    assert _tdb(r) == (0x8017, [0x8017, 0, 0], 1 << 5)
    assert r.axis.db.Statusword.Error and r.axis.state == "enabled" and mv.Busy
    assert REACTIONS[0x8017] is None
    r.call(mv, 2.0, Execute=True, Velocity=20.0)
    assert _tdb(r) == (0x8016, [0x8017, 0x8016, 0], (1 << 5) | (1 << 6))
    assert mv.CommandAborted and r.axis.state == "disabled"
    r.axis.drive.disturb(blocked=False)
    _assert_acknowledged(r)


@pytest.mark.parametrize("at_start, buffer", [(1, [0x0026, 0x8014, 0]), (0, [0x8014, 0, 0])])
def test_s7t_monitoring_software_limit_warning_at_start(at_start, buffer):
    """S7-Technology V4.1 §4.5.7.3 "monitoring of the software limit switches at start of motion": checked,
    a positioning beyond the switch shows warning 0026 as it starts (Statusword.Error stays FALSE, the axis
    travels on) and 8014 at the switch; unchecked only 8014."""
    r = _homed({"swlimit": {"state": 1, "plusposition": 50.0}, "Wizard.SWLimitMonitoringAtStart": at_start})
    ma = MC_MoveAbsolute()
    ma(Axis=r.axis, Execute=True, Position=100.0, Velocity=50.0)
    if at_start:
        assert r.axis.db.ErrorID == 0x0026 and not r.axis.db.Statusword.Error and ma.Busy
    else:
        assert r.axis.db.ErrorID == 0
    r.until(ma, _ended, Execute=True)
    assert ma.CommandAborted and list(r.axis.db.ErrorBuffer) == buffer
