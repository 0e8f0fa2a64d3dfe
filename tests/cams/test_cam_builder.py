"""Offline cam builder (S7-1500T V5 §6.2.5.7–§6.2.5.15) and the VDI 2143 motion laws of transitions.

Values are checked against closed forms; continuity at joins is read from the interpolated curve's
pieces on both sides of the join, so it covers the conversion to absolute-x segment coefficients.
"""
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.cams import (
    SEGMENT_FIELDS,
    CamBuilder,
    CamCapacityError,
    CamCoefficientError,
    CamDefinition,
    UnsupportedTransitionError,
    vdi,
)
from plcmotion.kernel.cam import (
    CUBIC_SPLINE,
    LINEAR,
    MAX_POINTS,
    MAX_SEGMENTS,
    interpolate,
)
from plcmotion.s7_1500.technology.cam_to import SEGMENT_FIELDS as TO_SEGMENT_FIELDS

PI = math.pi
INF = math.inf


# ------------------------------------------------------------------------------------------------------
# helpers
def ev(curve, x):
    """(f, f', f'', f''') at x (the piece to the right of a breakpoint)."""
    return [float(v[0]) for v in curve.evaluate(np.array([float(x)]), 3)]


def piece_derivs(curve, k, x):
    """f..f''' of piece k of the curve at x, also outside its own range (for one-sided limits)."""
    dx = x - curve.bp[k]
    c = curve.c[k].copy()
    out = []
    for order in range(4):
        p = np.polynomial.polynomial.polyval(dx, c)
        w = curve.sin_freq[k]
        out.append(p + curve.sin_amp[k] * w ** order * math.sin(w * dx + curve.sin_phase[k] + order * PI / 2))
        c = np.polynomial.polynomial.polyder(c)
    return out


def assert_join(curve, x, order, scale_y, scale_x, rel=1e-7):
    """Derivatives 0..order equal on both sides of the breakpoint x."""
    k = int(np.argmin(np.abs(curve.bp - x)))
    assert abs(curve.bp[k] - x) < 1e-9 * max(1.0, abs(x)), f"no breakpoint at {x}"
    left, right = piece_derivs(curve, k - 1, x), piece_derivs(curve, k, x)
    for d in range(order + 1):
        tol = rel * scale_y / scale_x ** d
        assert left[d] == pytest.approx(right[d], abs=tol), f"derivative {d} jumps at x={x}: {left[d]} / {right[d]}"


def dwell_dwell(law, y0=10.0, y1=70.0, continuity=None, lam=None):
    """Dwell on [0, 100] at y0, VDI transition, dwell on [160, 260] at y1."""
    b = CamBuilder(LINEAR)
    b.line(0, 100, y0=y0, slope=0).transition("vdi", law, continuity=continuity, lam=lam)
    b.line(160, 260, y0=y1, slope=0)
    return b.build()


# ------------------------------------------------------------------------------------------------------
# VDI 2143 laws (§6.2.5.15: characteristic values Cv, Ca, Cj)
CHARACTERISTICS = [
    # law, Cv, Ca, Cj, tolerance (closed forms exact; literature values to their printed digits)
    ("quadratic_parabola", 2.0, 4.0, INF, 1e-9),
    ("simple_sine", PI / 2, PI ** 2 / 2, INF, 1e-9),
    ("inclined_sine", 2.0, 2 * PI, 4 * PI ** 2, 1e-9),
    ("polynomial5", 1.875, 10 / math.sqrt(3), 60.0, 1e-9),
    ("polynomial7", 35 / 16, 7.5132, 52.5, 1e-4),
    ("modified_trapezoid", 2.0, 2 / (0.25 + 1 / (2 * PI)), 4 * PI * 2 / (0.25 + 1 / (2 * PI)), 1e-9),
    ("modified_sine", 1.7596, 5.5280, 69.47, 2e-4),
]


@pytest.mark.parametrize("name,cv,ca,cj,rel", CHARACTERISTICS)
def test_cams_vdi_characteristic_values_s6_2_5_15(name, cv, ca, cj, rel):
    c = vdi.law(name).characteristics()
    assert c.cv == pytest.approx(cv, rel=rel)
    assert c.ca == pytest.approx(ca, rel=rel)
    assert c.ca_star == pytest.approx(ca, rel=rel)             # dwell-in-dwell laws are point-symmetric
    assert c.cj == pytest.approx(cj, rel=rel) if math.isfinite(cj) else c.cj == INF


def test_cams_modified_trapezoid_and_modified_sine_jerk_is_4_pi_ca_s6_2_5_15():
    for name in ("modified_trapezoid", "modified_sine"):
        c = vdi.law(name).characteristics()
        assert c.cj == pytest.approx(4 * PI * c.ca, rel=1e-9)


ALL_LAWS = ["line", "quadratic_parabola", "simple_sine", "inclined_sine", "polynomial5", "polynomial7",
            "modified_trapezoid", "modified_sine", "harmonic_combination", "sine_line", "double_harmonic"]


@pytest.mark.parametrize("name", ALL_LAWS)
def test_cams_vdi_law_is_normalized_and_its_derivatives_are_consistent_s6_2_5_15(name):
    law = vdi.law(name)
    z = np.linspace(0.0, 1.0, 40001)
    s, v, a, j = law.evaluate(z)
    assert s[0] == pytest.approx(0.0, abs=1e-12) and s[-1] == pytest.approx(1.0, abs=1e-12)
    h = z[1] - z[0]
    # acceleration of the parabola and jerk of most laws jump at piece joins: compare away from joins
    far = np.ones_like(z, dtype=bool)
    for p in law.pieces[1:]:
        far &= np.abs(z - p.t0) > 3 * h
    inner = slice(2, -2)
    assert np.abs(np.gradient(s, h) - v)[inner][far[inner]].max() < 1e-6
    assert np.abs(np.gradient(v, h) - a)[inner][far[inner]].max() < 1e-4
    assert np.abs(np.gradient(a, h) - j)[inner][far[inner]].max() < 1e-3
    assert law.task in {"RR", "GG", "RU"}


def test_cams_vdi_harmonic_combination_is_jerk_continuous_at_lambda_and_ends_in_a_reversal_s6_2_5_15():
    law = vdi.harmonic_combination()
    assert law.task == "RU" and law.lam == pytest.approx(2 - math.sqrt(2))
    first, second = law.pieces
    for k in range(4):
        assert float(first.derivatives(law.lam, 3)[k]) == pytest.approx(float(second.derivatives(law.lam, 3)[k]))
    s, v, a, _ = law.boundary(1)
    assert s == pytest.approx(1.0) and v == pytest.approx(0.0, abs=1e-12) and a < -PI ** 2 / 4
    mirrored = vdi.harmonic_combination(mirrored=True)
    assert mirrored.task == "UR"
    z = np.linspace(0, 1, 11)
    assert mirrored.s(z) == pytest.approx(1 - law.s(1 - z), abs=1e-12)


# ------------------------------------------------------------------------------------------------------
# VDI transitions in a cam (§6.2.5.15; segments used: §6.2.5.7)
RR_SEGMENTS = {"quadratic_parabola": 2, "simple_sine": 1, "inclined_sine": 1, "polynomial": 1, "polynomial7": 2,
               "modified_trapezoid": 5, "modified_sine": 3, "sine_line": 3}


@pytest.mark.parametrize("name", sorted(RR_SEGMENTS))
def test_cams_vdi_dwell_in_dwell_transition_follows_the_law_and_is_continuous_s6_2_5_15(name):
    d = dwell_dwell(name)
    info = d.transitions[0]
    assert info.task == "RR" and info.segments == RR_SEGMENTS[name]
    assert d.statistics()["segments"] == 2 + RR_SEGMENTS[name]
    curve = d.curve()
    law = vdi.law(name)
    z = np.linspace(0, 1, 61)
    tol = 6e-4 * 60 if name == "polynomial7" else 1e-7 * 60        # 7th degree: two degree-6 segments
    assert curve.value(100 + 60 * z) == pytest.approx(10 + 60 * law.s(z), abs=tol)
    order = vdi.DEFAULT_CONTINUITY[vdi.canonical(name)]
    for x in (100.0, 160.0):
        assert_join(curve, x, order, 60.0, 60.0)
    if name != "polynomial7":
        want, got = law.characteristics(), info.characteristics
        assert (got.cv, got.ca) == pytest.approx((want.cv, want.ca), rel=1e-7)


def test_cams_vdi_7th_degree_polynomial_uses_two_segments_continuous_to_the_jerk_s6_2_5_7():
    d = dwell_dwell("polynomial7")
    curve = d.curve()
    for x in (100.0, 130.0, 160.0):                                 # both ends and the split
        assert_join(curve, x, 3, 60.0, 60.0, rel=1e-6)
    c = d.transitions[0].characteristics
    assert c.cv == pytest.approx(35 / 16, rel=0.01) and c.cj < 60


def test_cams_vdi_falling_transition_and_lambda_of_the_quadratic_parabola_s6_2_5_15():
    d = dwell_dwell("quadratic_parabola", y0=50, y1=20, lam=0.25)
    curve = d.curve()
    assert ev(curve, 115.0)[0] == pytest.approx(50 - 30 * 0.25, rel=1e-9)   # switch at lambda: s(lambda) = lambda
    assert_join(curve, 115.0, 1, 30, 60)
    assert d.transitions[0].lam == 0.25


def test_cams_vdi_simple_and_inclined_sine_between_equal_constant_velocities_g_g_s6_2_5_15():
    for name, order in (("simple_sine", 1), ("inclined_sine", 2)):
        b = CamBuilder().line(0, 100, y0=0, slope=1.0).transition("vdi", name).line(160, 260, y0=200, slope=1.0)
        d = b.build()
        assert d.transitions[0].task == "GG"
        curve = d.curve()
        for x in (100.0, 160.0):
            assert_join(curve, x, order, 100, 60)
        seg = d.segments[1]
        assert seg.sine_amplitude != 0 and seg.a[2:] == (0.0,) * 5     # a0 + a1 x + A sin(b1 x + b2)


def test_cams_vdi_sine_line_combination_dwell_into_constant_velocity_s6_2_5_15():
    b = CamBuilder().line(0, 100, y0=0, slope=0).transition("vdi", "sine_line").line(160, 200, y0=60, slope=1.5)
    d = b.build()
    info = d.transitions[0]
    assert info.task == "RG" and info.segments == 2 and info.lam == pytest.approx(2 - 2 / 1.5)
    for x in (100.0, 160.0):
        assert_join(d.curve(), x, 2, 60, 60)


def test_cams_vdi_harmonic_combination_dwell_into_reversal_matches_its_acceleration_s6_2_5_15():
    right = {"y0": 60, "y1": 0, "v0": 0.0, "a0": -0.2, "v1": 0.0, "a1": 0.0}         # starts in a reversal (U)
    b = CamBuilder().line(0, 100, y0=0, slope=0).transition("vdi", "harmonic_combination")
    d = b.polynomial(160, 260, **right).build()
    assert d.transitions[0].task == "RU"
    for x in (100.0, 160.0):
        assert_join(d.curve(), x, 2, 60, 60)
    # reverse-in-dwell: the mirrored law
    b = CamBuilder().polynomial(0, 100, y0=60, y1=0, v0=0, a0=0, v1=0, a1=0.2)
    d = b.transition("vdi", "harmonic_combination").line(160, 200, y0=60, slope=0).build()
    assert d.transitions[0].task == "UR"
    for x in (100.0, 160.0):
        assert_join(d.curve(), x, 2, 60, 60)


def test_cams_vdi_law_outside_its_motion_task_is_refused_with_a_hint_s6_2_5_15():
    b = CamBuilder().line(0, 100, y0=0, slope=1.0).transition("vdi", "inclined_sine").line(160, 200, y0=150, slope=0)
    with pytest.raises(UnsupportedTransitionError, match=r"transition #2 .*G-R.*'polynomial'"):
        b.build()
    with pytest.raises(UnsupportedTransitionError, match="acceleration continuity"):
        dwell_dwell("harmonic_combination")
    # with velocity continuity at the reversal side the dwell-in-dwell case is accepted
    d = dwell_dwell("harmonic_combination", continuity=("acceleration", "velocity"))
    assert_join(d.curve(), 160.0, 1, 60, 60)


def test_cams_vdi_line_law_and_double_harmonic_points_s6_2_5_7():
    d = CamBuilder().line(0, 100, y0=0, slope=1).transition("vdi", "line").line(150, 200, y0=150, slope=1).build()
    assert d.transitions[0].task == "GG"
    assert_join(d.curve(), 100.0, 2, 50, 50)
    b = CamBuilder(LINEAR).point(0, 0).transition("vdi", "double_harmonic", n_points=32).point(90, 45)
    d = b.build()
    assert d.statistics()["points"] == 32 and d.statistics()["segments"] == 0   # the two points are absorbed
    law = vdi.law("double_harmonic")
    xs = np.array([p[0] for p in d.points])
    assert np.array([p[1] for p in d.points]) == pytest.approx(45 * law.s(xs / 90), abs=1e-12)


# all 16 combinations of the motion tasks at the two ends (§6.2.5.15 table) with polynomial transitions
STATES = {"R": (0.0, 0.0), "G": (0.8, 0.0), "U": (0.0, -0.02), "B": (0.5, 0.015)}


@pytest.mark.parametrize("start", "RGUB")
@pytest.mark.parametrize("end", "RGUB")
def test_cams_vdi_polynomial_transition_for_every_motion_task_s6_2_5_15(start, end):
    (va, aa), (vb, ab) = STATES[start], STATES[end]
    b = CamBuilder()
    b.polynomial(0, 100, y0=0, y1=40, v0=0.2, a0=0.0, v1=va, a1=aa)
    b.transition("vdi", "polynomial")
    b.polynomial(160, 260, y0=90, y1=120, v0=vb, a0=ab, v1=0.0, a1=0.0)
    b.transition("vdi", "polynomial", continuity="jerk")                    # 7th degree: 2 segments
    b.polynomial(300, 400, y0=100, y1=40, v0=-0.4, a0=0.01, j0=0.0, v1=0.0, a1=0.0)
    d = b.build()
    assert d.transitions[0].task == start + end
    assert d.statistics()["segments"] == 1 + 1 + 1 + 2 + 1
    curve = d.curve()
    for x in (100.0, 160.0):
        assert_join(curve, x, 2, 100, 60, rel=1e-6)
    for x in (260.0, 300.0):
        assert_join(curve, x, 3, 100, 40, rel=1e-6)


@settings(max_examples=40, deadline=None)
@given(y0=st.floats(-500, 500), rise=st.floats(0.5, 400) | st.floats(-400, -0.5), x0=st.floats(0, 720),
       width=st.floats(5, 200), law=st.sampled_from(["quadratic_parabola", "simple_sine", "inclined_sine",
                                                     "polynomial", "modified_trapezoid", "modified_sine",
                                                     "sine_line"]))
def test_cams_property_vdi_dwell_transition_hits_both_levels_and_is_monotonic_s6_2_5_15(y0, rise, x0, width, law):
    y1 = y0 + rise
    b = CamBuilder(LINEAR).line(x0, x0 + 10, y0=y0, slope=0).transition("vdi", law)
    d = b.line(x0 + 10 + width, x0 + 20 + width, y0=y1, slope=0).build()
    curve = d.curve()
    xa, xb = x0 + 10, x0 + 10 + width
    scale = max(1.0, abs(y0), abs(y1))
    assert ev(curve, xa)[0] == pytest.approx(y0, abs=1e-8 * scale)
    assert ev(curve, xb)[0] == pytest.approx(y1, abs=1e-8 * scale)
    ys = curve.value(np.linspace(xa, xb, 400))
    steps = np.diff(ys) * math.copysign(1.0, rise)
    assert steps.min() >= -1e-8 * scale


@settings(max_examples=40, deadline=None)
@given(va=st.floats(-2, 2), aa=st.floats(-0.1, 0.1), vb=st.floats(-2, 2), ab=st.floats(-0.1, 0.1),
       yb=st.floats(-100, 100), width=st.floats(10, 100))
def test_cams_property_polynomial_transition_is_c2_between_any_states_s6_2_5_15(va, aa, vb, ab, yb, width):
    b = CamBuilder().polynomial(0, 50, y0=0, y1=10, v0=0, a0=0, v1=va, a1=aa).transition("vdi")
    d = b.polynomial(50 + width, 100 + width, y0=yb, y1=0, v0=vb, a0=ab, v1=0, a1=0).build()
    curve = d.curve()
    for x in (50.0, 50.0 + width):
        assert_join(curve, x, 2, max(10.0, abs(yb), 2 * width), width, rel=1e-6)


# ------------------------------------------------------------------------------------------------------
# elements (§6.2.5.9–§6.2.5.14)
def test_cams_point_and_point_group_absolute_and_relative_s6_2_5_9_s6_2_5_10():
    b = CamBuilder(LINEAR).point(0, 5)
    b.point_group([(0, 0), (0.5, 1), (1, 0.5)], relative=True, x_range=(100, 200), y_range=(10, 30))
    b.point_group([(0.0, 7.0), (1.0, 8.0)], relative="x", x_range=(300, 400))
    d = b.build()
    assert d.points == [(0.0, 5.0), (100.0, 10.0), (150.0, 30.0), (200.0, 20.0), (300.0, 7.0), (400.0, 8.0)]
    curve = d.curve()
    assert curve.value(125.0) == pytest.approx(20.0) and curve.value(350.0) == pytest.approx(7.5)
    assert d.statistics()["elements"][1]["points"] == 3
    with pytest.raises(ValueError, match="y_range"):
        CamBuilder().point_group([(0, 0), (1, 1)], relative=True, x_range=(0, 1))
    with pytest.raises(ValueError, match="within 0..1"):
        CamBuilder().point_group([(0, 0), (1.5, 1)], relative="x", x_range=(0, 1))


def test_cams_line_by_values_or_slope_s6_2_5_11():
    for kw in ({"y0": 2, "y1": 12}, {"y0": 2, "slope": 0.5}, {"slope": 0.5, "y1": 12}):
        d = CamBuilder().line(10, 30, **kw).build()
        y, v, a, j = ev(d.curve(), 25.0)
        assert (y, v, a, j) == pytest.approx((9.5, 0.5, 0.0, 0.0))
    with pytest.raises(ValueError, match="exactly two"):
        CamBuilder().line(0, 1, y0=0, y1=1, slope=1)


@pytest.mark.parametrize("definition", [
    {"phase0": 0.3, "phase1": 0.3 + 3 * PI}, {"phase0": 0.3, "period": 40 / 1.5}, {"phase0": 0.3, "frequency": 1.5 / 40},
    {"period": 40 / 1.5, "phase1": 0.3 + 3 * PI}, {"frequency": 1.5 / 40, "phase1": 0.3 + 3 * PI}])
def test_cams_sine_definitions_give_the_same_segment_s6_2_5_12(definition):
    d = CamBuilder().sine(200, 240, amplitude=4.0, offset=10.0, **definition).build()
    b1 = 3 * PI / 40
    for x in (200.0, 213.0, 240.0):
        y, v, a, j = ev(d.curve(), x)
        arg = 0.3 + b1 * (x - 200)
        assert y == pytest.approx(10 + 4 * math.sin(arg), abs=1e-9)
        assert v == pytest.approx(4 * b1 * math.cos(arg), abs=1e-9)
        assert a == pytest.approx(-4 * b1 ** 2 * math.sin(arg), abs=1e-9)
        assert j == pytest.approx(-4 * b1 ** 3 * math.cos(arg), abs=1e-9)
    seg = d.segments[0]
    assert seg.sine_period == pytest.approx(b1) and seg.a[1:] == (0.0,) * 6


@pytest.mark.parametrize("incl", [{"offset0": 1.0, "offset1": 9.0}, {"offset0": 1.0, "inclination": 0.2},
                                  {"inclination": 0.2, "offset1": 9.0}])
def test_cams_inclined_sine_definitions_s6_2_5_12(incl):
    d = CamBuilder().sine(0, 40, amplitude=2.0, phase0=0, phase1=2 * PI, inclined=True, **incl).build()
    for x in (0.0, 10.0, 33.0, 40.0):
        assert d.curve().value(x) == pytest.approx(1 + 0.2 * x + 2 * math.sin(2 * PI * x / 40), abs=1e-9)
    with pytest.raises(ValueError, match="two of offset0"):
        CamBuilder().sine(0, 40, amplitude=1, phase0=0, period=10, inclined=True, offset0=1)
    with pytest.raises(ValueError, match="two of phase0"):
        CamBuilder().sine(0, 40, amplitude=1, phase0=0, phase1=1, period=10)


def test_cams_polynomial_from_coefficients_in_its_own_leading_value_s6_2_5_13():
    c = [1.0, 0.5, 0.01, -1e-4, 2e-6, 0.0, 1e-10]
    d = CamBuilder().polynomial(100, 150, coefficients=c, trig=(0.5, 0.2, 0.1)).build()
    for x in (100.0, 120.0, 150.0):
        u = x - 100
        want = sum(ck * u ** k for k, ck in enumerate(c)) + 0.5 * math.sin(0.2 * u + 0.1)
        assert d.curve().value(x) == pytest.approx(want, rel=1e-9)
    with pytest.raises(ValueError, match="at most 7"):
        CamBuilder().polynomial(0, 1, coefficients=[0.0] * 8)


@pytest.mark.parametrize("given,segments", [
    ({"y0": 1, "y1": 5}, 1), ({"y0": 1, "y1": 5, "v0": 0.5, "v1": -0.2}, 1),
    ({"y0": 1, "y1": 5, "v0": 0.5, "v1": -0.2, "a0": 0.05, "a1": 0.0}, 1),
    ({"y0": 1, "y1": 5, "v0": 0.5, "v1": -0.2, "a0": 0.05, "a1": 0.0, "j0": 0.01}, 1),
    ({"y0": 1, "y1": 5, "v0": 0.5, "v1": -0.2, "a0": 0.05, "a1": 0.0, "j0": 0.01, "j1": -0.002}, 2)])
def test_cams_polynomial_from_boundary_values_s6_2_5_13(given, segments):
    d = CamBuilder().polynomial(20, 40, **given).build()
    assert len(d.segments) == segments
    curve = d.curve()
    for side, x in ((0, 20.0), (1, 40.0)):
        got = ev(curve, x) if side == 0 else piece_derivs(curve, curve.pieces - 1, x)
        for k, name in enumerate("yvaj"):
            value = given.get(f"{name}{side}")
            if value is not None:
                assert got[k] == pytest.approx(value, abs=1e-9 * 20 ** -k * 10)
    if segments == 2:
        assert_join(curve, 30.0, 3, 5, 20, rel=1e-6)


def test_cams_polynomial_boundary_values_with_trigonometric_part_s6_2_5_13():
    d = CamBuilder().polynomial(0, 10, y0=0, y1=3, v0=0, v1=0, trig=(0.5, 1.0, 0.0)).build()
    curve = d.curve()
    assert ev(curve, 0.0)[:2] == pytest.approx([0.0, 0.0], abs=1e-12)
    assert piece_derivs(curve, 0, 10.0)[:2] == pytest.approx([3.0, 0.0], abs=1e-9)
    assert d.segments[0].sine_amplitude == 0.5


def test_cams_inverse_sine_points_and_mirroring_s6_2_5_14():
    d = CamBuilder(LINEAR).inverse_sine(0, 100, 10, 30, n_points=5).build()
    assert len(d.points) == 5
    for (x, y), t in zip(d.points, np.linspace(-1, 1, 5)):
        assert y == pytest.approx(10 + 20 * (math.asin(t) + PI / 2) / PI)
    m = CamBuilder().inverse_sine(0, 100, 10, 30, mirrored=True, t_start=-0.5, t_end=0.5, n_points=3).build()
    assert [p[1] for p in m.points] == pytest.approx([30, 20, 10])
    # right of a VDI transition the inverse sine gives up its first point (§6.2.5.7): N - 1
    b = CamBuilder().line(-100, -50, y0=10, slope=0).transition("vdi")
    d = b.inverse_sine(0, 100, 10, 30, t_start=-0.9, t_end=0.9).build()
    assert d.statistics()["points"] == 31
    with pytest.raises(ValueError, match="infinite slope"):
        CamBuilder().line(-100, -50, y0=10, slope=0).transition("vdi").inverse_sine(0, 100, 10, 30).build()


def test_cams_statistics_points_and_segments_per_element_s6_2_5_7():
    b = CamBuilder().point(0, 0).point(10, 1).point_group([(20, 0), (30, 1), (40, 0)])
    b.line(50, 60, y0=0, slope=0).transition("vdi", "modified_sine").line(80, 90, y0=1, slope=0)
    b.sine(100, 120, 1, phase0=0, period=20)
    b.transition("system").polynomial(150, 200, y0=0, y1=1, v0=0, v1=0, a0=0, a1=0, j0=0, j1=0)
    b.inverse_sine(210, 260, 0, 1, n_points=12)
    stats = b.build().statistics()
    per = [(r["element"], r["points"], r["segments"]) for r in stats["elements"]]
    assert per == [("point #1", 1, 0), ("point #2", 1, 0), ("point_group #3", 3, 0), ("line #4", 0, 1),
                   ("transition #5", 0, 3), ("line #6", 0, 1), ("sine #7", 0, 1), ("transition #8", 0, 0),
                   ("polynomial #9", 0, 2), ("inverse_sine #10", 12, 0)]
    assert (stats["points"], stats["segments"]) == (17, 8)
    assert (stats["max_points"], stats["max_segments"]) == (MAX_POINTS, MAX_SEGMENTS)


# ------------------------------------------------------------------------------------------------------
# limits and errors
def test_cams_capacity_error_names_the_element_that_exceeds_50_segments_s6_2_5_7():
    b = CamBuilder()
    for i in range(50):
        b.line(i, i + 1, y0=0, slope=0)
    assert b.build().statistics()["segments"] == 50
    b.line(50, 51, y0=0, slope=0)
    with pytest.raises(CamCapacityError, match=r"line #51 .* 51 of at most 50 segments") as exc:
        b.build()
    assert (exc.value.element, exc.value.resource, exc.value.limit) == ("line #51", "segments", 50)
    b = CamBuilder()
    for i in range(24):
        b.line(10 * i, 10 * i + 1, y0=0, slope=0).transition("vdi", "modified_trapezoid")
    with pytest.raises(CamCapacityError, match="transition #18 needs 5 segments"):
        b.line(240, 241, y0=1, slope=0).build()


def test_cams_capacity_error_names_the_element_that_exceeds_1000_points_s6_2_5_7():
    b = CamBuilder().point_group([(i, 0.0) for i in range(600)]).inverse_sine(700, 800, 0, 1, n_points=400)
    assert b.build().statistics()["points"] == 1000
    b.point(900, 0)
    with pytest.raises(CamCapacityError, match=r"point #3 needs 1 points.* 1001 of at most 1000 points"):
        b.build()
    with pytest.raises(CamCapacityError, match="inverse_sine #1"):
        CamBuilder().inverse_sine(0, 1, 0, 1, n_points=1001).build()


def test_cams_overlapping_or_unordered_elements_are_refused_s6_2_5_7():
    with pytest.raises(ValueError, match=r"line #2 starts at x=5, before the end of line #1"):
        CamBuilder().line(0, 10, y0=0, slope=0).line(5, 20, y0=0, slope=0)
    with pytest.raises(ValueError, match="point #2 starts"):
        CamBuilder().line(0, 10, y0=0, slope=0).point(3, 1)
    with pytest.raises(ValueError, match="same leading value"):
        CamBuilder().point(0, 0).point(0, 1)
    with pytest.raises(ValueError, match="greater than the start"):
        CamBuilder().line(10, 10, y0=0, slope=0)
    with pytest.raises(ValueError, match="follows an element"):
        CamBuilder().transition("vdi")
    with pytest.raises(ValueError, match="follows an element"):
        CamBuilder().point(0, 0).transition().transition()
    with pytest.raises(ValueError, match="needs an element after it"):
        CamBuilder().point(0, 0).transition("vdi").build()
    with pytest.raises(ValueError, match="needs a gap"):
        CamBuilder().line(0, 10, y0=0, slope=0).transition("vdi").line(10, 20, y0=1, slope=0).build()
    with pytest.raises(ValueError, match="unknown VDI motion law"):
        CamBuilder().point(0, 0).transition("vdi", "spline")
    with pytest.raises(ValueError, match="no elements"):
        CamBuilder().build()


def test_cams_coefficients_beyond_the_lreal_range_of_the_tags_are_reported_sA_2_4():
    b = CamBuilder().line(1e5, 1e5 + 1, y0=0, slope=0).transition("vdi", "polynomial")
    b.line(1e5 + 2, 1e5 + 3, y0=1, slope=0)
    with pytest.raises(CamCoefficientError, match=r"transition #2 .*outside ±1.0E12"):
        b.build()
    # a moderately conditioned segment builds, with a rounding warning when the error estimate is large
    b = CamBuilder().line(2000, 2010, y0=0, slope=0).transition("vdi", "polynomial")
    d = b.line(2030, 2040, y0=1, slope=0).build()
    assert any("rounding" in w for w in d.warnings)


def test_cams_a_step_between_touching_elements_is_reported():
    d = CamBuilder().line(0, 10, y0=0, slope=0).line(10, 20, y0=1, slope=0).build()
    assert d.warnings and "step" in d.warnings[0]


# ------------------------------------------------------------------------------------------------------
# the cam TO (§9.2, §A.2)
def example_cam() -> CamDefinition:
    b = CamBuilder(CUBIC_SPLINE)
    b.line(0, 60, y0=0, slope=0).transition("vdi", "modified_sine").line(120, 180, y0=100, slope=0)
    b.transition("vdi", "polynomial").sine(200, 260, 5, offset=50, phase0=PI / 2, period=60)
    b.point_group([(280, 45), (300, 20), (330, 5)]).point(360, 0)
    return b.build()


def test_cams_apply_to_a_cam_to_and_interpolate_like_mc_interpolatecam_s9_2_1():
    assert SEGMENT_FIELDS == TO_SEGMENT_FIELDS
    d = example_cam()
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam1")
    d.apply(cam)
    assert cam.tag("InterpolationSettings.InterpolationMode") == CUBIC_SPLINE
    assert cam.valid_points() == d.points
    assert cam.valid_segments() == d.segments
    curve = interpolate(cam.valid_points(), cam.valid_segments(), cam.tag("InterpolationSettings.InterpolationMode"),
                        cam.tag("InterpolationSettings.BoundaryConditions"))
    x = np.linspace(0, 360, 721)
    assert curve.value(x) == pytest.approx(d.curve().value(x), abs=1e-12)
    assert (curve.start, curve.end) == (0.0, 360.0)
    assert curve.value(90.0) == pytest.approx(50.0, abs=1e-9)


def test_cams_to_dict_is_json_and_round_trips():
    d = example_cam()
    data = json.loads(json.dumps(d.to_dict()))
    assert data["statistics"]["segments"] == len(d.segments)
    assert data["transitions"][0]["law"] == "modified_sine" and data["transitions"][0]["task"] == "RR"
    back = CamDefinition.from_dict(data)
    x = np.linspace(0, 360, 361)
    assert back.curve().value(x) == pytest.approx(d.curve().value(x), abs=1e-12)
