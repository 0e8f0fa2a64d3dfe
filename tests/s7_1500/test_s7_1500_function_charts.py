"""The function charts of the S7-1500T synchronous operation instructions (V5 §9.1) as scenarios:
FB calls over application cycles and the outputs and status tags they must give."""
import math

import pytest

from plcmotion.s7_1500 import (MC_CamIn, MC_GearIn, MC_GearInPos, MC_Halt, MC_InterpolateCam,
                               MC_LeadingValueAdditive, MC_MoveVelocity, MC_PhasingAbsolute, MC_PhasingRelative,
                               MC_SynchronizedMotionSimulation)

from _s7_1500_rig import Rig


def _moving_masters(rig, *velocities):
    mvs = [MC_MoveVelocity() for _ in velocities]

    def step():
        for fb, ax, v in zip(mvs, rig.masters, velocities):
            fb(Axis=ax, Execute=rig.powers[ax.name].Status, Velocity=v)
    rig.steps.append(step)
    rig.run_until(lambda: all(fb.InVelocity for fb in mvs), timeout=2.0)
    return mvs


def test_s7_1500_gear_in_synchronizing_and_switching_the_leading_value_s9_1_1_2():
    rig = Rig(masters=2)
    m1, m2, slave = rig.masters[0], rig.masters[1], rig.slave
    _moving_masters(rig, 100.0, -50.0)
    a1, a2 = MC_GearIn(), MC_GearIn()
    exe = {"a1": False, "a2": False}
    rig.steps.append(lambda: a1(Master=m1, Slave=slave, Execute=exe["a1"], RatioNumerator=1,
                                Acceleration=500.0, Deceleration=500.0, Jerk=0.0))
    rig.steps.append(lambda: a2(Master=m2, Slave=slave, Execute=exe["a2"], RatioNumerator=2,
                                Acceleration=500.0, Deceleration=500.0, Jerk=0.0))
    exe["a1"] = True
    rig.ctl.step()
    sm = slave.StatusSynchronizedMotion
    # synchronization starts at once: Busy, StatusWord.X21, FunctionState 1, ActualMaster = M1
    assert a1.Busy and not a1.InGear
    assert slave.StatusWord.X21 and not slave.StatusWord.X22
    assert sm.FunctionState == 1 and sm.ActualMaster == m1.db_number
    rig.run_until(lambda: a1.InGear, timeout=2.0)
    # ①: velocity and acceleration of the leading axis times the ratio reached
    assert slave.Velocity == pytest.approx(100.0)
    assert slave.StatusWord.X22 and not slave.StatusWord.X21
    # ②: GearIn on M2 aborts A1 at once and synchronizes to M2 (A1 shows it at its next call: it is
    # called before A2 in the program)
    exe["a2"] = True
    rig.ctl.step()
    assert a2.Busy and not a1.CommandAborted
    rig.ctl.step()
    assert a1.CommandAborted and not a1.Busy and not a1.InGear
    assert a2.Busy and sm.ActualMaster == m2.db_number and slave.StatusWord.X21
    rig.run_until(lambda: a2.InGear, timeout=2.0)       # ③
    assert slave.Velocity == pytest.approx(-100.0)
    rig.run(0.5)
    assert a2.InGear and a2.Busy                       # gearing never ends by itself (§9.1.1)


def _gear_in_pos_rig(spr, **inputs):
    rig = Rig()
    _moving_masters(rig, 100.0)
    fb = MC_GearInPos()
    exe = {"on": False}
    rig.steps.append(lambda: fb(Master=rig.master, Slave=rig.slave, Execute=exe["on"], SyncProfileReference=spr,
                                **inputs))
    rig.record = lambda: {"t": rig.ctl.time, "m": rig.master.Position, "s": rig.slave.Position,
                          "StartSync": fb.StartSync, "InSync": fb.InSync, "Busy": fb.Busy,
                          "X21": rig.slave.StatusWord.X21, "X22": rig.slave.StatusWord.X22,
                          "wait": rig.slave.StatusSynchronizedMotion.WaitingFunctionState,
                          "fs": rig.slave.StatusSynchronizedMotion.FunctionState}
    exe["on"] = True
    rig.ctl.step()
    return rig, fb


def test_s7_1500_gear_in_pos_in_advance_with_dynamic_parameters_s9_1_2_2_chart1_a():
    rig, fb = _gear_in_pos_rig(0, MasterSyncPosition=400.0, SlaveSyncPosition=1000.0, RatioNumerator=1,
                               Velocity=400.0, Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0)
    assert fb.Busy and not fb.StartSync and rig.slave.StatusSynchronizedMotion.WaitingFunctionState == 2
    rig.run_until(lambda: fb.InSync, timeout=10.0)
    start = rig.first("StartSync")
    assert 0.0 < start["m"] < 400.0                   # master position minus the computed length
    assert start["X21"] and start["fs"] == 2 and start["wait"] == 0
    sync = rig.first("InSync")
    dx = 100.0 * rig.ctl.app_cycle
    assert 400.0 <= sync["m"] <= 400.0 + dx + 1e-9
    # synchronous exactly at MasterSyncPosition / SlaveSyncPosition: slave = 1000 + (master - 400)
    assert sync["s"] == pytest.approx(1000.0 + sync["m"] - 400.0, abs=1e-6)
    assert sync["X22"] and not sync["X21"]


def test_s7_1500_gear_in_pos_in_advance_with_leading_value_distance_s9_1_2_2_chart1_b():
    rig, fb = _gear_in_pos_rig(1, MasterSyncPosition=300.0, SlaveSyncPosition=50.0, RatioNumerator=1,
                               RatioDenominator=2, MasterStartDistance=100.0)
    rig.run_until(lambda: fb.InSync, timeout=10.0)
    start = rig.first("StartSync")
    dx = 100.0 * rig.ctl.app_cycle
    assert 200.0 <= start["m"] <= 200.0 + dx + 1e-9   # MasterSyncPosition - MasterStartDistance
    sync = rig.first("InSync")
    assert 300.0 <= sync["m"] <= 300.0 + dx + 1e-9
    assert sync["s"] == pytest.approx(50.0 + 0.5 * (sync["m"] - 300.0), abs=1e-9)
    rig.run(0.5)
    assert rig.slave.Position == pytest.approx(50.0 + 0.5 * (rig.master.Position - 300.0), abs=1e-9)


def test_s7_1500_gear_in_pos_subsequent_synchronization_s9_1_2_2_chart2_b():
    rig, fb = _gear_in_pos_rig(3, MasterSyncPosition=300.0, SlaveSyncPosition=20.0, RatioNumerator=1,
                               MasterStartDistance=150.0)
    rig.run_until(lambda: fb.InSync, timeout=10.0)
    dx = 100.0 * rig.ctl.app_cycle
    start = rig.first("StartSync")
    assert 300.0 <= start["m"] <= 300.0 + dx + 1e-9   # synchronization starts at MasterSyncPosition
    sync = rig.first("InSync")
    assert 450.0 <= sync["m"] <= 450.0 + dx + 1e-9    # ... and is complete MasterStartDistance later
    assert sync["s"] == pytest.approx(20.0 + (sync["m"] - 300.0), abs=1e-9)


def _geared(rig, ratio=1):
    """A following axis synchronous with MC_GearInPos (the phasing charts start from there)."""
    _moving_masters(rig, 100.0)
    gear = MC_GearInPos()
    msp = rig.master.Position + 60.0
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=True, RatioNumerator=ratio,
                                  SyncProfileReference=1, MasterStartDistance=50.0, MasterSyncPosition=msp,
                                  SlaveSyncPosition=0.0))
    rig.run_until(lambda: gear.InSync, timeout=5.0)
    return gear


def test_s7_1500_phasing_relative_adds_up_s9_1_3_2():
    rig = Rig()
    gear = _geared(rig)
    ph = MC_PhasingRelative()
    exe = {"on": False}
    rig.steps.append(lambda: ph(Master=rig.master, Slave=rig.slave, Execute=exe["on"], PhaseShift=50.0,
                                Velocity=100.0, Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0))
    offset = rig.slave.Position - rig.master.Position
    exe["on"] = True
    rig.ctl.step()
    assert ph.Busy and rig.slave.StatusWord.X24             # PhasingCommand
    seen = []
    while not ph.Done:
        seen.append(ph.CoveredPhaseShift)
        rig.ctl.step()
    assert seen == sorted(seen) and 0.0 <= seen[0] < 50.0     # ramps from 0 to 50
    assert ph.CoveredPhaseShift == 50.0 and rig.slave.StatusSynchronizedMotion.PhaseShift == pytest.approx(50.0)
    assert rig.slave.Position - rig.master.Position == pytest.approx(offset + 50.0)
    assert rig.master.Velocity == 100.0                       # the leading axis is not affected
    exe["on"] = False
    rig.ctl.step()
    exe["on"] = True
    rig.run_until(lambda: ph.Done, timeout=5.0)
    assert ph.CoveredPhaseShift == 50.0
    assert rig.slave.StatusSynchronizedMotion.PhaseShift == pytest.approx(100.0)
    assert gear.InSync and not rig.slave.StatusWord.X24


def test_s7_1500_phasing_absolute_to_the_same_shift_moves_nothing_s9_1_4_2():
    rig = Rig()
    _geared(rig)
    ph = MC_PhasingAbsolute()
    exe = {"on": True}
    rig.steps.append(lambda: ph(Master=rig.master, Slave=rig.slave, Execute=exe["on"], PhaseShift=50.0))
    rig.run_until(lambda: ph.Done, timeout=5.0)
    assert ph.AbsolutePhaseShift == 50.0 and rig.slave.StatusSynchronizedMotion.PhaseShift == pytest.approx(50.0)
    offset = rig.slave.Position - rig.master.Position
    exe["on"] = False
    rig.ctl.step()
    exe["on"] = True
    rig.run_until(lambda: ph.Done, timeout=1.0)
    assert rig.slave.Position - rig.master.Position == pytest.approx(offset)
    assert rig.slave.StatusSynchronizedMotion.PhaseShift == pytest.approx(50.0)


def test_s7_1500_phasing_needs_synchronous_gearing_s9_1_3():
    rig = Rig()
    ph = MC_PhasingRelative()
    rig.steps.append(lambda: ph(Master=rig.master, Slave=rig.slave, Execute=rig.enabled(), PhaseShift=5.0))
    rig.run_until(lambda: ph.Error, timeout=1.0)
    assert ph.ErrorID != 0


def _cams(rig):
    c1 = rig.ctl.add_cam("Cam_1", [(0, 0), (90, 40), (180, 100), (270, 40), (360, 0)], interpolation_mode=1,
                         boundary_conditions=1)
    c2 = rig.ctl.add_cam("Cam_2", [(0, 0), (180, -60), (360, 0)], interpolation_mode=1, boundary_conditions=1)
    ic1, ic2 = MC_InterpolateCam(), MC_InterpolateCam()
    rig.steps.append(lambda: (ic1(Cam=c1, Execute=True), ic2(Cam=c2, Execute=True)))
    rig.run_until(lambda: ic1.Done and ic2.Done, timeout=1.0)
    return c1, c2


def test_s7_1500_cam_in_switching_cams_in_advance_s9_1_5_2_chart1():
    rig = Rig(master_params=None)
    c1, c2 = _cams(rig)
    _moving_masters(rig, 200.0)
    a1, a2 = MC_CamIn(), MC_CamIn()
    exe = {"a1": False, "a2": False}
    rig.steps.append(lambda: a1(Master=rig.master, Slave=rig.slave, Cam=c1, Execute=exe["a1"], ApplicationMode=1,
                                SyncProfileReference=0, MasterOffset=400.0, Velocity=500.0, Acceleration=2000.0,
                                Deceleration=2000.0, Jerk=0.0))
    rig.steps.append(lambda: a2(Master=rig.master, Slave=rig.slave, Cam=c2, Execute=exe["a2"], ApplicationMode=1,
                                SyncProfileReference=1, MasterOffset=1500.0, MasterStartDistance=100.0))
    rig.record = lambda: {"m": rig.master.Position, "s": rig.slave.Position, "Abort_1": a1.CommandAborted,
                          "InSync_1": a1.InSync, "StartSync_2": a2.StartSync, "InSync_2": a2.InSync}
    exe["a1"] = True
    rig.run_until(lambda: a1.InSync, timeout=5.0)
    assert rig.master.Position >= 400.0                 # synchronous from the cam start (SyncPos = 400)
    m = rig.master.Position
    assert rig.slave.Position == pytest.approx(c1.curve.value((m - 400.0) % 360.0), abs=1e-6)
    exe["a2"] = True
    rig.ctl.step()
    rig.ctl.step()
    assert a2.Busy and not a2.StartSync and a1.InSync and not a1.CommandAborted   # A2 waits, A1 goes on
    rig.run_until(lambda: a2.StartSync, timeout=10.0)
    assert a1.CommandAborted                              # aborted when A2 becomes active
    row = next(r for r in rig.log if r["StartSync_2"])
    assert 1400.0 <= row["m"] <= 1400.0 + 200.0 * rig.ctl.app_cycle + 1e-9
    rig.run_until(lambda: a2.InSync, timeout=5.0)
    m = rig.master.Position
    assert rig.slave.Position == pytest.approx(c2.curve.value((m - 1500.0) % 360.0), abs=1e-6)


def test_s7_1500_cam_in_in_advance_then_subsequent_s9_1_5_2_chart2():
    rig = Rig()
    c1, c2 = _cams(rig)
    _moving_masters(rig, 200.0)
    a1, a2 = MC_CamIn(), MC_CamIn()
    exe = {"a1": True, "a2": False}
    rig.steps.append(lambda: a1(Master=rig.master, Slave=rig.slave, Cam=c1, Execute=exe["a1"], ApplicationMode=1,
                                SyncProfileReference=1, MasterOffset=300.0, MasterStartDistance=100.0))
    rig.steps.append(lambda: a2(Master=rig.master, Slave=rig.slave, Cam=c2, Execute=exe["a2"], ApplicationMode=1,
                                SyncProfileReference=3, MasterOffset=1000.0, MasterSyncPosition=90.0,
                                MasterStartDistance=120.0))
    rig.run_until(lambda: a1.StartSync, timeout=5.0)
    assert 200.0 <= rig.master.Position <= 210.0          # SyncPos - MasterStartDistance
    rig.run_until(lambda: a1.InSync, timeout=5.0)
    assert 300.0 <= rig.master.Position <= 310.0
    exe["a2"] = True
    rig.run_until(lambda: a2.StartSync, timeout=10.0)
    assert 1090.0 <= rig.master.Position <= 1100.0 and a1.CommandAborted   # at A2's MasterSyncPosition
    rig.run_until(lambda: a2.InSync, timeout=5.0)
    assert 1210.0 <= rig.master.Position <= 1220.0
    m = rig.master.Position
    assert rig.slave.Position == pytest.approx(c2.curve.value((m - 1000.0) % 360.0), abs=1e-6)


def test_s7_1500_simulation_of_synchronous_operation_procedure_s9_1_6_1():
    rig = Rig()
    mv = _moving_masters(rig, 100.0)[0]
    gear = MC_GearIn()
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=True))
    rig.run_until(lambda: gear.InGear, timeout=5.0)
    halt = MC_Halt()
    sim = MC_SynchronizedMotionSimulation()
    flags = {"halt": True, "sim": False}
    rig.steps.append(lambda: halt(Axis=rig.master, Execute=flags["halt"]))
    rig.steps.append(lambda: sim(Slave=rig.slave, Enable=flags["sim"]))
    rig.steps.remove(rig.steps[0])                         # the leading axis no longer gets MoveVelocity
    rig.run_until(lambda: halt.Done, timeout=5.0)
    offset = rig.slave.Position - rig.master.Position
    flags["sim"] = True
    rig.ctl.step()
    assert sim.InSimulation and sim.Busy and rig.slave.StatusSynchronizedMotion.StatusWord.X3
    rig.enable["Slave1"] = False                           # protective door opened
    rig.run(0.2)
    assert rig.slave.StatusWord.X22 and rig.slave.StatusSynchronizedMotion.FunctionState == 1
    assert gear.Busy and not gear.CommandAborted
    rig.enable["Slave1"] = True
    rig.run_until(lambda: rig.powers["Slave1"].Status, timeout=2.0)
    flags["sim"] = False
    rig.ctl.step()
    assert not sim.InSimulation and not sim.Busy
    assert rig.slave.Position - rig.master.Position == pytest.approx(offset)   # follows again, no resync
    assert gear.InGear
    del mv


def test_s7_1500_simulation_needs_status_synchronous_s9_1_6():
    rig = Rig()
    sim = MC_SynchronizedMotionSimulation()
    rig.steps.append(lambda: sim(Slave=rig.slave, Enable=rig.enabled()))
    rig.run(0.1)
    assert sim.Error and sim.ErrorID != 0 and not sim.InSimulation


def test_s7_1500_additive_leading_value_section_a_s9_1_7_2():
    rig = Rig()
    _moving_masters(rig, 100.0)
    add = MC_LeadingValueAdditive()
    gear = MC_GearInPos()
    value = {"add": 0.0}
    rig.steps.append(lambda: add(Axis=rig.slave, Enable=True, Position=value["add"]))
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=True, SyncProfileReference=0,
                                  MasterSyncPosition=500.0, SlaveSyncPosition=0.0, Velocity=300.0,
                                  Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0))
    rig.ctl.step()
    assert add.Busy and rig.slave.StatusSynchronizedMotion.StatusWord.X4
    rig.run_until(lambda: gear.StartSync, timeout=5.0)
    value["add"] = 30.0
    rig.ctl.step()
    eff = rig.slave.StatusSynchronizedMotion.EffectiveLeadingValue.Position
    assert eff == pytest.approx(rig.master.Position + 30.0, abs=0.5)
    value["add"] = 0.0
    rig.run_until(lambda: gear.InSync, timeout=5.0)
    assert rig.slave.Position == pytest.approx(rig.master.Position - 500.0, abs=1e-6)


def test_s7_1500_additive_leading_value_keeps_the_slave_still_section_b_s9_1_7_2():
    rig = Rig()
    _moving_masters(rig, 100.0)
    add = MC_LeadingValueAdditive()
    gear = MC_GearInPos()
    state = {"add": 0.0, "gear": False}

    def program():
        m = rig.master.Position
        if not state["gear"]:
            state["add"] = min(100.0, m)               # ramp the additive value up to 100
        elif gear.InSync and state["add"] > 0.0:
            state["add"] = max(0.0, 300.0 - m)         # effective value master + add stays at 300
        add(Axis=rig.slave, Enable=True, Position=state["add"])
        gear(Master=rig.master, Slave=rig.slave, Execute=state["gear"], SyncProfileReference=1,
             MasterSyncPosition=300.0, SlaveSyncPosition=0.0, MasterStartDistance=100.0)
    rig.steps.append(program)
    rig.run_until(lambda: rig.master.Position >= 100.0, timeout=5.0)
    state["gear"] = True
    rig.run_until(lambda: gear.StartSync, timeout=5.0)
    assert rig.master.Position + state["add"] == pytest.approx(200.0, abs=2 * 100.0 * 0.004)
    rig.run_until(lambda: gear.InSync, timeout=5.0)
    rig.run_until(lambda: rig.master.Position > 230.0, timeout=5.0)
    s0 = rig.slave.Position
    rig.run_until(lambda: rig.master.Position > 290.0, timeout=5.0)
    assert rig.slave.Position == pytest.approx(s0, abs=1e-6)    # effective value constant, slave at rest
    rig.run_until(lambda: rig.master.Position > 350.0, timeout=5.0)
    assert rig.slave.Position > s0 + 40.0                      # follows the master again


def test_s7_1500_disabling_the_slave_aborts_synchronous_operation_s9_1():
    rig = Rig()
    _moving_masters(rig, 100.0)
    gear = MC_GearIn()
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=True))
    rig.run_until(lambda: gear.InGear, timeout=5.0)
    rig.enable["Slave1"] = False
    rig.run(0.1)
    assert gear.CommandAborted and not gear.Busy
    assert rig.slave.StatusSynchronizedMotion.FunctionState == 0


def test_s7_1500_disabling_the_master_keeps_synchronous_operation_s9_1():
    rig = Rig()
    _moving_masters(rig, 100.0)
    gear = MC_GearIn()
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=True))
    rig.run_until(lambda: gear.InGear, timeout=5.0)
    rig.enable["Master1"] = False
    rig.run(0.5)
    assert gear.Busy and gear.InGear and not gear.CommandAborted
    offset = rig.slave.Position - rig.master.Position
    rig.run(0.1)
    assert rig.slave.Position - rig.master.Position == pytest.approx(offset)
    assert math.isfinite(rig.slave.Position)
