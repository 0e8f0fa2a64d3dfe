"""Cam technology object and MC_InterpolateCam / MC_GetCam* (S7-1500T V5 §3.2, §5.1, §6.2.5.7, §9.2, §A.2)."""
import math

import numpy as np
import pytest

from plcmotion.s7_1500 import MC_GetCamFollowingValue, MC_GetCamLeadingValue, MC_InterpolateCam

from _cam_h import HUMP, cam_rig, check_outputs_consistent, interpolate, run_fb


def fval(ctl, cam, x):
    get = MC_GetCamFollowingValue()
    tr = run_fb(ctl, get, Cam=cam, LeadingValue=x)
    check_outputs_consistent(tr)
    assert get.Done, (x, hex(get.ErrorID))
    return get.Value, get.FirstDerivative, get.SecondDerivative


# ---- §A.2.8 StatusWord, §9.2.1 timing -------------------------------------------------------------
def test_s7_1500_interpolate_done_busy_timing_and_status_bits():
    ctl, cam = cam_rig(interpolation_mode=1)
    assert cam.StatusWord.X5 is False or cam.StatusWord.X5 == 0
    fb = MC_InterpolateCam()
    tr = run_fb(ctl, fb, Cam=cam)
    check_outputs_consistent(tr)
    assert tr[0]["Busy"] and not tr[0]["Done"]
    assert fb.Done and cam.StatusWord.Interpolated and not cam.StatusWord.InInterpolation
    # Done stays TRUE while Execute stays TRUE (PLCopen convention)
    ctl.step()
    fb(Cam=cam, Execute=True)
    assert fb.Done and not fb.Busy
    fb(Cam=cam, Execute=False)
    ctl.step()
    fb(Cam=cam, Execute=False)
    assert not fb.Done


def test_s7_1500_cam_data_changed_bit_and_reinterpolation():
    ctl, cam = cam_rig(interpolation_mode=0)
    interpolate(ctl, cam)
    assert not cam.StatusWord.CamDataChanged
    cam.ValidPoint[3] = False
    assert cam.StatusWord.CamDataChanged
    cam.InterpolationSettings.InterpolationMode = 1
    assert cam.StatusWord.CamDataChanged
    interpolate(ctl, cam)
    assert not cam.StatusWord.CamDataChanged
    # point 3 (180, 100) is no longer used
    v, _, _ = fval(ctl, cam, 180.0)
    assert v < 100.0 - 1.0


def test_s7_1500_no_valid_elements_error():
    ctl, cam = cam_rig([])
    fb = MC_InterpolateCam()
    tr = run_fb(ctl, fb, Cam=cam)
    check_outputs_consistent(tr)
    assert fb.Error and fb.ErrorID != 0 and not cam.StatusWord.Interpolated


def test_s7_1500_all_points_invalid_error():
    ctl, cam = cam_rig()
    for i in range(1, 6):
        cam.ValidPoint[i] = False
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam)
    assert fb.Error and fb.ErrorID != 0


def test_s7_1500_interpolation_mode_out_of_range_rejected():
    """§A.2.6: InterpolationMode 0..2."""
    ctl, cam = cam_rig()
    try:
        cam.InterpolationSettings.InterpolationMode = 3
    except (ValueError, TypeError, Exception):
        return                                         # rejected at the tag: acceptable
    fb = MC_InterpolateCam()
    tr = run_fb(ctl, fb, Cam=cam)
    check_outputs_consistent(tr)
    assert fb.Error and fb.ErrorID != 0


def test_s7_1500_boundary_conditions_out_of_range_rejected():
    """§A.2.6: BoundaryConditions 0, 1."""
    ctl, cam = cam_rig()
    try:
        cam.InterpolationSettings.BoundaryConditions = 2
    except Exception:
        return
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam)
    assert fb.Error and fb.ErrorID != 0


def test_s7_1500_point_value_outside_tag_range_rejected():
    """§A.2.2: Point[].x/.y range -1.0E12 .. 1.0E12; a value outside it must not give an interpolated cam."""
    ctl, cam = cam_rig([(0, 0), (100, 10)])
    try:
        cam.Point[2].x = 5.0e12
    except Exception:
        return
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam)
    assert fb.Error and fb.ErrorID != 0, f"accepted: EndLeadingValue={cam.StatusCam.EndLeadingValue}"


def test_s7_1500_segment_value_outside_tag_range_rejected():
    """§A.2.4: Segment[] elements range -1.0E12 .. 1.0E12."""
    ctl, cam = cam_rig([], segments=[{"xmin": 0.0, "xmax": 100.0, "a0": 1.0}])
    try:
        cam.Segment[1].a1 = 3.0e12
    except Exception:
        return
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam)
    assert fb.Error and fb.ErrorID != 0


# ---- §5.1 / §A.2.7 definition range --------------------------------------------------------------
def test_s7_1500_definition_range_first_point_to_last_segment_end():
    ctl, cam = cam_rig([(-50, 0), (100, 20), (300, 40)],
                       segments=[{"xmin": 300.0, "xmax": 400.0, "a0": 40.0}], interpolation_mode=1)
    interpolate(ctl, cam)
    assert cam.StatusCam.StartLeadingValue == -50.0 and cam.StatusCam.EndLeadingValue == 400.0


def test_s7_1500_points_not_entered_in_ascending_order():
    """The manual does not require ascending order of entry; the range goes from the first to the last point."""
    ctl, cam = cam_rig([(360, 0), (0, 0), (180, 100), (90, 50), (270, 50)], interpolation_mode=0)
    interpolate(ctl, cam)
    assert cam.StatusCam.StartLeadingValue == 0.0 and cam.StatusCam.EndLeadingValue == 360.0
    assert fval(ctl, cam, 45.0)[0] == pytest.approx(25.0)


# ---- §6.2.5.7 boundary conditions for points and segments -------------------------------------------
def test_s7_1500_same_leading_value_last_entered_point_counts():
    ctl, cam = cam_rig([(0, 0), (90, 40), (180, 100), (360, 0), (90, 70)], interpolation_mode=0)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 90.0)[0] == pytest.approx(70.0)


def test_s7_1500_invalid_point_not_used():
    ctl, cam = cam_rig([(0, 0), (90, 40), (180, 100), (360, 0)], interpolation_mode=0)
    cam.ValidPoint[3] = False
    interpolate(ctl, cam)
    assert fval(ctl, cam, 180.0)[0] == pytest.approx(40.0 - 40.0 * 90.0 / 270.0)


def test_s7_1500_overlapping_segments_later_used_completely_earlier_resumes():
    segs = [{"xmin": 0.0, "xmax": 200.0, "a0": 10.0}, {"xmin": 50.0, "xmax": 100.0, "a0": 20.0}]
    ctl, cam = cam_rig([], segments=segs, interpolation_mode=0)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 25.0)[0] == pytest.approx(10.0)
    assert fval(ctl, cam, 75.0)[0] == pytest.approx(20.0)
    assert fval(ctl, cam, 150.0)[0] == pytest.approx(10.0)
    assert cam.StatusCam.StartLeadingValue == 0.0 and cam.StatusCam.EndLeadingValue == 200.0


def test_s7_1500_segment_wins_over_points_in_its_range():
    ctl, cam = cam_rig([(0, 0), (50, 999), (150, 0), (200, 0)],
                       segments=[{"xmin": 20.0, "xmax": 100.0, "a0": 5.0}], interpolation_mode=0)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 50.0)[0] == pytest.approx(5.0)


def test_s7_1500_segment_gap_above_1e_4_gets_transition():
    segs = [{"xmin": 0.0, "xmax": 100.0, "a0": 0.0}, {"xmin": 150.0, "xmax": 200.0, "a0": 50.0}]
    ctl, cam = cam_rig([], segments=segs, interpolation_mode=0)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 125.0)[0] == pytest.approx(25.0)


def test_s7_1500_segment_gap_below_1e_4_pulled_together():
    segs = [{"xmin": 0.0, "xmax": 100.0, "a1": 0.1}, {"xmin": 100.00005, "xmax": 200.0, "a0": 10.0}]
    ctl, cam = cam_rig([], segments=segs, interpolation_mode=1)
    interpolate(ctl, cam)
    v, d1, _ = fval(ctl, cam, 100.00003)
    assert v == pytest.approx(10.0, abs=1e-4)
    assert abs(d1) < 1.0                                  # no steep transition inserted


def test_s7_1500_segment_polynomial_and_sine_evaluated():
    """§A.2.4: y = a0 + a1 x + ... + a6 x^6 + sineAmplitude * sin(sinePeriod x + sinePhase)."""
    seg = {"xmin": 10.0, "xmax": 20.0, "a0": 1.0, "a1": 0.5, "a2": 0.01, "sineAmplitude": 2.0,
           "sinePeriod": 0.3, "sinePhase": 0.1}
    ctl, cam = cam_rig([], segments=[seg], interpolation_mode=0)
    interpolate(ctl, cam)
    x = 13.0
    v, d1, d2 = fval(ctl, cam, x)
    assert v == pytest.approx(1.0 + 0.5 * x + 0.01 * x * x + 2.0 * math.sin(0.3 * x + 0.1))
    assert d1 == pytest.approx(0.5 + 0.02 * x + 0.6 * math.cos(0.3 * x + 0.1))
    assert d2 == pytest.approx(0.02 - 0.18 * math.sin(0.3 * x + 0.1))


# ---- §5.1 interpolation types ------------------------------------------------------------------------
@pytest.mark.parametrize("mode", [0, 1])
def test_s7_1500_linear_and_cubic_pass_through_points(mode):
    ctl, cam = cam_rig(HUMP, interpolation_mode=mode)
    interpolate(ctl, cam)
    for x, y in HUMP:
        assert fval(ctl, cam, float(x))[0] == pytest.approx(y, abs=1e-9)


def test_s7_1500_cubic_spline_is_c2():
    ctl, cam = cam_rig(HUMP, interpolation_mode=1)
    interpolate(ctl, cam)
    for x in (90.0, 180.0, 270.0):
        a = fval(ctl, cam, x - 1e-7)
        b = fval(ctl, cam, x + 1e-7)
        assert a[1] == pytest.approx(b[1], abs=1e-5) and a[2] == pytest.approx(b[2], abs=1e-5)


def test_s7_1500_bezier_does_not_enlarge_value_range():
    pts = [(0, 0), (60, 100), (120, 0), (180, 100), (240, 0)]
    ctl, cam = cam_rig(pts, interpolation_mode=2)
    interpolate(ctl, cam)
    ys = [fval(ctl, cam, float(x))[0] for x in np.linspace(0, 240, 97)]
    assert min(ys) >= -1e-9 and max(ys) <= 100.0 + 1e-9
    # the curve starts and ends at the first/last point
    assert ys[0] == pytest.approx(0.0, abs=1e-9) and ys[-1] == pytest.approx(0.0, abs=1e-9)


def test_s7_1500_bezier_joins_segments():
    """§5.1: Bézier spline runs through the segments."""
    ctl, cam = cam_rig([(0, 0), (60, 80), (120, 20)],
                       segments=[{"xmin": 200.0, "xmax": 300.0, "a0": 50.0}], interpolation_mode=2)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 250.0)[0] == pytest.approx(50.0)
    v, d1, _ = fval(ctl, cam, 200.0 - 1e-6)
    assert v == pytest.approx(50.0, abs=1e-4)


@pytest.mark.parametrize("mode", [1, 2])
def test_s7_1500_boundary_conditions_equal_first_derivative_points_only(mode):
    pts = [(0, 0), (100, 30), (200, 100), (360, 10)]
    ctl, cam = cam_rig(pts, interpolation_mode=mode, boundary_conditions=1)
    interpolate(ctl, cam)
    d_start = fval(ctl, cam, 0.0)[1]
    d_end = fval(ctl, cam, 360.0)[1]
    assert d_start == pytest.approx(d_end, abs=1e-6)


@pytest.mark.parametrize("mode", [1, 2])
def test_s7_1500_boundary_conditions_with_segment_at_start(mode):
    pts = [(200, 100), (360, 20)]
    seg = {"xmin": 0.0, "xmax": 90.0, "a1": 0.5}
    ctl, cam = cam_rig(pts, segments=[seg], interpolation_mode=mode, boundary_conditions=1)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 0.0)[1] == pytest.approx(0.5)
    assert fval(ctl, cam, 360.0)[1] == pytest.approx(0.5, abs=1e-6)


@pytest.mark.parametrize("mode", [1, 2])
def test_s7_1500_boundary_conditions_zero_no_condition(mode):
    pts = [(0, 0), (100, 30), (200, 100), (360, 10)]
    ctl, cam = cam_rig(pts, interpolation_mode=mode, boundary_conditions=0)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 0.0)[1] != pytest.approx(fval(ctl, cam, 360.0)[1], abs=1e-3)


# ---- §9.2.3 MC_GetCamFollowingValue --------------------------------------------------------------
def test_s7_1500_get_following_value_not_interpolated_error():
    ctl, cam = cam_rig()
    get = MC_GetCamFollowingValue()
    tr = run_fb(ctl, get, Cam=cam, LeadingValue=10.0)
    check_outputs_consistent(tr)
    assert get.Error and get.ErrorID != 0


def test_s7_1500_get_following_value_at_definition_range_ends():
    ctl, cam = cam_rig(interpolation_mode=1)
    interpolate(ctl, cam)
    assert fval(ctl, cam, 0.0)[0] == pytest.approx(0.0, abs=1e-12)
    assert fval(ctl, cam, 360.0)[0] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("x", [-0.001, 360.001, 1e6])
def test_s7_1500_get_following_value_outside_range_error(x):
    ctl, cam = cam_rig(interpolation_mode=1)
    interpolate(ctl, cam)
    get = MC_GetCamFollowingValue()
    tr = run_fb(ctl, get, Cam=cam, LeadingValue=x)
    check_outputs_consistent(tr)
    assert get.Error and get.ErrorID != 0 and not get.Done


def test_s7_1500_get_following_value_derivatives_cubic_numeric():
    ctl, cam = cam_rig(interpolation_mode=1)
    interpolate(ctl, cam)
    h = 1e-3
    v0, d1, d2 = fval(ctl, cam, 130.0)
    vp = fval(ctl, cam, 130.0 + h)[0]
    vm = fval(ctl, cam, 130.0 - h)[0]
    assert d1 == pytest.approx((vp - vm) / (2 * h), rel=1e-5)
    assert d2 == pytest.approx((vp - 2 * v0 + vm) / (h * h), rel=1e-3)


# ---- §9.2.2 MC_GetCamLeadingValue ----------------------------------------------------------------
@pytest.mark.parametrize("approach,expected", [(0.0, 45.0), (100.0, 45.0), (250.0, 315.0), (1000.0, 315.0)])
def test_s7_1500_get_leading_value_non_monotonic_approach(approach, expected):
    ctl, cam = cam_rig([(0, 0), (180, 100), (360, 0)], interpolation_mode=0)
    interpolate(ctl, cam)
    get = MC_GetCamLeadingValue()
    tr = run_fb(ctl, get, Cam=cam, FollowingValue=25.0, ApproachLeadingValue=approach)
    check_outputs_consistent(tr)
    assert get.Done and get.Value == pytest.approx(expected)


def test_s7_1500_get_leading_value_not_taken_error():
    ctl, cam = cam_rig([(0, 0), (180, 100), (360, 0)], interpolation_mode=0)
    interpolate(ctl, cam)
    get = MC_GetCamLeadingValue()
    tr = run_fb(ctl, get, Cam=cam, FollowingValue=-5.0)
    check_outputs_consistent(tr)
    assert get.Error and get.ErrorID != 0


def test_s7_1500_get_leading_value_not_interpolated_error():
    ctl, cam = cam_rig()
    get = MC_GetCamLeadingValue()
    run_fb(ctl, get, Cam=cam, FollowingValue=5.0)
    assert get.Error and get.ErrorID != 0


def test_s7_1500_get_leading_value_spline_roundtrip():
    ctl, cam = cam_rig(interpolation_mode=1)
    interpolate(ctl, cam)
    y = fval(ctl, cam, 123.0)[0]
    get = MC_GetCamLeadingValue()
    run_fb(ctl, get, Cam=cam, FollowingValue=y, ApproachLeadingValue=100.0)
    assert get.Done and get.Value == pytest.approx(123.0, abs=1e-6)
