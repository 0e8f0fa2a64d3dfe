"""Hardware limit switches of the S7-1200 V6 positioning axis, derived from the function manual.

Manual sections (S7-1200 Motion Control V6.0, seeds/000):
  §2.3, §5.4.4.3  requirements (switches stay actuated beyond the limit), 'Select level' (low level = NC
                  contact: 0 V = approached; high level = NO contact), 'Behavior of axis when hardware limit
                  switches are approached' (PROFIdrive/analog: axis disabled; PTO: braked to standstill with
                  the emergency deceleration; error at the initiating instruction, at MC_Power and in the TO
                  tags), runtime change of PositionLimits_HW.Active
  §10.1, §12.9.23/24  StatusBits.HWLimitMinActive/HWLimitMaxActive, ErrorBits.HWLimit
  §12.8           16#8003/16#8004 (16#000E, PTO: stop with emergency ramp, PD/AQ: remove enable; acknowledge
                  and move out in the opposite direction), 16#800E/16#0042 (illegal free-travel direction),
                  16#0043 (polarity reversed), 16#0044 (both switches active), reaction remove enable
  §11.1.1.1       auto re-enable after acknowledgement while Enable stayed TRUE
Project decisions (docs/decisions.md): #25 (ErrorBits.HWLimit for 16#8003/16#8004/16#800E), #36 (16#0043
when a switch is approached while moving away from it), #37 (an axis on a HW limit switch may be enabled;
only the free direction can be commanded).

Simulated machine: low HW limit switch actuated at and below machine position -200, high one at and above
300 (``Plant.HWLimitMinPosition``/``HWLimitMaxPosition``); inputs I0.1 (low) and I0.2 (high).
"""
from __future__ import annotations

from typing import Any

import pytest

from _fb_program import FbProgram
from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_Reset

SERVO, APP = 0.001, 0.004
HW_MIN, HW_MAX = -200.0, 300.0
EMERGENCY, DECEL = 1000.0, 200.0


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
        "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": DECEL, "Jerk": 0.0,
                            "EmergencyDeceleration": EMERGENCY},
        "PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.1", "MaxSwitchAddress": "I0.2",
                              "MinSwitchLevel": False, "MaxSwitchLevel": False},
        "Actor.Interface": {"DriveReadyInput": "", "EnableDriveOutput": "Q0.0"},
        "Plant": {"InitialPosition": 0.0, "HWLimitMinPosition": HW_MIN, "HWLimitMaxPosition": HW_MAX},
    }
    cfg = _flat(base)
    cfg.update(_flat(extra or {}))
    return cfg


class Bench(FbProgram):
    """A controller with one axis and a program that calls every added instance once per application cycle;
    a post-servo hook samples (t, Position, Velocity, machine position) every servo cycle."""

    def __init__(self, actor: int = 2, extra: dict | None = None, *, filt: float = 0.0, enable: bool = True):
        ctl = Controller(servo_cycle=SERVO, app_cycle=APP, input_filter=filt, state_file=None)
        self.trace: list[tuple[float, float, float, float]] = []
        super().__init__(ctl, ctl.add_positioning_axis("Axis_1", config(actor, extra)), MC_Power(Enable=enable),
                         enable=enable, sample=self._sample)

    def _sample(self, t: float) -> None:
        ax = self.axis
        self.trace.append((t, ax.Position, ax.Velocity, ax.drive.mechanical_position()))

    def reset(self) -> MC_Reset:
        return self.finish(self.start(MC_Reset()), 0.1, "MC_Reset ended")


def peak_deceleration(b: Bench, k_from: int) -> float:
    """Largest speed decrease per servo cycle from trace index ``k_from`` on (jerk 0: the deceleration used;
    the PTO step from the start/stop velocity to 0 is left out)."""
    best = 0.0
    for k in range(k_from, len(b.trace) - 1):
        v0, v1 = b.trace[k][2], b.trace[k + 1][2]
        if abs(v1) < abs(v0) and v0 * v1 > 0.0:
            best = max(best, (abs(v0) - abs(v1)) / SERVO)
    return best


SIDES = [
    # side, start (machine), velocity towards the switch, ErrorID, StatusBits tag
    pytest.param("max", 250.0, +50.0, 0x8004, "HWLimitMaxActive", id="high"),
    pytest.param("min", -150.0, -50.0, 0x8003, "HWLimitMinActive", id="low"),
]


def drive_into_switch(b: Bench, velocity: float) -> tuple[MC_MoveVelocity, int]:
    k0 = len(b.trace)
    mv = b.start(MC_MoveVelocity(), Velocity=velocity, Direction=0)
    b.until(lambda: mv.Error or not mv.Busy, 5.0, "HW limit error")
    return mv, k0


# ---------------------------------------------------------------------------------------------------------
# reaction when a HW limit switch is approached
@pytest.mark.parametrize("side,start,velocity,error_id,status_bit", SIDES)
def test_s7_1200_5_4_4_3_pto_hw_limit_emergency_stop_axis_stays_enabled(side, start, velocity, error_id, status_bit):
    """§5.4.4.3 'Drive connection via PTO': when the hardware limit switch is approached the axis brakes to a
    standstill at the configured emergency deceleration; the error 'HW limit switch approached' is shown at
    the initiating instruction, at MC_Power and in the TO tags; §12.8 16#8003/16#8004 with 16#000E, PTO
    reaction 'stop with emergency stop ramp' (the enable stays); StatusBits.HWLimit*Active, ErrorBits.HWLimit."""
    b = Bench(extra={"Plant.InitialPosition": start})
    limit = HW_MAX if side == "max" else HW_MIN
    sgn = 1.0 if velocity > 0 else -1.0
    mv, k0 = drive_into_switch(b, velocity)
    assert mv.Error and (mv.ErrorID, mv.ErrorInfo) == (error_id, 0x000E), mv.outputs
    b.until(lambda: b.axis.Velocity == 0.0, 1.0, "standstill")
    b.steps(2)
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, 0x000E)
    assert b.power.Status and b.axis.StatusBits.Enable and b.ctl.outputs["Q0.0"], "PTO: no remove enable"
    assert getattr(b.axis.StatusBits, status_bit)
    assert b.axis.ErrorBits.HWLimit and b.axis.StatusBits.Error
    k_lim = next(k for k in range(k0, len(b.trace)) if (b.trace[k][3] - limit) * sgn >= 0.0)
    assert peak_deceleration(b, k_lim) == pytest.approx(EMERGENCY, rel=0.02)
    overrun = (b.axis.drive.mechanical_position() - limit) * sgn
    assert 0.0 < overrun <= 50.0 ** 2 / (2 * EMERGENCY) + 50.0 * 2 * SERVO + 0.02


@pytest.mark.parametrize("actor", [1, 0], ids=["PROFIdrive", "analog"])
@pytest.mark.parametrize("side,start,velocity,error_id,status_bit", SIDES)
def test_s7_1200_5_4_4_3_servo_hw_limit_removes_enable(actor, side, start, velocity, error_id, status_bit):
    """§5.4.4.3 'Drive connection via PROFIdrive / analog output': when a hardware limit switch is approached
    the axis is disabled and braked by the drive; §12.8 16#8003/16#8004 reaction PD/AQ 'remove enable':
    MC_Power.Status FALSE, the drive enable output FALSE; error at the instruction and at MC_Power."""
    b = Bench(actor, extra={"Plant.InitialPosition": start})
    mv, _ = drive_into_switch(b, velocity)
    assert mv.Error and (mv.ErrorID, mv.ErrorInfo) == (error_id, 0x000E), mv.outputs
    b.steps(2)
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, 0x000E)
    assert not b.power.Status and not b.axis.StatusBits.Enable
    assert not b.ctl.outputs["Q0.0"]
    assert getattr(b.axis.StatusBits, status_bit) and b.axis.ErrorBits.HWLimit
    b.steps(100)                                    # the drive brakes by itself and stays on the switch
    limit = HW_MAX if side == "max" else HW_MIN
    assert (b.axis.drive.mechanical_position() - limit) * (1 if velocity > 0 else -1) >= 0.0
    assert not b.power.Status


def test_s7_1200_5_4_4_3_hw_limit_error_at_the_initiating_instruction():
    """§5.4.4.3: 'The HW limit switch approached error is displayed in the initiating Motion Control
    instruction, at MC_Power, and in the technology object variables' (here MC_MoveRelative)."""
    b = Bench(1, extra={"Plant.InitialPosition": 280.0})
    mr = b.start(MC_MoveRelative(), Distance=50.0, Velocity=40.0)
    b.until(lambda: not mr.Busy, 5.0, "move ended")
    assert mr.Error and (mr.ErrorID, mr.ErrorInfo) == (0x8004, 0x000E), mr.outputs
    b.ctl.step()
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x8004, 0x000E)


# ---------------------------------------------------------------------------------------------------------
# freeing the axis
@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
@pytest.mark.parametrize("side,start,velocity,error_id,status_bit", SIDES)
def test_s7_1200_12_8_free_only_in_the_opposite_direction(actor, side, start, velocity, error_id, status_bit):
    """§12.8 16#8003/16#8004 remedy: acknowledge, then move out of the limit in the opposite direction;
    16#800E/16#0042 'illegal free-travel direction with active HW limit switch' (reaction remove enable);
    §5.4.4.3 the switch stays actuated until the axis is back in the valid range; §11.1.1.1 auto re-enable
    after MC_Reset while Enable stayed TRUE; decision #37."""
    b = Bench(actor, extra={"Plant.InitialPosition": start})
    drive_into_switch(b, velocity)
    b.until(lambda: b.axis.Velocity == 0.0, 1.0, "standstill")
    b.steps(30)
    rs = b.reset()
    assert not b.axis.StatusBits.Error, rs.outputs
    b.until(lambda: b.power.Status and not b.power.Error, 0.5, "enabled after acknowledgement")
    assert getattr(b.axis.StatusBits, status_bit), "still on the switch"
    assert not b.axis.ErrorBits.HWLimit
    sgn = 1.0 if velocity > 0 else -1.0
    # further into the switch: refused
    bad = b.start(MC_MoveRelative(), Distance=5.0 * sgn, Velocity=10.0)
    b.until(lambda: bad.Error or not bad.Busy, 1.0, "wrong direction refused")
    assert bad.Error and (bad.ErrorID, bad.ErrorInfo) == (0x800E, 0x0042), bad.outputs
    b.steps(2)
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x800E, 0x0042)
    assert not b.power.Status and not b.ctl.outputs["Q0.0"], "16#800E: remove enable"
    assert b.axis.ErrorBits.HWLimit
    assert (b.axis.drive.mechanical_position() - (HW_MAX if side == "max" else HW_MIN)) * sgn < 5.0
    # acknowledge again, free the axis in the opposite direction
    b.reset()
    b.until(lambda: b.power.Status and not b.power.Error, 0.5, "enabled again")
    good = b.start(MC_MoveRelative(), Distance=-20.0 * sgn, Velocity=10.0)
    b.until(lambda: not good.Busy, 5.0, "freed")
    assert good.Done, good.outputs
    assert not getattr(b.axis.StatusBits, status_bit)
    assert not b.axis.StatusBits.Error and not b.power.Error


def test_s7_1200_12_8_800E_0044_both_switches_active():
    """§12.8 16#800E/16#0044 'Both HW limit switches active; axis cannot be freed', reaction remove enable.
    Both NC contacts open at once (low level = approached, §5.4.4.3)."""
    b = Bench(1)
    b.ctl.inputs.force("I0.1", False)
    b.ctl.inputs.force("I0.2", False)
    b.steps(3)
    assert b.axis.StatusBits.HWLimitMinActive and b.axis.StatusBits.HWLimitMaxActive
    assert b.axis.ErrorBits.HWLimit
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (0x800E, 0x0044), b.power.outputs
    assert not b.power.Status and not b.ctl.outputs["Q0.0"]
    # acknowledged, the axis still cannot be freed in either direction
    for distance in (10.0, -10.0):
        b.reset()
        b.until(lambda: b.power.Status or b.power.Error, 0.5, "re-enabled")
        mr = b.start(MC_MoveRelative(), Distance=distance, Velocity=10.0)
        b.until(lambda mr=mr: not mr.Busy, 1.0, "refused")
        assert mr.Error and (mr.ErrorID, mr.ErrorInfo) == (0x800E, 0x0044), (distance, mr.outputs)


def test_s7_1200_decision_36_800E_0043_switch_approached_while_moving_away():
    """§12.8 16#800E/16#0043 'HW limit switch polarity reversed; axis cannot be freed', reaction remove
    enable; decision #36: a HW limit switch that becomes actuated while the axis moves away from it."""
    b = Bench(1)
    mv = b.start(MC_MoveVelocity(), Velocity=30.0, Direction=0)
    b.until(lambda: mv.InVelocity, 1.0, "moving positive")
    b.ctl.inputs.force("I0.1", False)                 # the LOW limit switch reports 'approached'
    b.until(lambda: mv.Error or not mv.Busy, 0.1, "error")
    assert (mv.ErrorID, mv.ErrorInfo) == (0x800E, 0x0043), mv.outputs
    b.steps(2)
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x800E, 0x0043)
    assert not b.power.Status and not b.ctl.outputs["Q0.0"]


# ---------------------------------------------------------------------------------------------------------
# enabling the switches, levels
@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
def test_s7_1200_5_4_4_3_hw_limits_ignored_when_not_active(actor):
    """§5.4.4.3 'Enable HW limit switches' (PositionLimits_HW.Active = FALSE): the switches have no function;
    the axis passes them without error and the status bits stay FALSE."""
    b = Bench(actor, extra={"PositionLimits_HW.Active": False, "Plant.InitialPosition": 280.0})
    mr = b.start(MC_MoveRelative(), Distance=40.0, Velocity=40.0)
    b.until(lambda: not mr.Busy, 5.0, "move ended")
    assert mr.Done, mr.outputs
    assert b.axis.drive.mechanical_position() == pytest.approx(320.0, abs=0.05)
    assert not b.ctl.inputs["I0.2"]                    # the NC contact is open ...
    assert not b.axis.StatusBits.HWLimitMaxActive      # ... but the function is off
    assert not b.axis.ErrorBits.HWLimit and not b.power.Error and b.power.Status


@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
def test_s7_1200_5_4_4_3_hw_limits_deactivated_at_runtime(actor):
    """§5.4.4.3 'Changing the configuration of the position limits in the user program': the HW limit
    switches can be deactivated at runtime with <axis>.PositionLimits_HW.Active (RW)."""
    b = Bench(actor, extra={"Plant.InitialPosition": 280.0})
    b.axis.PositionLimits_HW.Active = False
    b.ctl.step()
    mr = b.start(MC_MoveRelative(), Distance=40.0, Velocity=40.0)
    b.until(lambda: not mr.Busy, 5.0, "move ended")
    assert mr.Done, mr.outputs
    assert not b.axis.ErrorBits.HWLimit and not b.power.Error


def test_s7_1200_5_4_4_3_low_level_nc_contact():
    """§5.4.4.3 'Select level': 'Low level' (normally closed contact): 0 V (FALSE) at the CPU input = hardware
    limit switch approached.  Inside the travel range the inputs are TRUE; a broken wire (0 V) counts as
    approached."""
    b = Bench()
    assert b.ctl.inputs["I0.1"] and b.ctl.inputs["I0.2"]
    assert not b.axis.StatusBits.HWLimitMinActive and not b.axis.StatusBits.HWLimitMaxActive
    b.ctl.inputs.force("I0.1", False)                  # wire of the low limit switch broken
    b.steps(3)
    assert b.axis.StatusBits.HWLimitMinActive
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x8003, 0x000E)


def test_s7_1200_5_4_4_3_high_level_no_contact():
    """§5.4.4.3 'Select level': 'High level' (normally open contact): TRUE at the CPU input = approached.
    Inside the travel range the inputs are FALSE; the switch reached by the load sets the input."""
    b = Bench(extra={"PositionLimits_HW.MinSwitchLevel": True, "PositionLimits_HW.MaxSwitchLevel": True,
                     "Plant.InitialPosition": 250.0})
    assert not b.ctl.inputs["I0.1"] and not b.ctl.inputs["I0.2"]
    assert not b.axis.StatusBits.HWLimitMaxActive and not b.power.Error
    mv, _ = drive_into_switch(b, 50.0)
    assert (mv.ErrorID, mv.ErrorInfo) == (0x8004, 0x000E), mv.outputs
    assert b.ctl.inputs["I0.2"] and b.axis.StatusBits.HWLimitMaxActive


def test_s7_1200_5_4_4_3_status_bits_follow_the_switch_without_error_bits_after_reset():
    """§10.1 / §12.9.23: StatusBits.HWLimitMaxActive 'high HW limit reached or exceeded' while the switch is
    actuated; ErrorBits.HWLimit (§12.9.24) only while the error is pending."""
    b = Bench(1, extra={"Plant.InitialPosition": 250.0})
    assert not b.axis.StatusBits.HWLimitMaxActive
    drive_into_switch(b, 50.0)
    b.steps(30)
    assert b.axis.StatusBits.HWLimitMaxActive and b.axis.ErrorBits.HWLimit
    b.reset()
    assert b.axis.StatusBits.HWLimitMaxActive and not b.axis.ErrorBits.HWLimit
