"""More cam TO checks (S7-1500T V5 §5.1, §6.2.5.7, §9.2.1, §A.2)."""
import math

import pytest

from plcmotion.s7_1500 import MC_GetCamFollowingValue, MC_InterpolateCam

from _cam_h import Camming, cam_rig, interpolate, run_fb


def fval(ctl, cam, x):
    get = MC_GetCamFollowingValue()
    run_fb(ctl, get, Cam=cam, LeadingValue=x)
    assert get.Done
    return get.Value, get.FirstDerivative, get.SecondDerivative


def test_s7_1500_full_capacity_1000_points_50_segments():
    pts = [(float(i), math.sin(i / 50.0)) for i in range(1000)]
    segs = [{"xmin": 1000.0 + 10 * k, "xmax": 1005.0 + 10 * k, "a0": float(k % 3)} for k in range(50)]
    ctl, cam = cam_rig(pts, segments=segs, interpolation_mode=1)
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam, cycles=50)
    assert fb.Done and cam.StatusCam.EndLeadingValue == 1495.0
    assert fval(ctl, cam, 500.0)[0] == pytest.approx(math.sin(10.0), abs=1e-9)
    with pytest.raises(Exception):
        cam.Point[1001].x = 1.0
    with pytest.raises(Exception):
        cam.Segment[51].a0 = 1.0


def test_s7_1500_cubic_spline_c1_into_segment():
    ctl, cam = cam_rig([(0, 0), (50, 30), (100, 10)],
                       segments=[{"xmin": 150.0, "xmax": 250.0, "a0": -20.0, "a1": 0.2}], interpolation_mode=1)
    interpolate(ctl, cam)
    v1, d1, _ = fval(ctl, cam, 150.0 - 1e-7)
    v2, d2, _ = fval(ctl, cam, 150.0 + 1e-7)
    assert v1 == pytest.approx(10.0, abs=1e-5) and v2 == pytest.approx(10.0, abs=1e-5)
    assert d1 == pytest.approx(0.2, abs=1e-4)
    for x, y in [(0, 0), (50, 30), (100, 10)]:
        assert fval(ctl, cam, float(x))[0] == pytest.approx(y, abs=1e-9)


def test_s7_1500_interpolating_other_cam_does_not_abort_camming():
    h = Camming(cams={"Cam": [(0, 0), (180, 50), (360, 0)], "Other": [(0, 0), (10, 1)]})
    h.cam_in(SyncProfileReference=2, ApplicationMode=1)
    fb = MC_InterpolateCam()
    run_fb(h.ctl, fb, Cam=h.cams["Other"])
    assert fb.Done and h.ci[0].InSync and h.ci[0].Busy


def test_s7_1500_status_after_non_cyclic_end():
    h = Camming()
    h.cam_in(SyncProfileReference=2, MasterSyncPosition=10.0, ApplicationMode=0)
    h.move(720.0, settle=False)
    h.until(lambda: h.ci[0].EndOfProfile, timeout=5.0)
    h.run(0.02)
    sm = h.rig.slave.StatusSynchronizedMotion
    assert sm.FunctionState == 0 and sm.ActualCam == 0 and sm.ActualMaster == 0
    assert not h.rig.slave.StatusWord.X22 and not h.rig.slave.StatusWord.X21
