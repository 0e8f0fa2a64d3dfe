"""More MC_CamIn edge cases from the manual (S7-1500T V5 §5.3, §5.4.1, §5.4.3, §5.4.4, §5.5)."""
import pytest

from _cam_h import HUMP, Camming, flin

RAMP = [(0, 0), (180, 50), (360, 100)]


def test_s7_1500_spr2_once_msp_end_at_standstill_then_negative_runs_whole_cam():
    """Mirror case of the MSP=0 defect: synchronous at the cam end, then run in the negative direction:
    the whole cam should be run until the start point (§5.3)."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=360.0, ApplicationMode=0)
    h.run(0.1)
    assert h.ci[0].InSync and h.ci[0].Busy, "ended at once at the cam end point"


def test_s7_1500_spr2_once_msp0_master_already_moving():
    h = Camming()
    h.move(360.0)
    m0 = h.m
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=0)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    h.until(lambda: h.ci[0].EndOfProfile or not h.ci[0].Busy, timeout=5.0)
    assert h.m - mo >= 360.0 - 1e-6, f"ended after {h.m - mo:.2f} of 360"


def test_s7_1500_spr2_once_msp_mid_at_standstill():
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=100.0, ApplicationMode=0)
    h.run(0.2)
    assert h.ci[0].InSync and h.ci[0].Busy


def test_s7_1500_spr4_once_master_outside_cam_definition():
    """§5.4.3: with SPR 3 and 4 'the values must each be within the definition of the cam'.
    SPR 4 synchronizes from the present master position; with ApplicationMode 0 and the present position
    outside the (offset) cam, the job should be rejected."""
    h = Camming()
    h.cam_in(SyncProfileReference=4, MasterOffset=1000.0, MasterStartDistance=50.0, ApplicationMode=0)
    h.run(0.05)
    ci = h.ci[0]
    assert ci.Error and ci.ErrorID != 0, dict(Busy=ci.Busy, StartSync=ci.StartSync, InSync=ci.InSync)


def test_s7_1500_spr0_master_at_sync_position_must_cross_start_first():
    """§5.4.1: if the leading axis is in its synchronous position at job start it must first cross the
    start position: a linear master standing at SyncPos that then moves on does not synchronize."""
    h = Camming()
    h.cam_in(SyncProfileReference=0, MasterOffset=h.m, ApplicationMode=1, Velocity=500.0,
             Acceleration=5000.0, Deceleration=5000.0)
    h.move(100.0, settle=False)
    h.run(1.0)
    assert h.ci[0].Busy and not h.ci[0].StartSync and not h.ci[0].InSync
    assert h.rig.slave.StatusSynchronizedMotion.WaitingFunctionState == 3


def test_s7_1500_appending_with_master_scaling():
    h = Camming(cams={"Cam": RAMP})
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=2, MasterScaling=0.5)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(360.0)
    h.run(1.0)
    for r in h.rig.log:
        if r["InSync0"]:
            u = (r["m"] - mo) / 0.5
            assert r["s"] == pytest.approx(100.0 * u / 360.0 + so, abs=1e-6)
    assert (h.m - mo) / 0.5 > 720.0
    h.check_log()


def test_s7_1500_dynamic_limit_flags_acceleration():
    """§5.5: exceeding the configured acceleration in camming is shown (StatusSynchronizedMotion X1/X2)."""
    h = Camming(cams={"Cam": [(0, 0), (10, 0), (20, 500), (30, 0), (360, 0)]}, mode=1)
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    h.move(360.0, settle=False)
    seen = set()
    for _ in range(300):
        h.run(0.004)
        w = h.rig.slave.StatusSynchronizedMotion.StatusWord
        if w.X1:
            seen.add(1)
        if w.X2:
            seen.add(2)
    assert seen >= {1, 2}, seen


def test_s7_1500_camin_slave_not_enabled_rejected():
    h = Camming()
    h.rig.enable[h.rig.slave.name] = False
    h.run(0.05)
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0
    h.check_log()


def test_s7_1500_once_master_reverses_before_end_ends_at_start():
    """§5.3: non-cyclic, run in the negative direction -> ends at the cam start point."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=100.0, ApplicationMode=0)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(300.0)
    h.run(0.2)
    h.move(-300.0, settle=False)
    h.until(lambda: not h.ci[0].Busy, timeout=5.0)
    assert h.ci[0].EndOfProfile
    h.run(0.3)
    assert h.s == pytest.approx(so + flin(HUMP, 0.0), abs=1e-6)


def test_s7_1500_spr2_master_and_slave_offset_not_relevant():
    """§9.1.5: MasterOffset/SlaveOffset 'When SyncProfileReference = 2: Not relevant' -> not checked."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=1, MasterOffset=5.0e12, SlaveOffset=float("nan"))
    assert not h.ci[0].Error and h.ci[0].InSync, hex(h.ci[0].ErrorID)


def test_s7_1500_irrelevant_inputs_for_spr2_not_checked_start_distance():
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=1, MasterStartDistance=-5.0, Velocity=0.0)
    assert not h.ci[0].Error and h.ci[0].InSync
