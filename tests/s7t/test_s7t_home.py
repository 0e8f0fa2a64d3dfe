"""FB 403 MC_Home on a real positioning axis with a reference cam (machine 100..120 on I0.0) and encoder zero
marks every 10 from 5 (S7-Technology V4.1 §4.5.10 homing configuration, §6.2.2 MC_Home, §7.1 Statusword).

Expected positions come from the machine geometry and the sequences of §4.5.10.2: the homing event gives the
reference point coordinate minus the reference point offset, and the axis then stands at the coordinate.
"""
from __future__ import annotations

import math

import pytest

from plcmotion.s7t import MC_Home, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_Stop

from _s7t_homing_rig import CAM_HI, ENC, V_APPROACH, V_ENTRY, Rig
from _s7t_rig import VIRTUAL, enabled

def _ended(fb) -> bool:
    return fb.Done or fb.Error or fb.CommandAborted


# --- active homing, cycle by cycle --------------------------------------------------------------------------
def test_s7t_home_mode1_cam_and_zero_mark_cycle_by_cycle():
    """S7-Technology V4.1 §4.5.10.2 "reference cam and encoder zero mark" (zero mark after the cam, positive
    start), MC_Home Mode 1 Position 0: Busy from the start; Statusword.Homing while it runs; HomingDone is
    FALSE during the search and TRUE from the zero mark (125) on, while the axis still moves back to the
    reference point (§7.1 bit 1); Done only at standstill there; then Homing FALSE."""
    r = Rig(input_filter=0.0)
    home = r.home
    home(Axis=r.axis, Execute=True, Mode=1, Position=0.0)
    assert home.Busy and not home.Done
    seen_searching = seen_homed_busy = False
    while not _ended(home):
        r.ctl.run(r.ctl.app_cycle)
        home(Axis=r.axis, Execute=True)
        sw = r.axis.db.Statusword
        if home.Busy and r.ctl.time > 0.3:
            assert sw.Homing
            seen_searching |= not sw.HomingDone
            seen_homed_busy |= sw.HomingDone
        assert r.ctl.time < 30.0
    assert home.Done and not home.Busy and not home.Error
    assert seen_searching and seen_homed_busy
    r.ctl.run(0.5)                       # the position loop settles (window 0.005)
    assert r.mech == pytest.approx(125.0, abs=1e-3)
    assert r.axis.db.ActualPosition == pytest.approx(0.0, abs=1e-3)
    assert r.axis.db.Statusword.HomingDone and not r.axis.db.Statusword.Homing


def test_s7t_home_mode0_zero_mark_before_cam_and_offset():
    """S7-Technology V4.1 §4.5.10.2: approach direction negative at the zero mark with a positive start = the
    zero mark before the cam (95); Mode 0 takes the configured reference point coordinate (30); the mark gets
    30 - offset 5 = 25 and the axis travels the offset at the entry velocity to 30 (machine 100)."""
    r = Rig({f"{ENC}.approachDirection": 15, f"{ENC}.proceedShiftPos": 5.0,
             "userdefaulthoming.homeposition": 30.0}, input_filter=0.0)
    r.until(r.home, _ended, Execute=True, Mode=0, Position=999.0)
    assert r.home.Done
    r.ctl.run(0.5)                       # the position loop settles (window 0.005)
    assert r.mech == pytest.approx(100.0, abs=1e-3)
    assert r.axis.db.ActualPosition == pytest.approx(30.0, abs=1e-3)


def test_s7t_home_zero_mark_only_negative_start():
    """S7-Technology V4.1 §4.5.10.2 "encoder zero mark only": negative start from machine 12 at the shutdown
    velocity: the first zero mark is 5, which becomes Position 50."""
    r = Rig({f"{ENC}.homingMode": 23, "TypeOfAxis.Homing.direction": 4, "Plant.InitialPosition": 12.0},
            input_filter=0.0)
    r.until(r.home, _ended, Execute=True, Mode=1, Position=50.0)
    assert r.home.Done
    r.ctl.run(0.5)                       # the position loop settles (window 0.005)
    assert r.mech == pytest.approx(5.0, abs=1e-3)
    assert r.axis.db.ActualPosition == pytest.approx(50.0, abs=1e-3)


@pytest.mark.parametrize("edge, at", [(17, 100.0), (20, CAM_HI)])
def test_s7t_home_external_zero_mark_only(edge, at):
    """S7-Technology V4.1 §4.5.10.2 "external zero mark only": the drive's measuring input (in the simulation
    I0.1, the mark 100..120) homes at its configured transition: EDGE_POS_SIDE_NEG = the rising edge at 100,
    EDGE_NEG_SIDE_NEG = the falling edge at 120 (moving positive); the axis then stands there at Position,
    within one IPO cycle of approach travel."""
    r = Rig({f"{ENC}.homingMode": 24, f"{ENC}.approachDirection": edge, "Drive.ExternalZeroMarkInput": "I0.1"},
            input_filter=0.0)
    r.until(r.home, _ended, Execute=True, Mode=1, Position=0.0)
    assert r.home.Done
    r.ctl.run(0.5)                       # the position loop settles (window 0.005)
    assert at - 1e-3 <= r.mech <= at + V_APPROACH * r.ctl.servo_cycle + 1e-3
    assert r.axis.db.ActualPosition == pytest.approx(0.0, abs=1e-3)


def test_s7t_home_travel_to_the_reference_point_at_entry_velocity():
    """S7-Technology V4.1 §4.5.10.2 (parameter table): after the zero mark the axis travels the offset at the
    entry velocity (decision on the erratum "approach velocity" in the sequence text)."""
    r = Rig({f"{ENC}.proceedShiftPos": -40.0}, input_filter=0.0)
    r.home(Axis=r.axis, Execute=True, Mode=1, Position=0.0)
    top = 0.0
    while not _ended(r.home):
        r.ctl.run(r.ctl.servo_cycle)
        if r.axis.homed:
            top = max(top, abs(float(r.ctl.bank.sp_v[r.axis.index])))
        r.home(Axis=r.axis, Execute=True)
    assert r.home.Done and 0.0 < top <= V_ENTRY + 1e-9
    r.ctl.run(0.5)
    assert r.mech == pytest.approx(125.0 - 40.0, abs=1e-3)


# --- passive homing: the examples of §4.5.10.4 ----------------------------------------------------------------
PASSIVE = {"Plant.ZeroMarkOffset": 200.0, "Plant.ZeroMarkDistance": 100000.0,
           "TypeOfAxis.Homing.referencingNecessary": 0, "TypeOfAxis.MaxVelocity.maximum": 1000.0}


@pytest.mark.parametrize("move, end_position, end_machine", [
    (MC_MoveRelative, 800.0, 1000.0),       # the move keeps its distance: 1000 - 200
    (MC_MoveAbsolute, 1000.0, 1200.0),      # the target is reached in the new coordinates
])
def test_s7t_home_passive_with_a_move(move, end_position, end_machine):
    """S7-Technology V4.1 §4.5.10.4: passive homing (Mode 2, Position 0; default mode: the encoder zero mark,
    here the only one at 200) and a move of 1000 start together; at the mark the axis becomes 0 and goes on."""
    r = Rig(PASSIVE, input_filter=0.0)
    m = move()
    amount = {"Distance": 1000.0} if move is MC_MoveRelative else {"Position": 1000.0}
    r.home(Axis=r.axis, Execute=True, Mode=2, Position=0.0)
    m(Axis=r.axis, Execute=True, Velocity=200.0, **amount)
    assert r.home.Busy and m.Busy
    while not _ended(m):
        r.ctl.run(r.ctl.app_cycle)
        r.home(Axis=r.axis, Execute=True)
        m(Axis=r.axis, Execute=True, Velocity=200.0, **amount)
        assert r.ctl.time < 20.0
    r.home(Axis=r.axis, Execute=True)
    assert m.Done and r.home.Done and r.axis.homed
    r.ctl.run(0.5)                       # the position loop settles (window 0.005)
    assert r.axis.db.ActualPosition == pytest.approx(end_position, abs=1e-3)
    assert r.mech == pytest.approx(end_machine, abs=1e-3)


def test_s7t_home_mode8_cancels_passive_homing():
    """S7-Technology V4.1 §6.2.2 Mode 8: a started passive homing is cancelled (it shows CommandAborted);
    without one Mode 8 gives 16#8045."""
    r = Rig(PASSIVE)
    passive, cancel = MC_Home(), MC_Home()
    r.call(passive, 0.02, Execute=True, Mode=2, Position=0.0)
    assert passive.Busy
    r.call(cancel, 0.02, Execute=True, Mode=8)
    passive(Axis=r.axis, Execute=True)
    assert cancel.Done and passive.CommandAborted
    again = MC_Home()
    r.call(again, 0.02, Execute=True, Mode=8)
    assert again.Error and again.ErrorID == 0x8045


# --- direct homing and the corrections ------------------------------------------------------------------------
@pytest.mark.parametrize("enable", [True, False])
def test_s7t_home_direct_and_corrections(enable):
    """S7-Technology V4.1 §4.5.10.5/§4.5.10.6, §6.2.2: Mode 3 sets the position and homes the axis; Modes 4, 6,
    7 subtract Position and keep HomingDone as it was; all of them on a disabled axis too (§6.2.2)."""
    r = Rig(enable=enable)
    h = MC_Home()
    r.call(h, 0.02, Execute=True, Mode=4, Position=7.0)
    r.ctl.run(0.02)
    assert h.Done and not r.axis.db.Statusword.HomingDone
    assert r.axis.db.ActualPosition == pytest.approx(-7.0, abs=1e-3)
    for mode, position, expected in [(3, 50.0, 50.0), (4, 20.0, 30.0), (6, -10.0, 40.0), (7, 5.0, 35.0)]:
        h = MC_Home()
        r.call(h, 0.02, Execute=True, Mode=mode, Position=position)
        r.ctl.run(0.02)
        assert h.Done, (mode, h)
        assert r.axis.db.Statusword.HomingDone
        assert r.axis.db.ActualPosition == pytest.approx(expected, abs=1e-3)
    # the axis stands: TRANSFER_STANDSTILL (default) has taken Mode 7 into the base system (§6.2.2 Mode 7 notes)
    assert r.axis.homing.superimposed_offset == 0.0


# --- the restrictions of §6.2.2, table-driven ------------------------------------------------------------------
#: (axis kind, Mode, ErrorID or 0 = Done / Busy); virtual: 3, 4, 6, 7 only (804D); incremental: not 5
RESTRICTIONS = [
    ("virtual", 0, 0x804D), ("virtual", 1, 0x804D), ("virtual", 2, 0x804D), ("virtual", 5, 0x804D),
    ("virtual", 3, 0), ("virtual", 4, 0), ("virtual", 6, 0), ("virtual", 7, 0),
    ("incremental", 5, 0x8045), ("incremental", 0, 0), ("incremental", 2, 0), ("incremental", 3, 0),
    ("disabled", 0, 0x8040), ("disabled", 1, 0x8040), ("disabled", 2, 0x8040), ("disabled", 3, 0),
    ("disabled", 4, 0), ("disabled", 6, 0), ("disabled", 7, 0),
]


@pytest.mark.parametrize("kind, mode, error_id", RESTRICTIONS)
def test_s7t_home_mode_restrictions(kind, mode, error_id):
    """S7-Technology V4.1 §6.2.2 notes and prerequisites: virtual axes take Modes 3, 4, 6, 7 (else 804D);
    incremental encoders not Mode 5; Modes 0-2 need an enabled axis (8040), 3-7 run without enable."""
    if kind == "virtual":
        ctl, axis, _power = enabled(VIRTUAL)
        run = ctl.run
    else:
        r = Rig(enable=kind != "disabled")
        axis, run = r.axis, r.ctl.run
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=mode, Position=0.0)
    run(0.01)
    h(Axis=axis, Execute=True, Mode=mode, Position=0.0)
    if error_id:
        assert h.Error and h.ErrorID == error_id
    else:
        assert not h.Error and (h.Done or h.Busy)


@pytest.mark.parametrize("inputs, error_id", [
    ({"Mode": 9}, 0x8043), ({"Mode": -1}, 0x8043), ({"Position": math.nan}, 0x808B),
    ({"Position": 1.0e13}, 0x8043), ({"DoneFlag": 33}, 0x8043), ({"Axis": 4711}, 0x8083),
])
def test_s7t_home_input_errors(inputs, error_id):
    """S7-Technology V4.1 §6.2.2 ErrorIDs: Mode, REAL and DoneFlag inputs (8043, 808B); a DB that is no
    technology DB (8083)."""
    r = Rig()
    h = MC_Home()
    h(**dict({"Axis": r.axis, "Execute": True, "Mode": 3, "Position": 0.0}, **inputs))
    assert h.Error and h.ErrorID == error_id and not h.Busy


def test_s7t_home_speed_axis_is_not_supported():
    """S7-Technology V4.1 §6.2.2 8044: homing a speed-controlled axis."""
    ctl, axis, _power = enabled({**VIRTUAL, "Wizard.Technology": 0})
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=3)
    assert h.Error and h.ErrorID == 0x8044


def test_s7t_home_refused_while_mc_stop_holds_and_without_active_mode():
    """S7-Technology V4.1 §6.2.2 8045: active homing while MC_Stop is active; active homing when the axis has
    no active homing mode configured (MODE_NO_REFERENCE)."""
    r = Rig()
    stop = MC_Stop()
    r.call(stop, 0.05, Execute=True)
    h = MC_Home()
    r.call(h, 0.01, Execute=True, Mode=0)
    assert h.Error and h.ErrorID == 0x8045
    r2 = Rig({f"{ENC}.homingMode": 88})
    h2 = MC_Home()
    r2.call(h2, 0.01, Execute=True, Mode=1)
    assert h2.Error and h2.ErrorID == 0x8045


@pytest.mark.parametrize("mode, error_id", [(0, 0x8040), (2, 0x8045), (3, 0x8045), (4, 0)])
def test_s7t_home_in_speed_controlled_mode(mode, error_id):
    """S7-Technology V4.1 §6.2.2: Modes 2, 3, 5 not in speed-controlled mode (MC_MoveVelocity PositionControl =
    FALSE, 8045); active homing needs position-controlled operation (8040); a correction (4) is allowed."""
    r = Rig()
    mv = MC_MoveVelocity()
    r.call(mv, 0.1, Execute=True, Velocity=5.0, PositionControl=False)
    assert r.axis.db.Statusword.SpeedMode
    h = MC_Home()
    r.call(h, 0.01, Execute=True, Mode=mode)
    assert (h.ErrorID if h.Error else 0) == error_id


def test_s7t_home_configuration_rules():
    """S7-Technology V4.1 §4.12.3 (table of approach direction and homing mode): an external zero mark needs
    an EDGE_* direction, a zero mark an APPROACH_* one; homing with a reference cam needs its address, with
    an external zero mark its input (§4.5.10.2); the configuration error names the tag."""
    from plcmotion import ConfigurationError
    with pytest.raises(ConfigurationError, match="approachDirection"):
        Rig({f"{ENC}.homingMode": 24, f"{ENC}.approachDirection": 16})
    with pytest.raises(ConfigurationError, match="passiveApproachDirection"):
        Rig({f"{ENC}.passiveHomingMode": 24, f"{ENC}.passiveApproachDirection": 21,
             "Drive.ExternalZeroMarkInput": "I0.1"})
    with pytest.raises(ConfigurationError, match="logAdressBero"):
        Rig({f"{ENC}.logAdressBero": None})                     # cam and zero mark without a cam
    with pytest.raises(ConfigurationError, match="ExternalZeroMarkInput"):
        Rig({f"{ENC}.homingMode": 24, f"{ENC}.approachDirection": 17})
