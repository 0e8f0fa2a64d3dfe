"""Homing of the S7-1200 V6 positioning axis, derived from the function manual.

Manual sections (S7-1200 Motion Control V6.0, seeds/000):
  §2.5       homing modes, "Resetting the Homed status" (PTO / incremental / absolute actual values)
  §5.4.4.5   active homing (approach/homing direction, side of the switch, approach and homing velocity,
             home position offset, auto reversal at the HW limit switch, input filter warning), passive
             homing (no motion of its own, homed when the configured side is reached, the running travel
             is not cancelled, standstill: next rising or falling edge), zero mark homing (PROFIdrive)
  §11.1.3.1  MC_Home modes 0/1/2/3/6/7, override response, ReferenceMarkPosition, Homed status
  §12.8      16#8003/16#8004 (16#000E), 16#8009, 16#8011, 16#8012, 16#8207/16#0016, 16#8404/16#0017,
             16#8404/16#0055, 16#8404/16#0056, 16#8610/16#8611 (16#0008 / 16#0009)
Project decisions (docs/decisions.md) respected here: #28 (modes 6/7), #31 (homing direction = approach
direction, configured end crossed in that direction), #32 (the homing event gets Position - offset),
#33 (accuracy: velocity x (filter time + up to one servo cycle); zero marks exact), #34 (passive homing),
#35 (switch not found), #39 (homing velocity checks), #52 (absolute encoder).

The simulated machine: the homing switch is actuated for machine positions [100, 120]
(``Plant.HomingSwitchPosition``/``HomingSwitchLength``), the low HW limit switch at and below -200, the high
one at and above 300.  ``axis.drive.mechanical_position()`` is where the load really is.
"""
from __future__ import annotations

from typing import Any

import pytest

from _fb_program import FbProgram
from plcmotion import Controller
from plcmotion.s7_1200 import (
    MC_Halt,
    MC_Home,
    MC_MoveAbsolute,
    MC_MoveRelative,
    MC_MoveVelocity,
    MC_Power,
    MC_Reset,
)

SERVO, APP = 0.001, 0.004
PULSE = 0.01                    # PTO: LeadScrew 10 / 1000 pulses per revolution
V_APP, V_REF = 50.0, 5.0        # approach and homing (referencing) velocity
CAM_LO, CAM_HI = 100.0, 120.0   # machine positions of the ends of the homing switch
HW_MIN, HW_MAX = -200.0, 300.0


def _flat(tree: dict, prefix: str = "") -> dict:
    out: dict[str, Any] = {}
    for k, v in tree.items():
        path = f"{prefix}.{k}" if prefix else k
        if isinstance(v, dict):
            out.update(_flat(v, path))
        else:
            out[path] = v
    return out


def config(actor: int = 2, extra: dict | None = None) -> dict:
    base = {
        "Actor": {"Type": actor},
        "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0 if actor == 2 else 0.0},
        "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": 200.0, "Jerk": 0.0,
                            "EmergencyDeceleration": 1000.0},
        "Homing": {"ApproachVelocity": V_APP, "ReferencingVelocity": V_REF, "ApproachDirection": True,
                   "AutoReversal": False},
        "Sensor[1]": {"ActiveHoming": {"DigitalInputAddress": "I0.0", "SideInput": False, "HomePositionOffset": 0.0,
                                       "SwitchLevel": True},
                      "PassiveHoming": {"DigitalInputAddress": "I0.0", "SideInput": False}},
        "PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.1", "MaxSwitchAddress": "I0.2",
                              "MinSwitchLevel": False, "MaxSwitchLevel": False},
        "Actor.Interface": {"DriveReadyInput": "", "EnableDriveOutput": "Q0.0"},
        "Plant": {"InitialPosition": 0.0, "HomingSwitchPosition": CAM_LO, "HomingSwitchLength": CAM_HI - CAM_LO,
                  "HWLimitMinPosition": HW_MIN, "HWLimitMaxPosition": HW_MAX},
    }
    cfg = _flat(base)
    cfg.update(_flat(extra or {}))
    return cfg


class Bench(FbProgram):
    """A controller with one axis and a program that calls every added instance once per application cycle.
    A post-servo hook samples (t, Position, Velocity, machine position, HomingDone) every servo cycle."""

    def __init__(self, actor: int = 2, extra: dict | None = None, *, filt: float = 0.0, enable: bool = True,
                 state_file: str | None = None, cam_filter: float | None = None):
        ctl = Controller(servo_cycle=SERVO, app_cycle=APP, input_filter=filt, state_file=state_file)
        axis = ctl.add_positioning_axis("Axis_1", config(actor, extra))
        if cam_filter is not None:
            ctl.inputs.set_filter("I0.0", cam_filter)
        self.trace: list[tuple[float, float, float, float, bool]] = []
        super().__init__(ctl, axis, MC_Power(Enable=enable), enable=enable, sample=self._sample)

    def _sample(self, t: float) -> None:
        ax = self.axis
        self.trace.append((t, ax.Position, ax.Velocity, ax.drive.mechanical_position(), ax.StatusBits.HomingDone))

    def coordinate_of(self, machine: float) -> float:
        """Axis coordinate of a machine position (from the current actual value)."""
        ax = self.axis
        return ax.ActualPosition + (machine - ax.drive.mechanical_position())

    def direct_home(self, position: float = 0.0) -> None:
        hm = self.start(MC_Home(), Mode=0, Position=position)
        self.until(lambda: hm.Done, 0.1, "MC_Home Mode 0 done")
        hm.Execute = False
        self.ctl.step()
        assert self.axis.StatusBits.HomingDone


def run_active_homing(b: Bench, position: float, timeout: float = 30.0) -> tuple[MC_Home, int]:
    """Start MC_Home Mode 3 and run until it ends; returns the instance and the trace index of the start."""
    k0 = len(b.trace)
    hm = b.start(MC_Home(), Mode=3, Position=position)
    b.until(lambda: not hm.Busy, timeout, "active homing ended")
    return hm, k0


def first_homed(b: Bench, k0: int) -> int:
    return next(k for k in range(k0, len(b.trace)) if b.trace[k][4])


def peak_deceleration(b: Bench, k_from: int, k_to: int) -> float:
    """Largest velocity change per servo cycle while the speed falls (jerk 0: the deceleration used); the
    final step from the start/stop velocity of a PTO axis to 0 is not a deceleration (§5.4.4.4)."""
    best = 0.0
    for k in range(k_from, k_to - 1):
        v0, v1 = b.trace[k][2], b.trace[k + 1][2]
        if abs(v1) < abs(v0) and v0 * v1 > 0.0:
            best = max(best, (abs(v0) - abs(v1)) / SERVO)
    return best


# ---------------------------------------------------------------------------------------------------------
# active homing: directions, sides, sequence
ACTIVE_CASES = [
    # ApproachDirection, SideInput (TRUE upper), start (machine), homing mark (machine), crossing direction
    pytest.param(True, False, 0.0, CAM_LO, +1.0, id="positive-lower"),
    pytest.param(True, True, 0.0, CAM_HI, +1.0, id="positive-upper"),
    pytest.param(False, False, 250.0, CAM_LO, -1.0, id="negative-lower"),
    pytest.param(False, True, 250.0, CAM_HI, -1.0, id="negative-upper"),
]


@pytest.mark.parametrize("positive,upper,start,mark,direction", ACTIVE_CASES)
def test_s7_1200_5_4_4_5_active_homing_direction_and_side(positive, upper, start, mark, direction):
    """§5.4.4.5 'Sequence - Active homing' and 'Approach/homing direction', 'Side of homing switch';
    §2.5 (HomingDone reset at the start of active homing, set again on success); §11.1.3.1
    (Done + HomingDone, ReferenceMarkPosition).  The axis searches at the approach velocity in the approach
    direction; the configured end of the switch is crossed in the homing direction at the homing velocity
    and gets the coordinate MC_Home.Position (decisions #31, #32; filter 0 -> error at most one servo
    cycle at the homing velocity)."""
    b = Bench(extra={"Homing.ApproachDirection": positive, "Sensor[1].ActiveHoming.SideInput": upper,
                     "Plant.InitialPosition": start})
    b.direct_home(0.0)                                    # homed before: active homing must reset it
    hm, k0 = run_active_homing(b, 42.0)
    assert hm.Done and not hm.Error and not hm.CommandAborted, hm.outputs
    assert b.axis.StatusBits.HomingDone
    k_ev = first_homed(b, k0)
    assert k_ev > k0 + 10
    assert not any(s[4] for s in b.trace[k0 + 1:k_ev]), "HomingDone must be FALSE during active homing (§2.5)"
    assert all(s[4] for s in b.trace[k_ev:]), "HomingDone stays TRUE once homed"
    # search at the approach velocity in the approach direction
    search_dir = 1.0 if positive else -1.0
    assert max(s[2] * search_dir for s in b.trace[k0:k_ev]) == pytest.approx(V_APP)
    # the homing event: crossing the configured end in the homing direction at the homing velocity
    assert b.trace[k_ev - 1][2] == pytest.approx(direction * V_REF)
    assert abs(b.trace[k_ev - 1][3] - mark) < 2.0 * V_REF * SERVO + 1e-9
    # the end of the switch has the coordinate Position
    assert b.coordinate_of(mark) == pytest.approx(42.0, abs=V_REF * SERVO + PULSE + 1e-9)
    assert hm.ReferenceMarkPosition == pytest.approx(42.0)
    # no offset: the axis brakes after the mark with the configured deceleration
    assert b.axis.Velocity == 0.0
    assert b.axis.Position == pytest.approx(42.0 + direction * V_REF ** 2 / (2 * 200.0), abs=0.02)


def test_s7_1200_5_4_4_5_active_homing_status_while_searching():
    """§11.1.3.1 / §9.5.2: Busy TRUE while homing; §12.9.23 StatusBits.HomingCommand TRUE while MC_Home
    runs; §2.5: HomingDone FALSE from the start of active homing."""
    b = Bench()
    b.direct_home(5.0)
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(2)
    assert hm.Busy and not hm.Done
    assert b.axis.StatusBits.HomingCommand
    assert not b.axis.StatusBits.HomingDone
    b.until(lambda: hm.Done, 30.0, "homing done")
    b.ctl.step()
    assert not b.axis.StatusBits.HomingCommand


@pytest.mark.parametrize("upper,offset,mark", [
    pytest.param(True, 5.0, CAM_HI, id="S-HOME-3-upper-offset+5"),
    pytest.param(False, -5.0, CAM_LO, id="lower-offset-5"),
])
def test_s7_1200_5_4_4_5_home_position_offset(upper, offset, mark):
    """§5.4.4.5 'Home position offset' / 'Travel to home position offset': after homing at the switch the
    axis moves at the homing velocity by the offset; there it is at MC_Home.Position.  Decision #32: the
    switch end gets Position - HomePositionOffset; ReferenceMarkPosition shows Position - offset."""
    b = Bench(extra={"Sensor[1].ActiveHoming.SideInput": upper,
                     "Sensor[1].ActiveHoming.HomePositionOffset": offset})
    hm, k0 = run_active_homing(b, 0.0)
    assert hm.Done, hm.outputs
    k_ev = first_homed(b, k0)
    # the offset travel runs at (at most) the homing velocity
    assert max(abs(s[2]) for s in b.trace[k_ev:]) <= V_REF + 1e-9
    # standstill at the home position = MC_Home.Position
    assert b.axis.Velocity == 0.0
    assert b.axis.Position == pytest.approx(0.0, abs=1e-6)
    assert b.axis.drive.mechanical_position() == pytest.approx(mark + offset, abs=V_REF * SERVO + 2 * PULSE)
    assert b.coordinate_of(mark) == pytest.approx(-offset, abs=V_REF * SERVO + PULSE + 1e-9)
    assert hm.ReferenceMarkPosition == pytest.approx(0.0 - offset)


@pytest.mark.parametrize("upper,mark", [(False, CAM_LO), (True, CAM_HI)], ids=["lower", "upper"])
def test_s7_1200_5_4_4_5_active_homing_starting_on_the_switch(upper, mark):
    """§5.4.4.5 (and §12.10.2.1 'the actual sequence can differ depending on the start position'): an axis
    standing on the homing switch is homed on the configured end, crossed in the homing direction
    (decision #31: brake, reposition as needed, cross that end)."""
    b = Bench(extra={"Sensor[1].ActiveHoming.SideInput": upper, "Plant.InitialPosition": 110.0})
    assert b.ctl.inputs["I0.0"]                              # on the switch
    hm, k0 = run_active_homing(b, 10.0)
    assert hm.Done, hm.outputs
    k_ev = first_homed(b, k0)
    assert b.trace[k_ev - 1][2] == pytest.approx(+V_REF)    # crossing in the (positive) homing direction
    assert b.coordinate_of(mark) == pytest.approx(10.0, abs=V_REF * SERVO + PULSE + 1e-9)
    # it never searched away at the approach velocity
    assert max(abs(s[2]) for s in b.trace[k0:]) <= V_REF + 1e-9


# ---------------------------------------------------------------------------------------------------------
# HW limit switches during active homing
@pytest.mark.parametrize("positive,start,upper,mark,direction", [
    pytest.param(True, 200.0, False, CAM_LO, +1.0, id="positive-reverses-at-high-limit"),
    pytest.param(False, 50.0, False, CAM_LO, -1.0, id="negative-reverses-at-low-limit"),
])
def test_s7_1200_5_4_4_5_auto_reversal_at_hw_limit(positive, start, upper, mark, direction):
    """§5.4.4.5 'Permit auto reverse at HW limit switch': when the HW limit switch is reached during active
    homing the axis brakes with the configured deceleration (not the emergency deceleration), reverses and
    senses the homing switch in the reverse direction; homing then completes without error."""
    b = Bench(extra={"Homing.AutoReversal": True, "Homing.ApproachDirection": positive,
                     "Sensor[1].ActiveHoming.SideInput": upper, "Plant.InitialPosition": start})
    hm, k0 = run_active_homing(b, 0.0)
    assert hm.Done and not hm.Error, hm.outputs
    assert not b.power.Error and b.power.Status
    limit = HW_MAX if positive else HW_MIN
    sgn = 1.0 if positive else -1.0
    k_lim = next(k for k in range(k0, len(b.trace)) if (b.trace[k][3] - limit) * sgn >= 0.0)
    k_rev = next(k for k in range(k_lim, len(b.trace)) if b.trace[k][2] * sgn <= 0.0)
    overrun = max((s[3] - limit) * sgn for s in b.trace[k_lim:k_rev + 1])
    # braked with Deceleration = 200 (v^2/2a = 6.25), not with EmergencyDeceleration = 1000 (1.25)
    assert overrun > 0.8 * V_APP ** 2 / (2 * 200.0)
    assert peak_deceleration(b, k_lim, k_rev + 1) == pytest.approx(200.0, rel=0.02)
    # searched in the other direction at the approach velocity
    assert min(s[2] * sgn for s in b.trace[k_rev:]) == pytest.approx(-V_APP)
    k_ev = first_homed(b, k0)
    assert b.trace[k_ev - 1][2] == pytest.approx(direction * V_REF)
    assert b.coordinate_of(mark) == pytest.approx(0.0, abs=V_REF * SERVO + PULSE + 1e-9)


@pytest.mark.parametrize("positive,start,error_id", [
    pytest.param(True, 200.0, 0x8004, id="high-limit-16#8004"),
    pytest.param(False, 50.0, 0x8003, id="low-limit-16#8003"),
])
def test_s7_1200_5_4_4_5_hw_limit_without_auto_reversal(positive, start, error_id):
    """§5.4.4.5: without direction reversal, reaching the HW limit switch during active homing aborts homing
    with an error and the axis is braked with the emergency stop deceleration; §12.8 16#8003/16#8004 with
    ErrorInfo 16#000E ('during active homing: homing switch not found'), shown at MC_Home and MC_Power
    (§5.4.4.3)."""
    b = Bench(extra={"Homing.ApproachDirection": positive, "Plant.InitialPosition": start})
    hm, k0 = run_active_homing(b, 0.0)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (error_id, 0x000E), hm.outputs
    b.ctl.step()
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, 0x000E)
    assert b.axis.ErrorBits.HWLimit
    assert not b.axis.StatusBits.HomingDone
    b.until(lambda: b.axis.Velocity == 0.0, 1.0, "standstill")
    limit = HW_MAX if positive else HW_MIN
    sgn = 1.0 if positive else -1.0
    k_lim = next(k for k in range(k0, len(b.trace)) if (b.trace[k][3] - limit) * sgn >= 0.0)
    assert peak_deceleration(b, k_lim, len(b.trace)) == pytest.approx(1000.0, rel=0.02)
    overrun = max((s[3] - limit) * sgn for s in b.trace[k_lim:])
    assert overrun < V_APP ** 2 / (2 * 1000.0) + V_APP * 2 * SERVO + 1e-6


def test_s7_1200_12_8_8009_switch_not_found_between_the_limits():
    """§12.8 16#8009/16#0033 'Reference switch / encoder zero mark not found' (reaction: stop with emergency stop
    ramp); decision #35: with auto reversal, reaching the second HW limit switch gives 16#8009/16#0033.  Here the
    homing switch input never becomes TRUE (no switch in the machine)."""
    b = Bench(extra={"Homing.AutoReversal": True, "Plant.HomingSwitchPosition": None,
                     "Plant.InitialPosition": 250.0})
    hm, k0 = run_active_homing(b, 0.0)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8009, 0x0033), hm.outputs
    b.ctl.step()
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (0x8009, 0x0033)
    b.until(lambda: b.axis.Velocity == 0.0, 1.0, "standstill")
    assert min(s[3] for s in b.trace[k0:]) <= HW_MIN              # it went to the other limit switch
    k_lim = next(k for k in range(k0, len(b.trace)) if b.trace[k][3] <= HW_MIN)
    assert peak_deceleration(b, k_lim, len(b.trace)) == pytest.approx(1000.0, rel=0.02)
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_12_8_8404_0017_auto_reversal_with_hw_limits_disabled():
    """§12.8 16#8404/16#0017 'Direction reversal at HW limit activated although HW limits are disabled'
    (remedy: set <axis>.PositionLimits_HW.Active = TRUE); §5.4.4.5: the HW limit switches must be enabled
    for the reversal.  A block parameter error: only at MC_Home, the axis does not move."""
    b = Bench(extra={"Homing.AutoReversal": True, "PositionLimits_HW.Active": False})
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(2)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8404, 0x0017), hm.outputs
    assert b.axis.Velocity == 0.0
    assert not b.power.Error and b.power.Status


# ---------------------------------------------------------------------------------------------------------
# homing velocities
@pytest.mark.parametrize("path,error_id", [
    ("Homing.ApproachVelocity", 0x8011),
    ("Homing.ReferencingVelocity", 0x8012),
])
def test_s7_1200_12_8_zero_homing_velocity(path, error_id):
    """§12.8 16#8011/16#000A 'approach velocity ... is zero', 16#8012/16#000A 'homing velocity ... is zero':
    operating errors with axis stop, reaction remove enable; shown at MC_Home and MC_Power (§9.6);
    decision #39: checked when active homing starts."""
    b = Bench(extra={path: 0.0})
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(2)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (error_id, 0x000A), hm.outputs
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, 0x000A)
    assert not b.power.Status and not b.axis.StatusBits.Enable       # remove enable
    assert not b.ctl.outputs["Q0.0"]


@pytest.mark.parametrize("approach,referencing,error_id,error_info", [
    pytest.param(150.0, V_REF, 0x8610, 0x0008, id="approach-above-max"),
    pytest.param(V_APP, 150.0, 0x8611, 0x0008, id="homing-above-max"),
    pytest.param(0.5, V_REF, 0x8610, 0x0009, id="approach-below-start-stop"),
    pytest.param(V_APP, 0.5, 0x8611, 0x0009, id="homing-below-start-stop"),
])
def test_s7_1200_12_8_homing_velocity_outside_start_stop_to_max(approach, referencing, error_id, error_info):
    """§5.4.4.5 'Start/stop velocity <= approach (homing) velocity <= maximum velocity'; §12.8
    16#8610/16#8611 with 16#0008 (> maximum velocity) / 16#0009 (< start/stop velocity); configuration
    errors are shown at the triggering instruction and at MC_Power (§9.6); decision #39."""
    b = Bench(extra={"Homing.ApproachVelocity": approach, "Homing.ReferencingVelocity": referencing})
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(2)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (error_id, error_info), hm.outputs
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, error_info)
    assert abs(b.axis.Velocity) <= 1.0 + 1e-9 and not b.axis.StatusBits.HomingDone


# ---------------------------------------------------------------------------------------------------------
# override behaviour of active homing
@pytest.mark.parametrize("kind", ["MC_MoveVelocity", "MC_MoveRelative"])
def test_s7_1200_11_1_3_active_homing_aborts_running_motion(kind):
    """§2.5 'Active homing ... Active traversing motions are aborted'; §11.1.3.1 override response Mode 3:
    aborts MC_MoveVelocity, MC_MoveRelative, ... (the aborted instance shows CommandAborted)."""
    b = Bench()
    if kind == "MC_MoveVelocity":
        mv = b.start(MC_MoveVelocity(), Velocity=-20.0, Direction=0)
    else:
        mv = b.start(MC_MoveRelative(), Distance=-60.0, Velocity=20.0)
    b.steps(20)
    assert mv.Busy
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.ctl.step()
    assert mv.CommandAborted and not mv.Busy, mv.outputs
    assert hm.Busy
    b.until(lambda: not hm.Busy, 30.0, "homing ended")
    assert hm.Done and b.axis.StatusBits.HomingDone


def test_s7_1200_11_1_3_mc_halt_aborts_active_homing():
    """§11.1.3.1 override response Mode 3: can be aborted by MC_Halt (CommandAborted at MC_Home); §12.8
    16#8207/16#0016 remedy 'abort active homing with a motion command (e.g. MC_Halt)'.  The axis stops and is
    not homed (HomingDone was reset at the start, §2.5)."""
    b = Bench()
    b.direct_home(0.0)
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(100)
    assert hm.Busy and abs(b.axis.Velocity) > 0.0
    halt = b.start(MC_Halt())
    b.ctl.step()
    assert hm.CommandAborted and not hm.Busy, hm.outputs
    b.until(lambda: halt.Done, 2.0, "MC_Halt done")
    assert b.axis.Velocity == 0.0
    assert not b.axis.StatusBits.HomingDone
    assert not b.power.Error


@pytest.mark.parametrize("mode", [0, 1, 2])
def test_s7_1200_12_8_8207_0016_other_homing_while_active_homing(mode):
    """§12.8 16#8207/16#0016 'active homing running; another homing method cannot be started'; §11.1.3.1:
    Mode 0/1 do not abort and Mode 2 is not listed as aborting Mode 3.  Active homing goes on."""
    b = Bench()
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.steps(50)
    other = b.start(MC_Home(), Mode=mode, Position=7.0)
    b.ctl.step()
    assert other.Error and (other.ErrorID, other.ErrorInfo) == (0x8207, 0x0016), other.outputs
    assert hm.Busy and not hm.CommandAborted
    b.until(lambda: not hm.Busy, 30.0, "homing ended")
    assert hm.Done
    assert b.coordinate_of(CAM_LO) == pytest.approx(0.0, abs=V_REF * SERVO + PULSE + 1e-9)


def test_s7_1200_11_1_3_active_homing_aborts_passive_homing():
    """§11.1.3.1 override response: Mode 3 aborts an active MC_Home Mode 2 (CommandAborted), and a new Mode 2
    aborts a Mode 2 command."""
    b = Bench()
    p1 = b.start(MC_Home(), Mode=2, Position=1.0)
    b.steps(3)
    assert p1.Busy
    p2 = b.start(MC_Home(), Mode=2, Position=2.0)
    b.ctl.step()
    assert p1.CommandAborted and not p1.Busy and p2.Busy, (p1.outputs, p2.outputs)
    hm = b.start(MC_Home(), Mode=3, Position=0.0)
    b.ctl.step()
    assert p2.CommandAborted and not p2.Busy and hm.Busy, (p2.outputs, hm.outputs)
    b.until(lambda: not hm.Busy, 30.0, "homing ended")
    assert hm.Done and b.coordinate_of(CAM_LO) == pytest.approx(0.0, abs=V_REF * SERVO + PULSE + 1e-9)


# ---------------------------------------------------------------------------------------------------------
# passive homing
PASSIVE_CASES = [
    # ApproachDirection, SideInput, start, distance of MC_MoveRelative, homing mark (machine)
    pytest.param(True, False, 0.0, 150.0, CAM_LO, id="positive-lower"),
    pytest.param(True, True, 0.0, 150.0, CAM_HI, id="positive-upper"),
    pytest.param(False, False, 250.0, -200.0, CAM_LO, id="negative-lower"),
    pytest.param(False, True, 250.0, -200.0, CAM_HI, id="negative-upper"),
]


@pytest.mark.parametrize("positive,upper,start,distance,mark", PASSIVE_CASES)
def test_s7_1200_5_4_4_5_passive_homing_with_move_relative(positive, upper, start, distance, mark):
    """§5.4.4.5 'Sequence - Passive homing': MC_Home Mode 2 makes no motion; the user moves the axis with
    MC_MoveRelative; when the configured side of the switch is reached (in the homing direction, decision
    #34) the current position is set to Position, HomingDone TRUE, MC_Home Done; the travel is not
    cancelled and completes with the corrected axis position (§2.5, §11.1.3.1)."""
    b = Bench(extra={"Homing.ApproachDirection": positive, "Sensor[1].PassiveHoming.SideInput": upper,
                     "Plant.InitialPosition": start})
    hm = b.start(MC_Home(), Mode=2, Position=50.0)
    b.steps(25)
    assert hm.Busy and not hm.Done
    assert b.axis.Velocity == 0.0 and b.axis.drive.mechanical_position() == pytest.approx(start)
    assert not b.axis.StatusBits.HomingDone
    k0 = len(b.trace)
    mr = b.start(MC_MoveRelative(), Distance=distance, Velocity=20.0)
    b.until(lambda: hm.Done or hm.Error or not mr.Busy, 20.0, "passive homing event")
    assert hm.Done, hm.outputs
    assert mr.Busy and not mr.CommandAborted, "the travel previously started is not canceled"
    assert b.axis.StatusBits.HomingDone
    assert hm.ReferenceMarkPosition == pytest.approx(50.0)
    k_ev = first_homed(b, k0)
    assert abs(b.trace[k_ev][3] - mark) < 20.0 * 2 * SERVO + 1e-9
    b.until(lambda: not mr.Busy, 20.0, "MC_MoveRelative ended")
    assert mr.Done and not mr.CommandAborted, mr.outputs
    # the move ends where it was going (machine start + distance), now in the corrected coordinates
    assert b.axis.drive.mechanical_position() == pytest.approx(start + distance, abs=2 * PULSE)
    assert b.coordinate_of(mark) == pytest.approx(50.0, abs=20.0 * SERVO + PULSE + 1e-9)
    assert b.axis.Position == pytest.approx(50.0 + (start + distance - mark), abs=20.0 * SERVO + 2 * PULSE)


def test_s7_1200_5_4_4_5_passive_homing_only_in_the_homing_direction():
    """§5.4.4.5 'Use homing mark via digital input': the input is checked as soon as the axis moves in the
    assigned homing direction; decision #34: while moving, only the configured end crossed in the homing
    direction counts.  Crossing the switch against the homing direction does not home the axis."""
    b = Bench(extra={"Homing.ApproachDirection": True, "Plant.InitialPosition": 250.0})
    hm = b.start(MC_Home(), Mode=2, Position=50.0)
    mr = b.start(MC_MoveRelative(), Distance=-200.0, Velocity=20.0)
    b.until(lambda: not mr.Busy, 20.0, "move ended")
    assert mr.Done
    assert b.axis.drive.mechanical_position() == pytest.approx(50.0, abs=2 * PULSE)
    assert hm.Busy and not hm.Done
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_5_4_4_5_passive_homing_keeps_homingdone_true():
    """§5.4.4.5: 'The tag StatusBits.HomingDone remains TRUE during passive homing if the axis has already been
    homed'; §2.5 lists no reset for passive homing."""
    b = Bench()
    b.direct_home(0.0)
    k0 = len(b.trace)
    hm = b.start(MC_Home(), Mode=2, Position=50.0)
    mr = b.start(MC_MoveRelative(), Distance=150.0, Velocity=20.0)
    b.until(lambda: not mr.Busy, 20.0, "move ended")
    assert hm.Done and hm.ReferenceMarkPosition == pytest.approx(50.0)
    assert all(s[4] for s in b.trace[k0:]), "HomingDone dropped during passive homing"
    assert b.coordinate_of(CAM_LO) == pytest.approx(50.0, abs=20.0 * SERVO + PULSE + 1e-9)


@pytest.mark.parametrize("start,level", [
    pytest.param(0.0, True, id="rising-edge"),
    pytest.param(110.0, False, id="falling-edge"),
])
def test_s7_1200_5_4_4_5_passive_homing_at_standstill_next_edge(start, level):
    """§5.4.4.5 note: 'If passive homing is carried out without an axis motion command (axis at a standstill),
    homing will be executed upon the next rising or falling edge at the homing switch.'  The current position
    becomes Position (decision #34: whatever the side)."""
    b = Bench(extra={"Plant.InitialPosition": start})
    hm = b.start(MC_Home(), Mode=2, Position=50.0)
    b.steps(10)
    assert hm.Busy and not b.axis.StatusBits.HomingDone
    b.ctl.inputs.force("I0.0", level)                    # the switch changes while the axis stands
    b.until(lambda: hm.Done or hm.Error, 0.1, "homed at the edge")
    assert hm.Done, hm.outputs
    assert b.axis.StatusBits.HomingDone
    assert b.axis.Position == pytest.approx(50.0, abs=1e-9)
    assert b.axis.Velocity == 0.0
    assert hm.ReferenceMarkPosition == pytest.approx(50.0)


# ---------------------------------------------------------------------------------------------------------
# input filter (§5.4.4.5 note on the 6.4 ms filter)
def test_s7_1200_5_4_4_5_homing_error_grows_with_filter_time():
    """§5.4.4.5 note: the default filter time of 6.4 ms can result in inaccuracies.  Decision #33: the position
    is latched in the servo cycle in which the filtered input changes, so the error of the homed coordinate is
    homing velocity x (filter time + up to one servo cycle).  PROFIdrive axis (fine encoder, the switch sees the
    continuous load position).  The filter runs from the switch edge (somewhere between two servo cycles), so
    the edge is seen after filter time + [0, 1) servo cycle for any filter time, also the default 6.4 ms
    (issue 8: it was 7.75 ms when the edge was first sampled, then the filter rounded up to whole cycles).
    Filter times at least one servo cycle apart, so that the errors are ordered (two filters less than a
    servo cycle apart may be seen in the same servo cycle)."""
    tol = 1e-4 * V_REF                                   # speed loop and encoder quantisation
    errors, bad = {}, []
    for filt in (0.0, 0.001, 0.002, 0.005, 0.0064, 0.012):
        b = Bench(actor=1, cam_filter=filt)
        hm, _ = run_active_homing(b, 0.0)
        assert hm.Done, (filt, hm.outputs)
        err = 0.0 - b.coordinate_of(CAM_LO)             # the switch edge is homed too late, i.e. too low
        errors[filt] = err
        if not V_REF * filt - tol <= err <= V_REF * (filt + SERVO) + tol:
            bad.append(f"filter {filt * 1000:g} ms: error = velocity x {err / V_REF * 1000:.3f} ms")
    assert not bad, "; ".join(bad)
    values = [errors[f] for f in sorted(errors)]
    assert values == sorted(values) and values[-1] - values[0] > V_REF * 0.01


@pytest.mark.parametrize("length,filt,found", [
    pytest.param(0.2, 0.0064, False, id="4ms-signal-filter-6.4ms"),
    pytest.param(0.2, 0.001, True, id="4ms-signal-filter-1ms"),
    pytest.param(0.075, 0.002, False, id="1.5ms-signal-filter-2ms"),
])
def test_s7_1200_5_4_4_5_short_switch_missed_by_the_filter_passive(length, filt, found):
    """§5.4.4.5 note: 'Depending on the homing velocity and extent of the homing switch, the home position may
    not be detected ... The specified filter time must be less than the duration of the input signal at the
    homing switch.'  The switch is passed at 50 mm/s (0.2 mm: 4 ms, 0.075 mm: 1.5 ms); a signal shorter than
    the filter time is lost (plcmotion.kernel.io, decision #33)."""
    b = Bench(extra={"Plant.HomingSwitchLength": length}, cam_filter=filt)
    hm = b.start(MC_Home(), Mode=2, Position=50.0)
    mr = b.start(MC_MoveRelative(), Distance=150.0, Velocity=50.0)
    b.until(lambda: not mr.Busy, 10.0, "move ended")
    assert mr.Done
    assert b.axis.StatusBits.HomingDone is found
    assert hm.Done is found and hm.Busy is not found


def test_s7_1200_5_4_4_5_short_switch_missed_by_the_filter_active():
    """§5.4.4.5 note (filter longer than the switch signal: the home position may not be detected) with
    §5.4.4.5 'Permit auto reverse': without reversal the search ends at the HW limit switch with
    16#8004/16#000E ('homing switch not found', §12.8)."""
    b = Bench(extra={"Plant.HomingSwitchLength": 0.2}, cam_filter=0.0064)
    hm, _ = run_active_homing(b, 0.0)
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8004, 0x000E), hm.outputs
    assert not b.axis.StatusBits.HomingDone


# ---------------------------------------------------------------------------------------------------------
# zero mark homing (PROFIdrive)
ZM = {"Sensor[1].Interface.Type": 2, "Plant.ZeroMarkOffset": 3.0}


def test_s7_1200_5_4_4_5_zero_mark_homing_exact():
    """§5.4.4.5 'Use zero mark via PROFIdrive telegram' (ActiveHoming.Mode 0): the axis is homed at the encoder
    zero mark in the homing direction; decision #33: zero marks are latched exactly (no input filter).  Zero
    marks every encoder revolution (LeadScrew 10) from machine position 3.0."""
    b = Bench(actor=1, extra=dict(ZM, **{"Sensor[1].ActiveHoming.Mode": 0}), filt=0.0064)
    hm, _ = run_active_homing(b, 42.0)
    assert hm.Done, hm.outputs
    assert b.axis.StatusBits.HomingDone
    q = 10.0 / (2048 * 2 ** 11)
    assert b.coordinate_of(3.0) == pytest.approx(42.0, abs=3 * q)
    assert hm.ReferenceMarkPosition == pytest.approx(42.0)


def test_s7_1200_5_4_4_5_proximity_switch_and_zero_mark_homing_exact():
    """§5.4.4.5 'Use zero mark via PROFIdrive telegram and proximity switch' (Mode 1): after the proximity
    switch is reached and left again in the homing direction, the next zero mark homes the axis.  Switch
    [100, 120], zero marks at 3 + 10k -> homed at 123.0 exactly even with the 6.4 ms input filter."""
    b = Bench(actor=1, extra=dict(ZM, **{"Sensor[1].ActiveHoming.Mode": 1}), filt=0.0064)
    hm, k0 = run_active_homing(b, 0.0)
    assert hm.Done, hm.outputs
    q = 10.0 / (2048 * 2 ** 11)
    assert b.coordinate_of(123.0) == pytest.approx(0.0, abs=3 * q)
    k_ev = first_homed(b, k0)
    assert b.trace[k_ev][3] > CAM_HI


# ---------------------------------------------------------------------------------------------------------
# absolute encoder adjustment (modes 6/7)
ABS = {"Sensor[1].Type": 1, "Sensor[1].Interface.Type": 2, "Sensor[1].Parameter.DeterminableRevolutions": 4096,
       "Plant.InitialPosition": 37.5}


def test_s7_1200_11_1_3_absolute_encoder_adjustment_retentive(tmp_path):
    """§11.1.3.1 Mode 7 (current position set to Position) and Mode 6 (offset by Position); the absolute value
    offset is stored retentively (StatusSensor.AbsEncoderOffset); §2.5 / §9.4: with absolute actual values the
    homed status survives POWER OFF -> ON; decision #52 (state file)."""
    state = str(tmp_path / "retain.json")
    b = Bench(actor=1, extra=ABS, state_file=state)
    assert not b.axis.StatusBits.HomingDone
    assert b.axis.ActualPosition == pytest.approx(37.5, abs=1e-4)       # absolute value without adjustment
    hm = b.start(MC_Home(), Mode=7, Position=500.0)
    b.until(lambda: hm.Done or hm.Error, 0.1, "mode 7")
    assert hm.Done, hm.outputs
    assert b.axis.StatusBits.HomingDone
    assert b.axis.ActualPosition == pytest.approx(500.0, abs=1e-4)
    assert b.axis.StatusSensor.AbsEncoderOffset == pytest.approx(462.5, abs=1e-4)
    hm.Execute = False
    b.ctl.step()
    hm6 = b.start(MC_Home(), Mode=6, Position=-100.0)
    b.until(lambda: hm6.Done or hm6.Error, 0.1, "mode 6")
    assert hm6.Done, hm6.outputs
    assert b.axis.ActualPosition == pytest.approx(400.0, abs=1e-4)
    assert b.axis.StatusSensor.AbsEncoderOffset == pytest.approx(362.5, abs=1e-4)
    mr = b.start(MC_MoveRelative(), Distance=10.0, Velocity=20.0)
    b.until(lambda: mr.Done, 5.0, "move")
    mech = b.axis.drive.mechanical_position()
    assert mech == pytest.approx(47.5, abs=0.05)
    # POWER OFF -> ON: the adjustment and the homed status are kept
    b.ctl.power_cycle()
    b.ctl.step()
    assert b.axis.StatusBits.HomingDone
    assert b.axis.StatusSensor.AbsEncoderOffset == pytest.approx(362.5, abs=1e-4)
    mech = b.axis.drive.mechanical_position()
    assert b.axis.ActualPosition == pytest.approx(mech + 362.5, abs=1e-4)
    # a new controller from the same state file (CPU switched on again)
    b2 = Bench(actor=1, extra=dict(ABS, **{"Plant.InitialPosition": mech}), state_file=state)
    assert b2.axis.StatusBits.HomingDone
    assert b2.axis.StatusSensor.AbsEncoderOffset == pytest.approx(362.5, abs=1e-4)
    assert b2.axis.ActualPosition == pytest.approx(mech + 362.5, abs=1e-4)
    mv = b2.start(MC_MoveAbsolute(), Position=400.0, Velocity=20.0)       # homed: absolute positioning works
    b2.until(lambda: mv.Done or mv.Error, 5.0, "move absolute")
    assert mv.Done, mv.outputs
    assert b2.axis.drive.mechanical_position() == pytest.approx(37.5, abs=0.05)


@pytest.mark.parametrize("mode", [6, 7])
def test_s7_1200_12_8_8404_0055_modes_6_7_on_incremental_encoder(mode):
    """§12.8 16#8404/16#0055 'Invalid mode for incremental encoder (use Mode 0, 1, 2, 3)'; decision #28."""
    b = Bench(actor=1)
    hm = b.start(MC_Home(), Mode=mode, Position=1.0)
    b.ctl.step()
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8404, 0x0055), hm.outputs
    assert not b.axis.StatusBits.HomingDone and not b.power.Error


@pytest.mark.parametrize("mode", [6, 7])
def test_s7_1200_11_1_3_modes_6_7_not_on_pto(mode):
    """§11.1.3.1 'Mode 6 and 7 can only be used with drives with an analog interface and PROFIdrive drive';
    decision #28: PTO gives 16#8404/16#0011."""
    b = Bench()
    hm = b.start(MC_Home(), Mode=mode, Position=1.0)
    b.ctl.step()
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8404, 0x0011), hm.outputs


@pytest.mark.parametrize("mode", [2, 3])
def test_s7_1200_12_8_8404_0056_modes_2_3_on_absolute_encoder(mode, tmp_path):
    """§12.8 16#8404/16#0056 'Invalid mode for absolute encoder (Mode 2/3 impossible; use Mode 0, 1)'."""
    b = Bench(actor=1, extra=ABS, state_file=str(tmp_path / "r.json"))
    hm = b.start(MC_Home(), Mode=mode, Position=1.0)
    b.ctl.step()
    assert hm.Error and (hm.ErrorID, hm.ErrorInfo) == (0x8404, 0x0056), hm.outputs
    assert b.axis.Velocity == 0.0


# ---------------------------------------------------------------------------------------------------------
# §2.5 resetting the "Homed" status
def _disable_enable(b: Bench) -> None:
    b.power.Enable = False
    b.until(lambda: not b.power.Status and not b.power.Busy, 1.0, "disabled")
    b.power.Enable = True
    b.until(lambda: b.power.Status, 1.0, "enabled")


def test_s7_1200_2_5_pto_homed_reset_by_disabling():
    """§2.5 PTO: 'Disabling of axis by the MC_Power Motion Control instruction' resets HomingDone; §11.1.1
    MC_Power Status FALSE: 'PTO: axis not homed'."""
    b = Bench()
    b.direct_home(0.0)
    _disable_enable(b)
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_2_5_pto_homed_reset_by_power_cycle_and_cpu_restart():
    """§2.5 PTO: 'After POWER OFF -> POWER ON of the CPU' and 'After CPU restart (RUN-STOP -> STOP-RUN)'."""
    b = Bench()
    b.direct_home(0.0)
    b.ctl.power_cycle()
    b.ctl.step()
    assert not b.axis.StatusBits.HomingDone
    b.until(lambda: b.power.Status, 1.0, "enabled again")
    b.direct_home(0.0)
    b.ctl.stop()
    b.ctl.start()
    b.ctl.step()
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_2_5_incremental_homed_kept_when_disabled_reset_by_power_cycle():
    """§2.5 'Technology objects with incremental actual values': disabling is not a reset condition (only for
    PTO); 'After POWER OFF -> POWER ON of the CPU' resets HomingDone."""
    b = Bench(actor=1)
    b.direct_home(0.0)
    _disable_enable(b)
    assert b.axis.StatusBits.HomingDone
    b.ctl.power_cycle()
    b.ctl.step()
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_2_5_incremental_homed_reset_by_to_restart():
    """§2.5 incremental actual values: 'Restart of the technology object' (§9.7: MC_Reset with Restart = TRUE,
    axis disabled) resets HomingDone."""
    b = Bench(actor=1)
    b.direct_home(0.0)
    b.power.Enable = False
    b.until(lambda: not b.power.Status and not b.power.Busy, 1.0, "disabled")
    assert b.axis.StatusBits.HomingDone
    rs = b.start(MC_Reset(), Restart=True)
    b.until(lambda: rs.Done or rs.Error, 0.1, "restart")
    assert rs.Done, rs.outputs
    assert not b.axis.StatusBits.HomingDone


def test_s7_1200_2_5_absolute_homed_kept(tmp_path):
    """§2.5 'Technology objects with absolute actual values': the reset conditions are encoder errors, CPU
    replacement, encoder configuration change, factory settings, another project -- not disabling, TO restart
    or POWER OFF -> ON (§9.4: 'With an absolute encoder the homed status survives POWER OFF')."""
    b = Bench(actor=1, extra=ABS, state_file=str(tmp_path / "r.json"))
    hm = b.start(MC_Home(), Mode=7, Position=0.0)
    b.until(lambda: hm.Done, 0.1, "mode 7")
    b.power.Enable = False
    b.until(lambda: not b.power.Status and not b.power.Busy, 1.0, "disabled")
    assert b.axis.StatusBits.HomingDone
    rs = b.start(MC_Reset(), Restart=True)
    b.until(lambda: rs.Done or rs.Error, 0.1, "restart")
    assert rs.Done and b.axis.StatusBits.HomingDone
    b.ctl.power_cycle()
    b.ctl.step()
    assert b.axis.StatusBits.HomingDone
    assert b.axis.ActualPosition == pytest.approx(0.0, abs=1e-4)
