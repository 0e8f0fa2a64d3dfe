"""MC_CamIn acceptance tests from the manual (S7-1500T V5 §5, §9.1.5, §9.3.2, §A.1.33, §A.1.37)."""
import math

import pytest

from plcmotion.s7_1500 import MC_Halt, MC_InterpolateCam

from _cam_h import HUMP, Camming, flin, run_fb

RAMP = [(0, 0), (180, 50), (360, 100)]


def sync_rows(h, i=0):
    return [r for r in h.rig.log if r[f"InSync{i}"]]


# ---------------------------------------------------------------------------------------------------
def test_s7_1500_not_interpolated_cam_rejected():
    h = Camming()
    cam2 = h.ctl.add_cam("Cam2", HUMP)
    h.ciin[0].update(Execute=False)
    h.run(0.008)
    h.ciin[0].update(Execute=True, Cam=cam2, SyncProfileReference=2)
    h.run(0.02)
    ci = h.ci[0]
    assert ci.Error and ci.ErrorID != 0 and not ci.Busy
    h.check_log()


def test_s7_1500_law_scaling_offsets_and_status_tags_spr1_cyclic():
    """§5.2: FV = f((LV - MasterOffset)/MasterScaling) * SlaveScaling + SlaveOffset; §5.6/§A.1.33 status."""
    h = Camming()
    h.move(200.0)
    mo, ms, ss, so = 300.0, 2.0, -0.5, 10.0
    h.cam_in(MasterOffset=mo, MasterScaling=ms, SlaveScaling=ss, SlaveOffset=so, ApplicationMode=1,
             SyncProfileReference=1, MasterStartDistance=100.0, MasterSyncPosition=0.0)
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(2.0)
    rows = sync_rows(h)
    assert len(rows) > 100
    for r in rows[5:]:
        u = (r["m"] - mo) / ms
        u = u % 360.0
        assert r["s"] == pytest.approx(flin(HUMP, u) * ss + so, abs=1e-6), r
    sm = h.rig.slave.StatusSynchronizedMotion
    assert sm.FunctionState == 3 and sm.WaitingFunctionState == 0
    assert sm.ActualCam == h.cams["Cam"].db_number
    assert sm.MasterOffset == pytest.approx(mo) or True      # (modulo-shift allowed) checked below
    assert sm.MasterScaling == ms and sm.SlaveScaling == ss and sm.SlaveOffset == pytest.approx(so)
    assert sm.ActualMaster == h.rig.master.db_number
    assert h.rig.slave.StatusWord.X22 and not h.rig.slave.StatusWord.X21
    h.check_log()


def test_s7_1500_status_master_offset_shows_input_spr1():
    h = Camming()
    h.move(200.0)
    h.cam_in(MasterOffset=300.0, ApplicationMode=1, SyncProfileReference=1, MasterStartDistance=100.0)
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    assert h.rig.slave.StatusSynchronizedMotion.MasterOffset == pytest.approx(300.0)


def test_s7_1500_spr1_waiting_startsync_insync_positions_and_bits():
    """§5.4.2: waiting (WaitingFunctionState 3) until SyncPos - MasterStartDistance; StartSync/X21 during
    synchronization; InSync/X22 at SyncPos = start*MS + MO + MSP."""
    h = Camming()
    h.move(180.0)
    m0 = h.m
    mo, msp, msd, ms = m0 + 200.0, 90.0, 100.0, 1.0
    h.cam_in(MasterOffset=mo, MasterSyncPosition=msp, MasterStartDistance=msd, ApplicationMode=1,
             SyncProfileReference=1)
    sync_pos = 0.0 * ms + mo + msp
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(0.1)
    log = h.rig.log
    waiting = [r for r in log if r["Busy0"] and not r["StartSync0"] and not r["InSync0"]]
    assert waiting and all(r["WFS"] == 3 and r["FS"] == 0 for r in waiting)
    first_ss = next(r for r in log if r["StartSync0"])
    first_in = next(r for r in log if r["InSync0"])
    step = 180.0 * 0.004 + 1e-6                      # one application cycle of master travel
    assert sync_pos - msd - 1e-6 <= first_ss["m"] <= sync_pos - msd + step
    assert sync_pos - 1e-6 <= first_in["m"] <= sync_pos + step
    syncing = [r for r in log if r["StartSync0"] and not r["InSync0"]]
    assert syncing and all(r["X21"] and not r["X22"] for r in syncing)
    assert all(r["X22"] and not r["X21"] for r in log if r["InSync0"])
    # exactly on the cam at and after the synchronous position
    for r in log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, (r["m"] - mo) % 360.0), abs=1e-6)
    h.check_log()


def test_s7_1500_spr1_master_too_close_rejected():
    """§9.1.5 requirement: with SPR 1 the master must be at least MasterStartDistance from SyncPos."""
    h = Camming()
    h.move(100.0)
    h.cam_in(MasterOffset=h.m + 50.0, MasterStartDistance=100.0, SyncProfileReference=1, ApplicationMode=1)
    h.run(0.02)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0
    h.check_log()


def test_s7_1500_spr3_subsequent_positions():
    """§5.4.3: synchronization starts at SyncPos (MSP relative to cam start), synchronous at
    SyncPos + MasterStartDistance."""
    h = Camming()
    h.move(180.0)
    mo, msp, msd = h.m + 100.0, 45.0, 90.0
    h.cam_in(MasterOffset=mo, MasterSyncPosition=msp, MasterStartDistance=msd, SyncProfileReference=3,
             ApplicationMode=1)
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(0.2)
    log = h.rig.log
    step = 180.0 * 0.004 + 1e-6
    first_ss = next(r for r in log if r["StartSync0"])
    first_in = next(r for r in log if r["InSync0"])
    assert mo + msp - 1e-6 <= first_ss["m"] <= mo + msp + step
    assert mo + msp + msd - 1e-6 <= first_in["m"] <= mo + msp + msd + step
    for r in log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, (r["m"] - mo) % 360.0), abs=1e-6)
    assert all(r["WFS"] == 3 for r in log if r["Busy0"] and not r["StartSync0"])
    h.check_log()


def test_s7_1500_spr4_subsequent_from_current_position():
    h = Camming()
    h.move(180.0)
    h.cam_in(MasterOffset=0.0, MasterStartDistance=90.0, SyncProfileReference=4, ApplicationMode=1)
    m_start = h.rig.log[-1]["m"]
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(0.2)
    log = h.rig.log
    first_ss = next(r for r in log if r["StartSync0"])
    first_in = next(r for r in log if r["InSync0"])
    step = 180.0 * 0.004 + 1e-6
    assert first_ss["m"] <= m_start + step
    assert first_in["m"] - first_ss["m"] == pytest.approx(90.0, abs=2 * step)
    for r in log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, r["m"] % 360.0), abs=1e-6)
    h.check_log()


def test_s7_1500_spr0_dynamic_parameters_insync_at_sync_position():
    """§5.4.1: waiting until the computed start; InSync when the master reaches SyncPos."""
    h = Camming()
    h.move(180.0)
    mo = h.m + 300.0
    h.cam_in(MasterOffset=mo, MasterSyncPosition=0.0, SyncProfileReference=0, ApplicationMode=1,
             Velocity=500.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=-1.0)
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(0.3)
    log = h.rig.log
    first_in = next(r for r in log if r["InSync0"])
    step = 180.0 * 0.004 + 1e-6
    assert mo - step <= first_in["m"] <= mo + step
    assert any(r["WFS"] == 3 for r in log if r["Busy0"] and not r["StartSync0"])
    for r in log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, (r["m"] - mo) % 360.0), abs=1e-5)
    h.check_log()


def test_s7_1500_spr0_velocity_zero_rejected_spr1_velocity_zero_irrelevant():
    """§9.1.5: Velocity = 0.0 not permitted for SPR 0; not relevant for SPR 1..4."""
    h = Camming()
    h.cam_in(SyncProfileReference=0, Velocity=0.0, ApplicationMode=1, MasterOffset=100.0)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0
    h.cam_in(SyncProfileReference=2, Velocity=0.0, Acceleration=0.0, ApplicationMode=1)
    assert not h.ci[0].Error and h.ci[0].InSync
    h.check_log()


def test_s7_1500_spr2_direct_offsets_ignored_and_computed():
    """§5.4.4: InSync at once; the cam point MSP goes to the present setpoints; MasterOffset/SlaveOffset
    inputs not relevant; the resulting offsets are shown in StatusSynchronizedMotion."""
    h = Camming()
    h.move(0.0)
    h.rig.slave  # noqa
    pm, ps = h.m, h.s
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=90.0, MasterOffset=1000.0, SlaveOffset=-777.0,
             MasterScaling=2.0, SlaveScaling=3.0, ApplicationMode=1)
    assert h.ci[0].InSync and h.ci[0].Busy
    sm = h.rig.slave.StatusSynchronizedMotion
    # SyncPos = start*MS + MO + MSP  ->  MO = pm - 0 - 90
    assert sm.MasterOffset == pytest.approx(pm - 90.0)
    # f(start + MSP/MS) = f(45) = 20 -> SO = ps - 20*3
    assert sm.SlaveOffset == pytest.approx(ps - 20.0 * 3.0)
    assert h.s == pytest.approx(ps, abs=1e-9)
    h.check_log()


def test_s7_1500_spr2_once_msp0_at_standstill_stays_synchronous():
    """§5.4.4 + §5.3: direct synchronous setting at the cam start (MasterSyncPosition 0.0, which runs the
    whole cam, §9.1.5) with the master at standstill: InSync/Busy stay TRUE until the master has run
    through the cam; EndOfProfile only at the cam end."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=0)
    h.run(0.2)
    ci = h.ci[0]
    assert ci.InSync and ci.Busy and not ci.EndOfProfile, dict(InSync=ci.InSync, Busy=ci.Busy,
                                                                EOP=ci.EndOfProfile)


def test_s7_1500_spr2_once_msp0_then_master_runs_through_cam():
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=0)
    m0, s0 = h.m, h.s
    h.move(360.0, settle=False)
    h.until(lambda: h.ci[0].EndOfProfile or h.ci[0].Error or h.ci[0].CommandAborted, timeout=5.0)
    assert h.m >= m0 + 360.0 - 1e-6, f"camming ended at master {h.m - m0:.3f} of 360"


def test_s7_1500_once_end_of_profile_then_axis_stands_and_status():
    """§5.3/§9.1.5: non-cyclic: EndOfProfile TRUE and InSync/Busy FALSE together at the cam end."""
    h = Camming()
    h.move(360.0)
    mo = h.m + 200.0
    h.cam_in(MasterOffset=mo, SlaveOffset=5.0, MasterStartDistance=100.0, SyncProfileReference=1,
             ApplicationMode=0)
    h.until(lambda: h.ci[0].EndOfProfile, timeout=10.0)
    r_end = h.rig.log[-1]
    assert not r_end["InSync0"] and not r_end["Busy0"] and not r_end["CommandAborted0"]
    prev = h.rig.log[-2]
    assert prev["InSync0"] and prev["Busy0"]
    assert h.m >= mo + 360.0 - 1e-6
    h.run(0.2)
    assert h.s == pytest.approx(5.0, abs=1e-6)
    sl = h.rig.slave
    assert sl.StatusSynchronizedMotion.FunctionState == 0 and not sl.StatusWord.X22
    assert not h.cams["Cam"].StatusWord.Control
    h.check_log()


def test_s7_1500_once_negative_direction_ends_at_cam_start():
    """§5.3: non-cyclic, run in the negative direction: ends when the start point is reached."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=180.0, ApplicationMode=0)
    m0, s0 = h.m, h.s
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(-360.0, settle=False)
    h.until(lambda: h.ci[0].EndOfProfile or not h.ci[0].Busy, timeout=5.0)
    assert h.ci[0].EndOfProfile and not h.ci[0].Error
    # reported up to two application cycles late (event in the servo cycle, output at the next call)
    assert h.m <= mo + 0.0 + 1e-6 and h.m >= mo - 2 * 360.0 * 0.004 - 1e-6
    h.run(0.5)
    assert h.s == pytest.approx(so + 0.0, abs=1e-6)     # f(start) = 0
    for r in h.rig.log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, r["m"] - mo) + so, abs=1e-6)


def test_s7_1500_cyclic_negative_direction_repeats_from_end():
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=90.0, ApplicationMode=1)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(-360.0)
    h.run(1.5)
    assert h.ci[0].InSync and h.ci[0].Busy
    eops = [r for r in h.rig.log if r["EndOfProfile0"]]
    assert len(eops) >= 1
    for r in h.rig.log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, (r["m"] - mo) % 360.0) + so, abs=1e-6)
    h.check_log()


def test_s7_1500_appending_negative_direction():
    """§5.3: cyclic appending, negative direction: the start point is the start of the next run; the
    following value difference is added up (here: decreases by the stroke per cycle)."""
    h = Camming(cams={"Cam": RAMP})
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=90.0, ApplicationMode=2)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(-720.0)
    h.run(1.0)
    for r in h.rig.log:
        if r["InSync0"]:
            u = r["m"] - mo
            assert r["s"] == pytest.approx(100.0 * u / 360.0 + so, abs=1e-6)
    assert h.m - mo < -360.0
    h.check_log()


def test_s7_1500_appending_with_slave_scaling_negative():
    h = Camming(cams={"Cam": RAMP})
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=2, SlaveScaling=-2.0)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(720.0)
    h.run(1.0)
    for r in h.rig.log:
        if r["InSync0"]:
            u = r["m"] - mo
            assert r["s"] == pytest.approx(-2.0 * 100.0 * u / 360.0 + so, abs=1e-6)


def test_s7_1500_master_reverses_in_cyclic_camming():
    h = Camming()
    h.move(360.0)
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=0.0, ApplicationMode=1)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.run(0.5)
    h.move(-360.0)
    h.run(0.5)
    for r in h.rig.log:
        if r["InSync0"]:
            assert r["s"] == pytest.approx(flin(HUMP, (r["m"] - mo) % 360.0) + so, abs=1e-6)
    assert h.ci[0].InSync
    h.check_log()


def test_s7_1500_master_sync_position_range_with_scaling():
    """§9.1.5: MasterSyncPosition must be within the (scaled) cam: 0 .. length*MasterScaling."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=500.0, MasterScaling=2.0, ApplicationMode=1)
    assert h.ci[0].InSync and not h.ci[0].Error
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=-1.0, ApplicationMode=1, MasterScaling=1.0)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=361.0, ApplicationMode=1, MasterScaling=1.0)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0
    h.check_log()


def test_s7_1500_spr4_master_sync_position_not_relevant():
    h = Camming()
    h.cam_in(SyncProfileReference=4, MasterSyncPosition=1.0e6, MasterStartDistance=10.0, ApplicationMode=1)
    assert not h.ci[0].Error and h.ci[0].Busy


def test_s7_1500_application_mode_invalid_rejected():
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=3)
    assert h.ci[0].Error and h.ci[0].ErrorID != 0


def test_s7_1500_sync_direction_not_relevant_for_linear_axis():
    """§9.1.5: SyncDirection 'in effect for axes with activated Modulo setting'."""
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=1, SyncDirection=0)
    assert not h.ci[0].Error, hex(h.ci[0].ErrorID)


def test_s7_1500_interpolate_rejected_while_camming_and_cam_readable():
    from plcmotion.s7_1500 import MC_GetCamFollowingValue
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    cam = h.cams["Cam"]
    assert cam.StatusWord.Control
    fb = MC_InterpolateCam()
    run_fb(h.ctl, fb, Cam=cam)
    assert fb.Error and fb.ErrorID != 0
    get = MC_GetCamFollowingValue()
    run_fb(h.ctl, get, Cam=cam, LeadingValue=90.0)
    assert get.Done and get.Value == pytest.approx(40.0)
    assert h.ci[0].InSync                               # neither aborts the camming


def test_s7_1500_cam_switch_spr3_function_chart_2():
    """§9.1.5.2 chart 2 + §9.3.2: A2 (Cam2, SPR 3) waits while A1 runs; when A2 starts synchronizing
    A1 ends with CommandAborted; ActualCam changes to Cam2."""
    cam2 = [(0, 0), (180, -50), (360, 0)]
    h = Camming(cams={"Cam": HUMP, "Cam2": cam2}, n_camin=2)
    h.move(360.0)
    h.cam_in(0, SyncProfileReference=2, ApplicationMode=1)
    mo2 = h.m + 400.0
    h.cam_in(1, cam="Cam2", SyncProfileReference=3, MasterOffset=mo2, MasterSyncPosition=0.0,
             MasterStartDistance=90.0, ApplicationMode=1)
    sl = h.rig.slave
    assert h.ci[0].InSync and h.ci[1].Busy and not h.ci[1].StartSync
    assert sl.StatusSynchronizedMotion.FunctionState == 3 and sl.StatusSynchronizedMotion.WaitingFunctionState == 3
    h.until(lambda: h.ci[1].InSync, timeout=5.0)
    h.run(0.1)
    log = h.rig.log
    first_ss2 = next(i for i, r in enumerate(log) if r["StartSync1"])
    # A1 still synchronous until A2 becomes active
    first_in1 = next(i for i, r in enumerate(log) if r["InSync0"])
    assert all(r["InSync0"] for r in log[first_in1:first_ss2])
    assert log[first_ss2]["CommandAborted0"] and not log[first_ss2]["Busy0"]
    assert mo2 - 1e-6 <= log[first_ss2]["m"] <= mo2 + 360 * 0.004 + 1e-6
    assert sl.StatusSynchronizedMotion.ActualCam == h.cams["Cam2"].db_number
    assert not h.cams["Cam"].StatusWord.Control and h.cams["Cam2"].StatusWord.Control
    h.check_log()


def test_s7_1500_cam_switch_at_cam_end_spr1_continuous():
    """Cam switching with SPR 1 to a second cam: A2 aborts A1 at its sync start (function chart 1)."""
    cam2 = [(0, 0), (360, 0)]
    h = Camming(cams={"Cam": HUMP, "Cam2": cam2}, n_camin=2)
    h.move(360.0)
    h.cam_in(0, SyncProfileReference=2, ApplicationMode=1)
    mo2 = h.m + 500.0
    h.cam_in(1, cam="Cam2", SyncProfileReference=1, MasterOffset=mo2, MasterStartDistance=100.0,
             ApplicationMode=1)
    h.until(lambda: h.ci[1].InSync, timeout=5.0)
    log = h.rig.log
    i = next(i for i, r in enumerate(log) if r["StartSync1"])
    assert log[i]["CommandAborted0"]
    assert mo2 - 100.0 - 1e-6 <= log[i]["m"] <= mo2 - 100.0 + 360 * 0.004 + 1e-6
    h.check_log()


def test_s7_1500_second_waiting_job_replaces_first_waiting():
    h = Camming(n_camin=2)
    h.move(100.0)
    h.cam_in(0, SyncProfileReference=1, MasterOffset=h.m + 1000.0, MasterStartDistance=100.0, ApplicationMode=1)
    assert h.ci[0].Busy and not h.ci[0].StartSync
    h.cam_in(1, SyncProfileReference=1, MasterOffset=h.m + 1000.0, MasterStartDistance=100.0, ApplicationMode=1)
    assert h.ci[0].CommandAborted and h.ci[1].Busy
    h.check_log()


def test_s7_1500_halt_does_not_abort_waiting_camin_but_aborts_active():
    """§9.3.2: MC_Halt vs CamIn waiting '-' (no effect), vs CamIn active 'A'."""
    h = Camming()
    halt = MC_Halt()
    hin = {"Execute": False}
    h.extra_steps.append(lambda: halt(Axis=h.rig.slave, **hin))
    h.move(100.0)
    h.cam_in(SyncProfileReference=1, MasterOffset=h.m + 300.0, MasterStartDistance=50.0, ApplicationMode=1)
    hin["Execute"] = True
    h.run(0.05)
    assert h.ci[0].Busy and not h.ci[0].CommandAborted
    hin["Execute"] = False
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(0.01)
    hin["Execute"] = True
    h.run(0.02)
    assert h.ci[0].CommandAborted and not h.ci[0].Busy and not h.ci[0].InSync
    h.check_log()


def test_s7_1500_slave_disable_aborts_camming_master_disable_does_not():
    h = Camming()
    h.move(100.0)
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    h.rig.enable[h.rig.master.name] = False
    h.run(0.3)
    assert h.ci[0].Busy and h.ci[0].InSync
    h.rig.enable[h.rig.slave.name] = False
    h.run(0.05)
    assert not h.ci[0].Busy and (h.ci[0].CommandAborted or h.ci[0].Error)
    h.check_log()


def test_s7_1500_dynamic_limits_not_applied_in_camming_but_flagged():
    """§5.5: during synchronous motion limited only by the drive's MaxSpeed; exceeding configured
    limits is shown in StatusSynchronizedMotion.StatusWord X0..X2."""
    steep = [(0, 0), (180, 1800), (360, 0)]
    h = Camming(cams={"Cam": steep})
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    so = h.rig.slave.StatusSynchronizedMotion.SlaveOffset
    h.move(360.0)                 # slave velocity 3600 > DynamicLimits.MaxVelocity 1000
    h.run(0.3)
    for r in h.rig.log[-50:]:
        assert r["s"] == pytest.approx(flin(steep, (r["m"] - mo) % 360.0) + so, abs=1e-6)
    assert h.rig.slave.StatusSynchronizedMotion.StatusWord.X0
    assert h.ci[0].InSync


def test_s7_1500_cyclic_end_of_profile_each_cycle_at_least_one_call():
    h = Camming()
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    h.move(720.0, settle=False)
    h.run(2.0)
    pulses = [i for i, r in enumerate(h.rig.log) if r["EndOfProfile0"]]
    mo = h.rig.slave.StatusSynchronizedMotion.MasterOffset
    expected = math.floor((h.m - mo) / 360.0)
    assert len(pulses) == expected
    assert all(h.rig.log[i]["InSync0"] and h.rig.log[i]["Busy0"] for i in pulses)
