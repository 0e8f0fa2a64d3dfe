"""Invariants of synchronous operation (S7-1500T V5 §4.2, §4.3, §5.4): synchronism reached exactly at the
synchronous positions for any positions, ratios and directions; the following axis's setpoint is always
finite and continuous; the synchronous law holds afterwards."""
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.s7_1500 import MC_CamIn, MC_GearInPos, MC_InterpolateCam, MC_MoveVelocity

from _s7_1500_rig import VIRTUAL, Rig, merge, modulo


@settings(max_examples=25, deadline=None)
@given(spr=st.sampled_from([1, 3]), direction=st.sampled_from([1.0, -1.0]), num=st.integers(-3, 3).filter(bool),
       den=st.integers(1, 4), distance=st.floats(20.0, 150.0), ahead=st.floats(30.0, 300.0),
       slave_sync=st.floats(-500.0, 500.0), master_modulo=st.booleans())
def test_s7_1500_gear_in_pos_synchronous_exactly_at_the_synchronous_positions_s4_3(spr, direction, num, den, distance,
                                                                           ahead, slave_sync, master_modulo):
    mp = merge(VIRTUAL, modulo(360.0)) if master_modulo else VIRTUAL
    rig = Rig(master_params=mp)
    speed = 120.0 * direction
    mv = MC_MoveVelocity()
    gear = MC_GearInPos()
    ratio = num / den
    start_gap = distance + ahead if spr == 1 else ahead
    msp_raw = direction * start_gap
    msp = msp_raw % 360.0 if master_modulo else msp_raw
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=rig.enabled(), Velocity=speed))
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=rig.enabled(), RatioNumerator=num,
                                  RatioDenominator=den, MasterSyncPosition=msp, SlaveSyncPosition=slave_sync,
                                  SyncProfileReference=spr, MasterStartDistance=distance))
    rows = []
    rig.record = lambda: rows.append({"m": float(rig.ctl.bank.sp_p[rig.master.index]), "s": rig.slave.Position,
                                      "v": rig.slave.Velocity, "in_sync": gear.InSync}) or {}
    rig.run_until(lambda: gear.InSync or gear.Error, timeout=6.0)
    assert not gear.Error, hex(gear.ErrorID)
    # unwrapped leading value of the synchronous point; the master position when InSync is first shown
    sync_point = msp_raw if spr == 1 else msp_raw + direction * distance
    law_anchor = msp_raw
    first = next(r for r in rows if r["in_sync"])
    travelled = (first["m"] - sync_point) * direction
    # InSync in the servo cycle after the point is passed, shown at the next call of the instruction
    assert -1e-9 <= travelled <= abs(speed) * (rig.ctl.app_cycle + rig.ctl.servo_cycle) + 1e-9
    expected = slave_sync + ratio * (first["m"] - law_anchor)
    assert first["s"] == pytest.approx(expected, abs=1e-7 * max(1.0, abs(expected)))
    rig.run(0.2)
    m_now = rig.ctl.bank.sp_p[rig.master.index]
    assert rig.slave.Position == pytest.approx(slave_sync + ratio * (m_now - law_anchor), abs=1e-6)
    assert all(math.isfinite(r["s"]) and math.isfinite(r["v"]) for r in rows)


@settings(max_examples=20, deadline=None)
@given(sync_direction=st.sampled_from([1, 2, 3]), slave_start=st.floats(0.0, 359.0), slave_sync=st.floats(0.0, 359.0))
def test_s7_1500_sync_direction_on_a_modulo_following_axis_s4_3(sync_direction, slave_start, slave_sync):
    """SyncDirection 1: the following axis covers a non-negative net distance during synchronization,
    2 a non-positive one, 3 the shortest correction to the synchronous law (at most half a revolution);
    the synchronous position is reached modulo the axis length (docs/s7_1500/decisions.md #17)."""
    rig = Rig(slave_params=merge(VIRTUAL, modulo(360.0)))
    from plcmotion.s7_1500 import MC_Home
    home = MC_Home()
    mv = MC_MoveVelocity()
    gear = MC_GearInPos()
    flags = {"go": False}
    rig.steps.append(lambda: home(Axis=rig.slave, Execute=rig.enabled(), Mode=0, Position=slave_start))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=flags["go"], Velocity=100.0))
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=flags["go"], RatioNumerator=0 + 1,
                                  MasterSyncPosition=200.0, SlaveSyncPosition=slave_sync, SyncProfileReference=1,
                                  MasterStartDistance=100.0, SyncDirection=sync_direction))
    rig.run_until(lambda: home.Done, timeout=1.0)
    start = float(rig.ctl.bank.sp_p[rig.slave.index])      # the slave stands here until StartSync
    flags["go"] = True
    rig.run_until(lambda: gear.InSync, timeout=5.0)
    m_now = rig.ctl.bank.sp_p[rig.master.index]
    end = rig.ctl.bank.sp_p[rig.slave.index] - (m_now - 200.0)      # slave position at the sync point
    moved = end - start
    assert (end - slave_sync) % 360.0 == pytest.approx(0.0, abs=1e-6) or \
        (end - slave_sync) % 360.0 == pytest.approx(360.0, abs=1e-6)
    law_delta = 100.0                                               # ratio 1 over the 100 of start distance
    if sync_direction == 1:
        assert moved >= -1e-6
    elif sync_direction == 2:
        assert moved <= 1e-6
    else:
        assert abs(moved - law_delta) <= 180.0 + 1e-6


@settings(max_examples=15, deadline=None)
@given(spr=st.sampled_from([1, 3, 4]), master_offset=st.floats(0.0, 200.0), scaling=st.floats(0.5, 2.0),
       slave_scaling=st.floats(-2.0, 2.0), distance=st.floats(30.0, 200.0), app_mode=st.sampled_from([1, 2]))
def test_s7_1500_cam_in_synchronous_on_the_scaled_cam_s5_2_s5_4(spr, master_offset, scaling, slave_scaling, distance,
                                                                app_mode):
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", [(0, 0), (60, 10), (120, 50), (240, 70), (360, 100)], interpolation_mode=1)
    ic = MC_InterpolateCam()
    mv = MC_MoveVelocity()
    ci = MC_CamIn()
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=ic.Done, Velocity=150.0))
    # SyncProfileReference 1 needs the master at least MasterStartDistance before the synchronous position
    offset = master_offset + (distance if spr == 1 else 0.0)
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=ic.Done, MasterOffset=offset,
                                MasterScaling=scaling, SlaveScaling=slave_scaling, SlaveOffset=5.0,
                                SyncProfileReference=spr, MasterStartDistance=distance, MasterSyncPosition=30.0,
                                ApplicationMode=app_mode))
    rig.run_until(lambda: ci.InSync or ci.Error, timeout=8.0)
    assert not ci.Error, hex(ci.ErrorID)
    rig.run(0.3)
    x = rig.ctl.bank.sp_p[rig.master.index]
    curve = cam.curve
    u = (x - offset) / scaling
    cycles = math.floor(u / 360.0)
    f = float(curve.value(u - cycles * 360.0))
    if app_mode == 2:
        f += cycles * (100.0 - 0.0)
    assert rig.slave.Position == pytest.approx(f * slave_scaling + 5.0, abs=1e-6)
