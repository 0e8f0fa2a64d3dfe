"""Software limit switches and modulo axes of the S7-1200 Motion Control V6 positioning axis.

Manual (seeds/000_a03aa7b7d80586ce.txt):

* §2.3 / §5.4.4.3 "Position limits": "Activated software limit switches act only on a homed axis";
  "If software limit switches are activated, an active motion is stopped at the position of the
  software limit switch.  The axis is braked at the configured deceleration."  The error is shown at the
  initiating instruction, at MC_Power and in the TO tags (ErrorBits.SWLimit,
  StatusBits.SWLimitMinActive / SWLimitMaxActive, §10.1).
* §12.8 16#8001 / 16#8002 ErrorInfo 16#000E; remedy: acknowledge with MC_Reset, then move the axis out
  of the limit in the positive (low limit) / negative (high limit) direction.
* §9.5.3: MC_MoveVelocity with Execute FALSE after the velocity was reached shows no Error for an axis
  error (e.g. SW limit) -- the error is only shown at MC_Power.
* §5.4.4.2 "Modulo" (PROFIdrive/analog only): position in [StartValue, StartValue + Length);
  MC_MoveAbsolute.Direction 0 = sign of Velocity, 1 = positive, 2 = negative, 3 = shortest distance;
  moving to 400° with a 0°/360° range ends at 40°.

Documented decision of the implementation respected here: SW limit switches are not evaluated on
modulo axes.
"""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity,
                               MC_Power, MC_Reset)

ACC, DEC, JERK, EMERGENCY = 80.0, 40.0, 800.0, 400.0
LIMIT = 100.0


def _config(actor: int, **extra):
    cfg = {"Actor": {"Type": actor},
           "DynamicLimits": {"MaxVelocity": 100.0},
           "DynamicDefaults": {"Acceleration": ACC, "Deceleration": DEC, "Jerk": JERK,
                               "EmergencyDeceleration": EMERGENCY},
           "PositionLimits_SW": {"Active": True, "MinPosition": -LIMIT, "MaxPosition": LIMIT}}
    if actor == 2:
        cfg["DynamicLimits"]["MinVelocity"] = 10.0
    cfg.update(extra)
    return cfg


def make(kind: str, **extra):
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", _config(1 if kind == "pd" else 2, **extra))
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    return ctl, axis, power


def home(ctl, axis, position=0.0):
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=0, Position=position)
    ctl.run_until(lambda: h().Done or h.Error, timeout=1.0)
    assert h.Done and axis.StatusBits.HomingDone


def settle(ctl, *fbs, cycles=2):
    for _ in range(cycles):
        ctl.step()
        for fb in fbs:
            fb()


class Trace:
    """Setpoint position/velocity/acceleration of every servo cycle (post-servo hook)."""

    def __init__(self, ctl, axis):
        self.ctl, self.axis = ctl, axis
        self.t, self.p, self.v, self.a = [], [], [], []
        ctl.on_post_servo(self)

    def __call__(self, t):
        self.t.append(t)
        self.p.append(self.axis.Position)
        self.v.append(self.axis.Velocity)
        self.a.append(self.axis.Acceleration)

    def close(self):
        self.ctl.remove_hook(self)


def _toward(cls, direction, velocity=40.0):
    if cls is MC_MoveAbsolute:
        return dict(Execute=True, Position=160.0 * direction, Velocity=velocity)
    if cls is MC_MoveRelative:
        return dict(Execute=True, Distance=160.0 * direction, Velocity=velocity)
    if cls is MC_MoveVelocity:
        return dict(Execute=True, Velocity=velocity * direction)
    return dict(JogForward=direction > 0, JogBackward=direction < 0, Velocity=velocity)


MOVES = [MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog]


# ----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("direction", [+1, -1], ids=["positive", "negative"])
def test_s7_1200_sw_limits_act_only_when_homed_5_4_4_3(kind, direction):
    """§5.4.4.3 note: "Activated software limit switches act only on a homed axis" -- an axis that is
    not homed travels through the configured limit positions without error."""
    ctl, axis, power = make(kind)
    assert not axis.StatusBits.HomingDone
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=150.0 * direction, Velocity=50.0)
    ctl.run_until(lambda: mr().Done or mr.Error, timeout=10.0)
    power()
    assert mr.Done and not mr.Error
    assert axis.Position == pytest.approx(150.0 * direction, abs=1e-6)
    assert not power.Error and not axis.StatusBits.Error and not axis.ErrorBits.SWLimit
    assert not axis.StatusBits.SWLimitMaxActive and not axis.StatusBits.SWLimitMinActive


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("direction", [+1, -1], ids=["high", "low"])
@pytest.mark.parametrize("cls", MOVES, ids=lambda c: c.__name__)
def test_s7_1200_sw_limit_stop_exactly_at_limit_with_configured_deceleration_5_4_4_3(kind, direction, cls):
    """§5.4.4.3 "Behavior of axis when software limit switches are reached": the motion is stopped at
    the position of the SW limit switch, braked with the configured deceleration (not the emergency
    deceleration); §12.8 16#8001/16#8002 ErrorInfo 16#000E at the instruction and at MC_Power;
    ErrorBits.SWLimit, StatusBits.SWLimitMinActive/MaxActive (§10.1)."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    tr = Trace(ctl, axis)
    fb = cls()
    fb(Axis=axis, **_toward(cls, direction))
    ctl.run_until(lambda: fb().Error or getattr(fb, "Done", False), timeout=10.0)
    settle(ctl, fb, power)
    tr.close()
    error_id = 0x8002 if direction > 0 else 0x8001
    assert fb.Error and (fb.ErrorID, fb.ErrorInfo) == (error_id, 0x000E)
    assert power.Error and (power.ErrorID, power.ErrorInfo) == (error_id, 0x000E)
    assert axis.StatusBits.Error and axis.ErrorBits.SWLimit
    # stopped exactly at the limit, never beyond it (setpoint)
    assert axis.Velocity == 0.0
    assert axis.Position == pytest.approx(LIMIT * direction, abs=1e-6)
    assert max(p * direction for p in tr.p) <= LIMIT + 1e-6
    # StatusBits: the limit of this side is active, the other one is not
    if direction > 0:
        assert axis.StatusBits.SWLimitMaxActive and not axis.StatusBits.SWLimitMinActive
    else:
        assert axis.StatusBits.SWLimitMinActive and not axis.StatusBits.SWLimitMaxActive
    # the commanded velocity was reached before braking (the limit does not slow the whole motion)
    assert max(v * direction for v in tr.v) == pytest.approx(40.0, rel=1e-6)
    # braked with the configured deceleration DEC (< ACC < EMERGENCY): the braking acceleration
    # reaches -DEC and never exceeds it
    braking = [-a * direction for a in tr.a]
    assert max(braking) == pytest.approx(DEC, rel=1e-3)
    assert max(braking) <= DEC * (1 + 1e-9)


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("direction", [+1, -1], ids=["high", "low"])
def test_s7_1200_sw_limit_reset_then_free_direction_12_8(kind, direction):
    """§12.8 remedy of 16#8001/16#8002: acknowledge with MC_Reset, then move the axis out of the limit
    in the free direction (negative out of the high limit, positive out of the low limit)."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=150.0 * direction, Velocity=50.0)
    ctl.run_until(lambda: ma().Error, timeout=10.0)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, power)
    assert reset.Done and not axis.StatusBits.Error and not power.Error
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=-20.0 * direction, Velocity=20.0)
    ctl.run_until(lambda: mr().Done or mr.Error, timeout=10.0)
    power()
    assert mr.Done and not power.Error
    assert axis.Position == pytest.approx(80.0 * direction, abs=1e-6)
    assert not axis.StatusBits.SWLimitMaxActive and not axis.StatusBits.SWLimitMinActive
    # and back into the range with a velocity command in the free direction
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=-30.0 * direction)
    ctl.run_until(lambda: mv().InVelocity or mv.Error, timeout=5.0)
    assert mv.InVelocity and not mv.Error


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("direction", [+1, -1], ids=["high", "low"])
@pytest.mark.parametrize("cls", MOVES, ids=lambda c: c.__name__)
def test_s7_1200_sw_limit_further_into_limit_refused_12_8(kind, direction, cls):
    """§12.8 16#8001/16#8002: after MC_Reset, only the free direction is possible; a motion further
    into the limit is stopped at once with the SW limit error again and the setpoint stays at the
    limit position (§5.4.4.3)."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=150.0 * direction, Velocity=50.0)
    ctl.run_until(lambda: ma().Error, timeout=10.0)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, power)
    assert not axis.StatusBits.Error
    tr = Trace(ctl, axis)
    fb = cls()
    kw = _toward(cls, direction, 20.0)
    if cls is MC_MoveRelative:
        kw["Distance"] = 10.0 * direction
    if cls is MC_MoveAbsolute:
        kw["Position"] = 110.0 * direction
    fb(Axis=axis, **kw)
    ctl.run_until(lambda: fb().Error or getattr(fb, "Done", False), timeout=3.0)
    settle(ctl, fb, power)
    tr.close()
    error_id = 0x8002 if direction > 0 else 0x8001
    assert fb.Error and fb.ErrorID == error_id
    assert power.Error and power.ErrorID == error_id
    assert max(p * direction for p in tr.p) <= LIMIT + 1e-6
    assert axis.Position == pytest.approx(LIMIT * direction, abs=1e-6)


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_sw_limit_velocity_execute_false_only_at_mc_power_9_5_3(kind):
    """§9.5.3 exception: velocity reached, Execute FALSE, then an axis error (SW limit switch) occurs:
    MC_MoveVelocity shows no Error, the error is only shown at MC_Power."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=50.0)
    ctl.run_until(lambda: mv().InVelocity, timeout=3.0)
    mv(Execute=False)
    seen_error = False
    for _ in range(2000):
        ctl.step()
        mv()
        power()
        seen_error |= mv.Error
        if power.Error:
            break
    settle(ctl, mv, power)
    assert power.Error and (power.ErrorID, power.ErrorInfo) == (0x8002, 0x000E)
    assert not seen_error and not mv.Error
    assert not mv.Busy
    assert axis.Position == pytest.approx(LIMIT, abs=1e-6)


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_move_inside_limits_no_error_5_4_4_3(kind):
    """§5.4.4.3: a target inside the SW limits is reached without any limit reaction."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    for target in (95.0, -95.0, 0.0):
        ma = MC_MoveAbsolute()
        ma(Axis=axis, Execute=True, Position=target, Velocity=60.0)
        ctl.run_until(lambda: ma().Done or ma.Error, timeout=10.0)
        power()
        assert ma.Done and not power.Error
        assert axis.Position == pytest.approx(target, abs=1e-6)
        assert not axis.StatusBits.SWLimitMaxActive and not axis.StatusBits.SWLimitMinActive


# ----------------------------------------------------------------------------------------------------
# Modulo (§5.4.4.2, §11.1.5 Direction)
def make_modulo(start=0.0, length=360.0, home_at=0.0, **extra):
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    cfg = {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 100.0},
           "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "Jerk": 1000.0,
                               "EmergencyDeceleration": 1000.0},
           "Modulo": {"Enable": True, "Length": length, "StartValue": start}}
    cfg.update(extra)
    axis = ctl.add_positioning_axis("Axis_1", cfg)
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    home(ctl, axis, home_at)
    return ctl, axis, power


class Travel:
    """Unwrapped travel of the (wrapped) Position tag, and the range of the tag values seen."""

    def __init__(self, ctl, axis, length):
        self.ctl, self.axis, self.length = ctl, axis, length
        self.prev = axis.Position
        self.travel = 0.0
        self.positions = []
        self.actual = []
        self.v = []
        ctl.on_post_servo(self)

    def __call__(self, _t):
        p = self.axis.Position
        d = math.remainder(p - self.prev, self.length)
        self.travel += d
        self.prev = p
        self.positions.append(p)
        self.actual.append(self.axis.ActualPosition)
        self.v.append(self.axis.Velocity)

    def close(self):
        self.ctl.remove_hook(self)


MODULO_CASES = [
    # (start position, Position, Direction, Velocity, expected signed travel)
    (10.0, 350.0, 1, 100.0, +340.0),
    (10.0, 350.0, 2, 100.0, -20.0),
    (10.0, 350.0, 3, 100.0, -20.0),
    (350.0, 10.0, 3, 100.0, +20.0),
    (10.0, 100.0, 3, 100.0, +90.0),
    (100.0, 10.0, 1, 100.0, +270.0),
    (100.0, 10.0, 2, 100.0, -90.0),
    (200.0, 10.0, 3, 100.0, +170.0),
    (10.0, 350.0, 0, 100.0, +340.0),     # Direction 0: sign of Velocity
    (10.0, 350.0, 0, -100.0, -20.0),
    (350.0, 10.0, 0, -100.0, -340.0),
    (0.0, 400.0, 1, 100.0, +40.0),       # §5.4.4.2: 400° -> 40°
    (0.0, 400.0, 3, 100.0, +40.0),
    (0.0, -30.0, 1, 100.0, +330.0),      # -30° -> 330°
    (0.0, 810.0, 2, 100.0, -270.0),      # 810° -> 90°
]


@pytest.mark.parametrize("p0,target,direction,velocity,travel", MODULO_CASES,
                         ids=[f"{c[0]:g}->{c[1]:g}-dir{c[2]}-v{c[3]:g}" for c in MODULO_CASES])
def test_s7_1200_modulo_move_absolute_direction_5_4_4_2(p0, target, direction, velocity, travel):
    """§5.4.4.2 / §11.1.5 Direction on a modulo axis: 1 positive, 2 negative, 3 shortest distance,
    0 sign of Velocity; a Position outside the modulo range ends at the equivalent position inside it
    (400° -> 40°).  The motion never runs against the selected direction."""
    ctl, axis, power = make_modulo(home_at=p0)
    assert axis.Position == pytest.approx(p0, abs=1e-9)
    tr = Travel(ctl, axis, 360.0)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=target, Velocity=velocity, Direction=direction)
    ctl.run_until(lambda: ma().Done or ma.Error, timeout=15.0)
    tr.close()
    power()
    assert ma.Done and not ma.Error and not power.Error
    expected = target % 360.0
    assert math.remainder(axis.Position - expected, 360.0) == pytest.approx(0.0, abs=1e-6)
    assert 0.0 <= axis.Position < 360.0
    assert tr.travel == pytest.approx(travel, abs=1e-3)
    sign = math.copysign(1.0, travel)
    assert min(v * sign for v in tr.v) >= -1e-9, "moved against the selected direction"
    assert max(abs(v) for v in tr.v) <= abs(velocity) * (1 + 1e-9)


@pytest.mark.parametrize("start,length", [(0.0, 360.0), (-180.0, 360.0), (45.0, 90.0), (1000.0, 10.0)])
@pytest.mark.parametrize("velocity", [100.0, -100.0])
def test_s7_1200_modulo_position_tag_in_range_5_4_4_2(start, length, velocity):
    """§5.4.4.2: "the position value of the technology object is represented by means of a recurring
    modulo range" [StartValue, StartValue + Length) -- for the setpoint and the actual position, during
    several revolutions in both directions."""
    ctl, axis, power = make_modulo(start=start, length=length, home_at=start + 0.5 * length)
    tr = Travel(ctl, axis, length)
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=velocity)
    ctl.run(1.5 + 2.3 * length / abs(velocity))
    mv()
    tr.close()
    assert mv.Busy and mv.InVelocity and not power().Error
    assert abs(tr.travel) > 2 * length
    for values in (tr.positions, tr.actual):
        assert min(values) >= start
        assert max(values) < start + length


def test_s7_1200_modulo_move_relative_wraps_11_1_6():
    """§11.1.6 target = start position + Distance; §5.4.4.2 the position is shown in the modulo range."""
    ctl, axis, power = make_modulo(home_at=10.0)
    tr = Travel(ctl, axis, 360.0)
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=400.0, Velocity=100.0)
    ctl.run_until(lambda: mr().Done or mr.Error, timeout=15.0)
    tr.close()
    assert mr.Done
    assert tr.travel == pytest.approx(400.0, abs=1e-3)
    assert axis.Position == pytest.approx(50.0, abs=1e-6)
    assert min(tr.positions) >= 0.0 and max(tr.positions) < 360.0


def test_s7_1200_modulo_axis_sw_limits_not_evaluated_decision():
    """Documented decision (manual silent; §2.5 of the catalog: the SW limit order check is for
    non-modulo axes only): SW limit switches are not evaluated on a modulo axis."""
    ctl, axis, power = make_modulo(home_at=0.0, PositionLimits_SW={"Active": True, "MinPosition": 10.0,
                                                                    "MaxPosition": 20.0})
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=100.0)
    ctl.run(5.0)
    mv()
    power()
    assert mv.Busy and not mv.Error and not power.Error and not axis.ErrorBits.SWLimit


# ----------------------------------------------------------------------------------------------------
# §12.4 special cases (PTO): homing shifts and lower deceleration near the SW limit switch
def _moving_pto(velocity=50.0):
    ctl, axis, power = make("pto", DynamicDefaults={"Acceleration": ACC, "Deceleration": DEC, "Jerk": 0.0,
                                                    "EmergencyDeceleration": EMERGENCY})
    home(ctl, axis, 0.0)
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=velocity)
    ctl.run_until(lambda: mv().InVelocity, timeout=3.0)
    return ctl, axis, power, mv


def test_s7_1200_pto_homing_shift_emergency_stop_at_limit_12_4_1_example_1():
    """§12.4.1 example 1: during a travel command a homing job (set reference point) moves the position
    toward the SW limit; the configured deceleration no longer suffices, the emergency deceleration does:
    constant motion, then braking with the emergency stop deceleration to standstill exactly at the
    limit; §12.8 16#8002 ErrorInfo 16#000F (no remove enable)."""
    ctl, axis, power, mv = _moving_pto(50.0)
    # distance 12 to the limit: configured deceleration needs ~30, emergency deceleration ~3
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=0, Position=LIMIT - 12.0)
    tr = Trace(ctl, axis)
    ctl.run_until(lambda: [h(), power()] and mv().Error, timeout=3.0)
    settle(ctl, mv, power, h)
    tr.close()
    assert h.Done
    assert (mv.ErrorID, mv.ErrorInfo) == (0x8002, 0x000F)
    assert power.Error and (power.ErrorID, power.ErrorInfo) == (0x8002, 0x000F)
    assert power.Status
    assert axis.Position == pytest.approx(LIMIT, abs=1e-6)
    assert max(tr.p) <= LIMIT + 1e-6
    braking = [-a for a in tr.a]
    assert max(braking) == pytest.approx(EMERGENCY, rel=1e-6)


def test_s7_1200_pto_homing_shift_overrun_12_4_1_example_2():
    """§12.4.1 example 2: even the emergency deceleration is not sufficient -- the axis overruns the SW
    limit; §12.8 16#8002 ErrorInfo 16#0010 with reaction "remove enable"."""
    ctl, axis, power, mv = _moving_pto(50.0)
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=0, Position=LIMIT - 1.0)   # emergency stop needs ~3.1
    ctl.run_until(lambda: [h(), mv()] and power().Error, timeout=3.0)
    ctl.run_until(lambda: [mv()] and not power().Status, timeout=3.0)
    assert (power.ErrorID, power.ErrorInfo) == (0x8002, 0x0010)
    assert not axis.StatusBits.Enable
    assert axis.ErrorBits.SWLimit
    assert axis.Position > LIMIT


def test_s7_1200_pto_override_with_lower_deceleration_12_4_3_example_1():
    """§12.4.3 example 1: an overriding motion command started with a lower DynamicDefaults.Deceleration
    could not stop before the limit; the axis moves on at constant velocity and brakes with the
    emergency stop deceleration to standstill at the SW limit (16#8002 / 16#000F)."""
    ctl, axis, power, mv = _moving_pto(50.0)
    ctl.run_until(lambda: mv() and axis.Position >= 55.0, timeout=3.0)
    axis.DynamicDefaults.Deceleration = 2.0          # effective at the next command start (§12.9 code 5)
    mv2 = MC_MoveVelocity()
    mv2(Axis=axis, Execute=True, Velocity=50.0)
    tr = Trace(ctl, axis)
    ctl.run_until(lambda: [mv(), power()] and mv2().Error, timeout=5.0)
    settle(ctl, mv2, power)
    tr.close()
    assert mv.CommandAborted
    assert (mv2.ErrorID, mv2.ErrorInfo) == (0x8002, 0x000F)
    assert (power.ErrorID, power.ErrorInfo) == (0x8002, 0x000F)
    assert axis.Position == pytest.approx(LIMIT, abs=1e-6)
    assert max(tr.p) <= LIMIT + 1e-6
    assert max(-a for a in tr.a) == pytest.approx(EMERGENCY, rel=1e-6)


def test_s7_1200_pd_homing_shift_beyond_limit_disables_5_4_4_3():
    """§5.4.4.3: "When a software limit switch is overtraveled" on a PROFIdrive axis "the axis is
    disabled"; the error 16#8002 is shown at MC_Power (§12.8, 16#0010: exceeded, remove enable)."""
    ctl, axis, power = make("pd")
    home(ctl, axis, 0.0)
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=50.0)
    ctl.run_until(lambda: mv().InVelocity, timeout=3.0)
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=0, Position=LIMIT - 1.0)   # emergency stop would need ~3.1
    ctl.run_until(lambda: [h(), mv()] and power().Error, timeout=3.0)
    ctl.run_until(lambda: [mv()] and not power().Status, timeout=3.0)
    assert power.ErrorID == 0x8002 and power.ErrorInfo == 0x0010
    assert not axis.StatusBits.Enable and axis.ErrorBits.SWLimit


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_homed_beyond_limit_status_and_refusal_10_1(kind):
    """§10.1 StatusBits.SWLimitMaxActive: "high SW limit reached or exceeded" -- also when homing puts
    the standing axis beyond it; a further motion in that direction is stopped with 16#8002
    (§5.4.4.3) and does not move the axis further out."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 150.0)
    settle(ctl, power)
    assert axis.StatusBits.SWLimitMaxActive and not axis.StatusBits.SWLimitMinActive
    if axis.StatusBits.Error:
        reset = MC_Reset()
        reset(Axis=axis, Execute=True)
        settle(ctl, reset, power)
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0)
    ctl.run_until(lambda: mr().Error or mr.Done, timeout=3.0)
    assert mr.Error and mr.ErrorID == 0x8002
    assert axis.Position <= 150.0 + 1e-6


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_sw_limit_error_pulsed_execute_one_cycle_9_5_2(kind):
    """§9.5.2: if Execute is already FALSE when the error occurs, Error is TRUE for exactly one call."""
    ctl, axis, power = make(kind)
    home(ctl, axis, 0.0)
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=150.0, Velocity=50.0)
    mr(Execute=False)
    shown = []
    for _ in range(2000):
        ctl.step()
        mr()
        shown.append(mr.Error)
        if power().Error and len(shown) > 2 and not mr.Busy and not shown[-1] and True in shown:
            break
    settle(ctl, mr, cycles=3)
    assert shown.count(True) == 1
    assert not mr.Error
    assert power.ErrorID == 0x8002


def test_s7_1200_sw_limit_error_after_jog_release_one_cycle_9_5_4():
    """§9.5.4 note: jog inputs already FALSE (axis still decelerating) and a new error occurs (SW limit
    switch approached): Error is shown for only one execution cycle; the axis error stays at MC_Power.
    Scenario (PTO): a lower Deceleration written while jogging takes effect when the jog is stopped
    (§12.9 effective code 6); the release braking would pass the limit, so the axis continues and
    brakes with the emergency deceleration to standstill at the limit (§12.4.3, 16#8002/16#000F)."""
    ctl, axis, power = make("pto")
    home(ctl, axis, 0.0)
    jog = MC_MoveJog()
    jog(Axis=axis, JogForward=True, Velocity=50.0)
    ctl.run_until(lambda: jog().InVelocity and axis.Position >= 40.0, timeout=5.0)
    axis.DynamicDefaults.Deceleration = 5.0
    ctl.run_until(lambda: jog() and axis.Position >= 55.0, timeout=5.0)
    assert axis.Velocity == pytest.approx(50.0)
    jog(JogForward=False)                  # braking distance with Deceleration 5 is about 240
    tr = Trace(ctl, axis)
    shown = []
    for _ in range(1000):
        ctl.step()
        jog()
        shown.append(jog.Error)
        if not jog.Busy and axis.Velocity == 0.0 and len(shown) > 3 and not shown[-1]:
            break
    settle(ctl, jog, power, cycles=3)
    tr.close()
    assert power.Error and (power.ErrorID, power.ErrorInfo) == (0x8002, 0x000F)
    assert shown.count(True) == 1 and not jog.Error
    assert max(tr.p) <= LIMIT + 1e-6
    assert axis.Position == pytest.approx(LIMIT, abs=1e-6)
    assert max(-a for a in tr.a) == pytest.approx(EMERGENCY, rel=1e-6)


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("jerk", [0.0, JERK], ids=["trapezoidal", "jerk"])
@pytest.mark.parametrize("target,velocity", [(100.0, 10.0), (100.0, 60.0), (95.0, 10.0)])
def test_s7_1200_override_during_limit_braking_never_passes_limit_5_4_4_3(kind, jerk, target, velocity):
    """§5.4.4.3: "an active motion is stopped at the position of the software limit switch"; §12.4 /
    §12.8: passing the limit is only possible when even the emergency deceleration is insufficient
    (16#0010).  A MC_MoveVelocity is already braking for the high limit when a MC_MoveAbsolute with a
    lower Velocity overrides it; the configured deceleration (and certainly the emergency deceleration)
    still suffices to stop at the limit, so the setpoint must never pass the limit position."""
    ctl, axis, power = make(kind, DynamicDefaults={"Acceleration": ACC, "Deceleration": DEC, "Jerk": jerk,
                                                   "EmergencyDeceleration": EMERGENCY})
    home(ctl, axis, 0.0)
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=60.0)
    ctl.run_until(lambda: mv() and axis.Position > 30.0 and axis.Acceleration < -1.0, timeout=5.0)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=target, Velocity=velocity)
    tr = Trace(ctl, axis)
    ctl.run_until(lambda: ma().Done or ma.Error, timeout=10.0)
    tr.close()
    assert max(tr.p) <= LIMIT + 1e-6, f"setpoint passed the SW limit: {max(tr.p)}"
    if ma.Error:
        assert ma.ErrorID == 0x8002 and ma.ErrorInfo in (0x000E, 0x000F)
