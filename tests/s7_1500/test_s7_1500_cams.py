"""The cam technology object and the cam instructions (S7-1500T V5 §3.2, §5, §9.2, §A.2); camming
application modes and synchronization variants of MC_CamIn (§5.3, §5.4)."""
import math

import pytest

from plcmotion import ConfigurationError, Controller
from plcmotion.s7_1500 import (MC_CamIn, MC_GetCamFollowingValue, MC_GetCamLeadingValue, MC_InterpolateCam,
                               MC_MoveVelocity, MC_Power, MC_Reset)
from plcmotion.s7_1500 import errors as E

from _s7_1500_rig import Rig

HUMP = [(0, 0), (90, 40), (180, 100), (270, 40), (360, 0)]


def cam_rig(points=HUMP, **settings):
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam", points, **settings)
    return ctl, cam


def run_fb(ctl, fb, **inputs):
    fb(Execute=False, **inputs)
    fb(Execute=True, **inputs)
    for _ in range(5):
        if fb.Done or fb.Error:
            break
        ctl.step()
        fb(Execute=True, **inputs)
    return fb


def test_s7_1500_interpolate_cam_status_and_done_s9_2_1():
    ctl, cam = cam_rig(interpolation_mode=1)
    assert not cam.StatusWord.Interpolated and cam.StatusCam.EndLeadingValue == 0.0
    fb = MC_InterpolateCam()
    fb(Cam=cam, Execute=True)
    assert fb.Busy and cam.StatusWord.X6                       # InInterpolation until the next servo cycle
    ctl.step()
    fb(Cam=cam, Execute=True)
    assert fb.Done and not fb.Busy and cam.StatusWord.X5 and not cam.StatusWord.X6
    assert cam.StatusCam.StartLeadingValue == 0.0 and cam.StatusCam.EndLeadingValue == 360.0
    cam.Point[2].y = 50.0                                       # a change of the definition
    assert cam.StatusWord.CamDataChanged and cam.StatusWord.Interpolated   # the old curve stays in use
    run_fb(ctl, fb, Cam=cam)
    assert not cam.StatusWord.CamDataChanged and float(cam.curve.value(90.0)) == pytest.approx(50.0)


def test_s7_1500_cam_tags_points_segments_validity_sA_2():
    ctl, cam = cam_rig([])
    cam.Point[1].x, cam.Point[1].y = 0.0, 0.0
    cam.Point[2].x, cam.Point[2].y = 100.0, 10.0
    cam.ValidPoint[1] = cam.ValidPoint[2] = True
    cam.Segment[1].xmin, cam.Segment[1].xmax, cam.Segment[1].a0 = 100.0, 200.0, 10.0
    cam.ValidSegment[1] = True
    cam.InterpolationSettings.InterpolationMode = 0
    run_fb(ctl, MC_InterpolateCam(), Cam=cam)
    assert cam.curve.value(50.0) == pytest.approx(5.0) and cam.curve.value(150.0) == 10.0
    assert cam.tag("Point[2].y") == 10.0 and cam.tag("ValidSegment[1]") is True
    with pytest.raises(IndexError):
        cam.Point[1001].x = 0.0
    with pytest.raises(TypeError):
        cam.Point[1].x = "ten"


def test_s7_1500_interpolate_cam_definition_error_s9_2_1():
    ctl, cam = cam_rig([(0, 0)])
    fb = run_fb(ctl, MC_InterpolateCam(), Cam=cam)
    assert fb.Error and fb.ErrorID == E.CAM_DEFINITION and not cam.StatusWord.Interpolated


def test_s7_1500_get_cam_following_value_and_derivatives_s9_2_3():
    ctl, cam = cam_rig(interpolation_mode=0)
    get = MC_GetCamFollowingValue()
    assert run_fb(ctl, get, Cam=cam, LeadingValue=45.0).ErrorID == E.NO_FOLLOWING_VALUE
    run_fb(ctl, MC_InterpolateCam(), Cam=cam)
    run_fb(ctl, get, Cam=cam, LeadingValue=45.0)
    assert get.Done and get.Value == pytest.approx(20.0) and get.FirstDerivative == pytest.approx(40.0 / 90.0)
    assert get.SecondDerivative == 0.0
    assert run_fb(ctl, get, Cam=cam, LeadingValue=400.0).ErrorID == E.NO_FOLLOWING_VALUE


def test_s7_1500_get_cam_leading_value_with_approach_value_s9_2_2():
    ctl, cam = cam_rig(interpolation_mode=0)
    run_fb(ctl, MC_InterpolateCam(), Cam=cam)
    get = MC_GetCamLeadingValue()
    run_fb(ctl, get, Cam=cam, FollowingValue=70.0, ApproachLeadingValue=0.0)
    assert get.Done and get.Value == pytest.approx(135.0)
    run_fb(ctl, get, Cam=cam, FollowingValue=70.0, ApproachLeadingValue=300.0)
    assert get.Value == pytest.approx(225.0)
    assert run_fb(ctl, get, Cam=cam, FollowingValue=150.0).ErrorID == E.NO_LEADING_VALUE


def _camming(app_mode, spr, cam_points=HUMP, velocity=180.0, **inputs):
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", cam_points, interpolation_mode=1)
    ic, mv, ci = MC_InterpolateCam(), MC_MoveVelocity(), MC_CamIn()
    exe = {"cam": True}
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=ic.Done, Velocity=velocity))
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=ic.Done and exe["cam"],
                                ApplicationMode=app_mode, SyncProfileReference=spr, **inputs))
    rig.record = lambda: {"m": rig.master.Position, "s": rig.slave.Position, "InSync": ci.InSync,
                          "Busy": ci.Busy, "EndOfProfile": ci.EndOfProfile}
    return rig, cam, ci, exe


def test_s7_1500_cam_once_ends_with_end_of_profile_s5_3():
    rig, cam, ci, exe = _camming(0, 1, MasterOffset=100.0, MasterStartDistance=50.0)
    rig.run_until(lambda: ci.InSync, timeout=5.0)
    assert cam.StatusWord.Control                               # cam in use
    interp = MC_InterpolateCam()
    interp(Cam=cam, Execute=True)
    rig.ctl.step()
    interp(Cam=cam, Execute=True)
    assert interp.Error and interp.ErrorID == E.CAM_IN_USE     # not while the cam is used (§9.2.1)
    rig.run_until(lambda: ci.EndOfProfile, timeout=5.0)
    assert not ci.InSync and not ci.Busy
    assert rig.master.Position >= 460.0
    assert rig.slave.Position == pytest.approx(0.0, abs=1e-6)   # the end point of the cam
    rig.run(0.3)
    assert rig.slave.Position == pytest.approx(0.0, abs=1e-6)   # the following axis stands
    assert rig.slave.StatusSynchronizedMotion.FunctionState == 0 and not cam.StatusWord.Control
    exe["cam"] = False
    rig.ctl.step()
    rig.ctl.step()
    assert not ci.EndOfProfile


def test_s7_1500_cam_cyclic_end_of_profile_for_one_call_per_cycle_s5_3():
    rig, cam, ci, exe = _camming(1, 1, MasterOffset=100.0, MasterStartDistance=50.0, velocity=360.0)
    rig.run_until(lambda: ci.InSync, timeout=5.0)
    rig.log.clear()
    rig.run(3.0)
    pulses = [r for r in rig.log if r["EndOfProfile"]]
    assert len(pulses) == 3 and all(r["InSync"] and r["Busy"] for r in rig.log)


def test_s7_1500_cam_cyclic_appending_accumulates_the_following_value_s5_3():
    ramp = [(0, 0), (180, 50), (360, 100)]
    rig, cam, ci, exe = _camming(2, 1, ramp, MasterOffset=100.0, MasterStartDistance=50.0, velocity=360.0)
    rig.run_until(lambda: ci.InSync, timeout=5.0)
    rig.run(2.0)
    x = rig.ctl.bank.sp_p[rig.master.index]
    assert rig.slave.Position == pytest.approx(100.0 * (x - 100.0) / 360.0, abs=1e-6)


def test_s7_1500_cam_direct_synchronous_setting_s5_4_4():
    rig, cam, ci, exe = _camming(1, 2, MasterSyncPosition=90.0, velocity=0.0)
    rig.run_until(lambda: ci.InSync, timeout=2.0)
    sm = rig.slave.StatusSynchronizedMotion
    # the cam point at MasterSyncPosition lies at the present master and slave positions
    assert sm.MasterOffset == pytest.approx(rig.master.Position - 90.0)
    assert sm.SlaveOffset == pytest.approx(rig.slave.Position - 40.0)
    assert sm.FunctionState == 3 and sm.ActualCam == cam.db_number


def test_s7_1500_cam_subsequent_from_current_position_s5_4_3():
    rig, cam, ci, exe = _camming(1, 4, MasterStartDistance=120.0, MasterOffset=0.0)
    rig.run_until(lambda: ci.StartSync, timeout=2.0)
    start = rig.master.Position
    rig.run_until(lambda: ci.InSync, timeout=5.0)
    # StartSync and InSync are both seen up to one application cycle late
    assert rig.master.Position - start == pytest.approx(120.0, abs=180.0 * 2 * rig.ctl.app_cycle + 1e-6)


def test_s7_1500_cam_in_rejections_s9_1_5():
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", HUMP)
    ci = MC_CamIn()
    inputs = {"spr": 1, "msp": 0.0}
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=rig.enabled(),
                                SyncProfileReference=inputs["spr"], MasterSyncPosition=inputs["msp"],
                                MasterOffset=500.0, MasterStartDistance=10.0))
    rig.run_until(lambda: ci.Error, timeout=1.0)
    # a cam not interpolated: alarm 612 at the following axis (reaction 4 remove enable), acknowledged with
    # MC_Reset before the next job (docs/s7_1500/decisions.md #95)
    assert ci.ErrorID == E.TO_ALARM and rig.slave.ErrorDetail.Number == 612 and not rig.slave.StatusWord.Enable
    run_fb(rig.ctl, MC_InterpolateCam(), Cam=cam)
    ci(Execute=False)
    inputs["msp"] = 400.0                                      # beyond the cam (0 .. 360)
    run_fb(rig.ctl, MC_Reset(), Axis=rig.slave)
    rig.run_until(lambda: ci.Error, timeout=1.0)
    assert ci.ErrorID == E.SYNC_POSITION


def test_s7_1500_cam_restart_reloads_the_start_values_sA_2():
    ctl, cam = cam_rig()
    run_fb(ctl, MC_InterpolateCam(), Cam=cam)
    cam.Point[3].y = 0.0
    reset = MC_Reset()
    reset(Axis=cam, Execute=True, Restart=True)
    assert reset.Done and not cam.StatusWord.Interpolated and cam.Point[3].y == 100.0
    assert math.isclose(cam.Point[2].x, 90.0)


def test_s7_1500_cyclic_cam_over_whole_revolutions_of_a_modulo_axis_has_no_step_s5_3():
    """§5.3 cyclic camming of a rotary knife / cross cutter: a cam from 0 to 360 degrees on a modulo axis
    (360) repeats without a setpoint step at the cam end — the end and start positions are the same
    position of the axis — so a PROFIdrive following axis runs on without a following error alarm."""
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", {"VirtualAxis": {"Mode": 1}})
    s = ctl.add_synchronous_axis("S", {"Actor": {"Type": 1}, "Modulo": {"Enable": True, "Length": 360.0}},
                                 leading_values=["M"])
    cam = ctl.add_cam("Cam", [(0, 0), (500, 180), (1000, 360)])
    pm, ps, mv, ip, ci = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_InterpolateCam(), MC_CamIn()

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        ip(Cam=cam, Execute=True)
        mv(Axis=m, Execute=pm.Status, Velocity=500.0)
        ci(Master=m, Slave=s, Cam=cam, Execute=ps.Status and ip.Done, ApplicationMode=1, SyncProfileReference=2)

    ctl.run_until(lambda: ci.InSync and mv.InVelocity, timeout=2.0)
    ends, speeds = 0, []
    while ctl.time < 5.0:
        ctl.step()
        ends += ci.EndOfProfile
        speeds.append(s.Velocity)
        assert not ci.Error and s.StatusWord.Enable and s.ErrorDetail.Number == 0
        assert 0.0 <= s.Position < 360.0
    assert ends >= 2                                     # the master passed the cam end more than once
    assert max(speeds) < 180.0 + 1e-6 and min(speeds) > 180.0 - 1e-6   # 360/1000 x 500: no step
    assert ci.InSync and ci.Busy


def test_s7_1500_add_cam_rejects_an_unknown_interpolation_mode_sA_2_6():
    """§A.2.6: InterpolationSettings.InterpolationMode 0..2, BoundaryConditions 0..1 (named in the error)."""
    ctl = Controller(family="S7-1500T")
    with pytest.raises(ConfigurationError, match="InterpolationSettings.InterpolationMode = 3"):
        ctl.add_cam("Cam", [(0, 0), (1, 1)], interpolation_mode=3)
    with pytest.raises(ConfigurationError, match="BoundaryConditions = 2"):
        ctl.add_cam("Cam", [(0, 0), (1, 1)], boundary_conditions=2)
