"""Cam technology object robustness (issue 8, defect 3): MC_InterpolateCam never stops the controller on
points the manual admits (S7-1500T V5 §9.2.1, §A.2: Point[] values -1.0E12 .. 1.0E12), and the cam TO's
jobs given in the same application cycle as MC_Reset(Restart) or another cam job end properly."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_CamIn, MC_GetCamFollowingValue, MC_GetCamLeadingValue, MC_InterpolateCam,
                               MC_MoveVelocity, MC_Reset)
from plcmotion.s7_1500 import errors as E

from _s7_1500_rig import Rig

POINTS = [(150, -3.9), (220, 87), (290, -95.2)]


def _interpolate(points, mode, boundary):
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam", points=points, interpolation_mode=mode, boundary_conditions=boundary)
    ic = MC_InterpolateCam()

    @ctl.program
    def main():
        ic(Cam=cam, Execute=True)
    ctl.run(0.02)
    assert ctl.mode == "RUN", ctl.stop_reason
    return ic, cam


def test_s7_1500_three_point_periodic_cubic_spline_interpolates_defect3a():
    """Defect 3a: scipy's periodic check failed on the rounding of the detrended end value and the
    controller went to STOP.  The cam interpolates; BoundaryConditions 1 (cubic spline): equal first
    and second derivative at start and end (§6.2.5.7 "for cyclic use")."""
    ic, cam = _interpolate(POINTS, 1, 1)
    assert ic.Done and not ic.Error
    c = cam.curve
    y0, d0, dd0 = (float(v[0]) for v in c.evaluate(np.array([150.0])))
    y1, d1, dd1 = (float(v[0]) for v in c.evaluate(np.array([290.0])))
    assert (y0, y1) == (pytest.approx(-3.9), pytest.approx(-95.2))
    assert d1 == pytest.approx(d0, rel=1e-9, abs=1e-9) and dd1 == pytest.approx(dd0, rel=1e-9, abs=1e-9)
    assert float(c.value(220.0)) == pytest.approx(87.0)


@pytest.mark.parametrize("points", [POINTS, [(0, 0), (100, 50), (200, 30), (300, 100)],
                                    [(-50, 3), (0, -2), (10, 8), (70, 1), (80, 40)]])
def test_s7_1500_cubic_spline_with_boundary_conditions_passes_through_its_points_s6_2_5_7(points):
    """Found with defect 3a: with BoundaryConditions 1 a cubic spline cam whose end value differs from
    its start value missed all its interpolation points but the first (the linear trend taken out for
    the periodic spline was put back into the slopes only).  A cubic spline runs through the points."""
    ic, cam = _interpolate(points, 1, 1)
    assert ic.Done
    for x, y in points:
        assert float(cam.curve.value(float(x))) == pytest.approx(y, abs=1e-9)


_coord = st.one_of(st.floats(-1e12, 1e12, allow_nan=False), st.floats(-1e3, 1e3, allow_nan=False),
                   st.integers(-5, 5).map(float))


@settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck))
@given(points=st.lists(st.tuples(_coord, _coord), min_size=2, max_size=6), mode=st.sampled_from([0, 1, 2]),
       boundary=st.sampled_from([0, 1]))
def test_s7_1500_any_admitted_points_interpolate_or_give_the_errorid_defect3a(points, mode, boundary):
    """Any points within the tag ranges (§A.2): Done with a finite curve, or Error with the cam's
    ErrorID - never a controller STOP."""
    ic, cam = _interpolate(points, mode, boundary)
    assert ic.Done or (ic.Error and ic.ErrorID == E.CAM_DEFINITION), hex(ic.ErrorID)
    if ic.Done:
        c = cam.curve
        for v in c.evaluate(np.linspace(c.start, c.end, 97)):
            assert np.isfinite(v).all()


def _cam_rig():
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam", points=[(0, 0), (100, 10), (200, 0)], interpolation_mode=1)
    fbs = dict(ic=MC_InterpolateCam(), gf=MC_GetCamFollowingValue(), gl=MC_GetCamLeadingValue(), rs=MC_Reset())
    go = {k: False for k in fbs}
    go["ic"] = True
    order = list(fbs)

    @ctl.program
    def main():
        for k in order:
            fb = fbs[k]
            if k == "ic":
                fb(Cam=cam, Execute=go[k])
            elif k == "gf":
                fb(Cam=cam, Execute=go[k], LeadingValue=50.0)
            elif k == "gl":
                fb(Cam=cam, Execute=go[k], FollowingValue=5.0, ApproachLeadingValue=40.0)
            else:
                fb(Axis=cam, Execute=go[k], Restart=True)
    ctl.run(0.02)
    assert fbs["ic"].Done
    go["ic"] = False
    ctl.run(0.01)
    return ctl, cam, fbs, go, order


def _outputs_ok(fb):
    assert sum(bool(getattr(fb, k)) for k in ("Done", "Busy", "Error")) <= 1
    assert not (fb.Error and fb.ErrorID == 0)


def test_s7_1500_get_cam_following_value_and_restart_in_the_same_cycle_defect3b():
    """Defect 3b: MC_GetCamFollowingValue(Execute) and MC_Reset(Restart) on the cam in the same cycle
    stopped the controller (assertion).  The job given before the restart finds the cam restarted - not
    interpolated - and ends with that ErrorID; the restart is done."""
    ctl, cam, fbs, go, _ = _cam_rig()
    go["gf"] = go["rs"] = True
    ctl.run(0.02)
    assert ctl.mode == "RUN", ctl.stop_reason
    assert fbs["rs"].Done
    assert fbs["gf"].Error and fbs["gf"].ErrorID == E.NO_FOLLOWING_VALUE
    assert not cam.StatusWord.X5                         # not interpolated after the restart


SAME_CYCLE = [("gf", "rs"), ("rs", "gf"), ("gl", "rs"), ("rs", "gl"), ("ic", "rs"), ("rs", "ic"), ("gl", "ic"),
              ("ic", "gl"), ("gf", "ic"), ("ic", "gf"), ("ic", "gf", "gl", "rs"), ("rs", "gl", "gf", "ic")]


@pytest.mark.parametrize("combo", SAME_CYCLE, ids=["+".join(c) for c in SAME_CYCLE])
def test_s7_1500_cam_jobs_in_the_same_cycle_never_stop_the_controller_defect3b(combo):
    """Audit of the cam TO's job handling: any cam instructions started in the same application cycle
    (in either call order) end with Done or Error with an ErrorID, the controller stays in RUN."""
    ctl, cam, fbs, go, order = _cam_rig()
    order[:] = list(combo) + [k for k in order if k not in combo]
    for k in combo:
        go[k] = True
    for _ in range(10):
        ctl.step()
        for fb in fbs.values():
            _outputs_ok(fb)
    assert ctl.mode == "RUN", ctl.stop_reason
    for k in combo:
        assert fbs[k].Done or fbs[k].Error, k
    if "rs" in combo and "ic" in combo:
        if combo.index("rs") < combo.index("ic"):
            assert fbs["rs"].Done and fbs["ic"].Done and cam.StatusWord.X5     # restarted, then interpolated
        else:
            # an interpolation is in progress (StatusWord.X6 InInterpolation): the restart is refused
            assert fbs["ic"].Done and fbs["rs"].Error and fbs["rs"].ErrorID == E.RESTART_IMPOSSIBLE
    if "gf" in combo and fbs["gf"].Done:
        assert fbs["gf"].Value == pytest.approx(float(cam.curve.value(50.0)))


def test_s7_1500_interpolate_and_cam_in_in_the_same_cycle_s9_2_1():
    """MC_CamIn takes the cam into use: an MC_InterpolateCam given in the same cycle after it is
    rejected (16#80AB); given before it, the interpolation finds the cam in use when it runs."""
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", points=[(0, 0), (100, 10), (200, 0)], interpolation_mode=1)
    ic0, ic, ci, mv = MC_InterpolateCam(), MC_InterpolateCam(), MC_CamIn(), MC_MoveVelocity()
    go = {"now": False}
    rig.steps.append(lambda: ic0(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=ic0.Done, Velocity=10.0))
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=go["now"],
                                SyncProfileReference=2, ApplicationMode=1))
    rig.steps.append(lambda: ic(Cam=cam, Execute=go["now"]))
    rig.run_until(lambda: ic0.Done and rig.enabled(), timeout=1.0)
    go["now"] = True
    rig.run(0.05)
    assert rig.ctl.mode == "RUN"
    assert ci.InSync and ic.Error and ic.ErrorID == E.CAM_IN_USE
    assert math.isfinite(rig.slave.Position)
