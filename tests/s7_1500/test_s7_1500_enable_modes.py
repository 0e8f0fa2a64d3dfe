"""MC_Power of the S7-1500 (issue 8, manual points): StartMode 0 on a simulated axis, and the position of an
unhomed axis that is enabled again.

Manual: S7-1500T synchronous operation V5 (seeds/001) §A.1.37 StatusWord bit 28 NonPositionControlled, §7.1.1
"position-controlled mode" = inversion of X28, §3.3.5 a setpoint-coupled job waits for a position-controlled
leading axis, §7.1.2 ActualPosition of an unhomed axis, §9.1.1 "the following axis follows the leading axis
during the braking ramp and after the leading axis is enabled again"; catalog s7-1500-sync.md §1.6, §7.
"""
from __future__ import annotations

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import MC_GearIn, MC_Home, MC_MoveRelative, MC_MoveVelocity, MC_Power

DYN = {"DynamicDefaults": {"Velocity": 100.0, "Acceleration": 500.0, "Deceleration": 500.0, "Jerk": 0.0,
                           "EmergencyDeceleration": 2000.0},
       "DynamicLimits": {"MaxVelocity": 500.0, "Velocity": 500.0, "MaxAcceleration": 5000.0, "MaxDeceleration": 5000.0}}
SIMULATED = {"Simulation": {"Mode": 1}, **DYN}
VIRTUAL = {"VirtualAxis": {"Mode": 1}, **DYN}


class Bench:
    def __init__(self, leader: dict, *, follower: bool = False, start_mode: int = 1):
        self.ctl = Controller(family="S7-1500T", servo_cycle=0.001, app_cycle=0.004)
        self.lead = self.ctl.add_positioning_axis("Lead", leader)
        self.fol = (self.ctl.add_synchronous_axis("Fol", VIRTUAL, leading_values=["Lead"]) if follower else None)
        self.p_lead, self.p_fol = MC_Power(), MC_Power()
        self.enable, self.start_mode = True, start_mode
        self.steps: list = []
        self.rows: list[tuple[float, float, float]] = []
        self.ctl.program(self._main)
        self.ctl.run_until(lambda: self.p_lead.Status and (self.fol is None or self.p_fol.Status), timeout=1.0)

    def _main(self) -> None:
        self.p_lead(Axis=self.lead, Enable=self.enable, StartMode=self.start_mode, StopMode=0)
        if self.fol is not None:
            self.p_fol(Axis=self.fol, Enable=True)
        for step in self.steps:
            step()
        self.rows.append((self.ctl.time, self.lead.Position,
                          self.fol.Position if self.fol is not None else 0.0))


def test_s7_1500_A_1_37_simulated_axis_start_mode_0_runs_without_position_control():
    """§A.1.37 X28 NonPositionControlled: MC_Power(StartMode=0) on a simulated axis (Simulation.Mode 1) enables
    it without position control, as on the real drive it simulates; StartMode 1 enables it position-controlled."""
    b = Bench(SIMULATED, start_mode=0)
    assert b.lead.StatusWord.X0
    assert b.lead.StatusWord.X28, "StartMode 0: the simulated axis must not be position-controlled"
    b2 = Bench(SIMULATED, start_mode=1)
    assert b2.lead.StatusWord.X0 and not b2.lead.StatusWord.X28


def test_s7_1500_A_1_37_simulated_axis_velocity_without_position_control_keeps_x28_positioning_clears_it():
    """MC_MoveVelocity(PositionControlled=FALSE) keeps the simulated axis non-position-controlled (X28 TRUE);
    a positioning job switches it to position control (X28 FALSE), as on an axis with a drive."""
    b = Bench(SIMULATED, start_mode=0)
    mv, rel = MC_MoveVelocity(), MC_MoveRelative()
    b.steps.append(lambda: mv(Axis=b.lead, Execute=True, Velocity=50.0, PositionControlled=False))
    b.ctl.run_until(lambda: mv.InVelocity, timeout=2.0)
    assert b.lead.StatusWord.X28 and b.lead.Velocity == pytest.approx(50.0)
    b.steps.append(lambda: rel(Axis=b.lead, Execute=True, Distance=10.0))
    b.ctl.run_until(lambda: rel.Done or rel.Error, timeout=2.0)
    assert rel.Done, rel.outputs
    assert not b.lead.StatusWord.X28


def test_s7_1500_3_3_5_setpoint_coupling_waits_for_a_simulated_leader_enabled_with_start_mode_0():
    """§3.3.5: with setpoint coupling MC_GearIn waits while the leading axis is not position-controlled - also
    when the leading axis is simulated and was enabled with StartMode 0; it starts once the leader is
    position-controlled (here by a positioning job)."""
    b = Bench(SIMULATED, follower=True, start_mode=0)
    gear, rel = MC_GearIn(), MC_MoveRelative()
    b.steps.append(lambda: gear(Master=b.lead, Slave=b.fol, Execute=True, RatioNumerator=1, RatioDenominator=1))
    b.ctl.run(0.1)
    assert gear.Busy and not gear.InGear and not b.fol.StatusWord.X21 and not b.fol.StatusWord.X22
    b.steps.append(lambda: rel(Axis=b.lead, Execute=True, Distance=5.0))
    b.ctl.run_until(lambda: gear.InGear or gear.Error, timeout=2.0)
    assert gear.InGear, gear.outputs


@pytest.mark.parametrize("leader", [VIRTUAL, SIMULATED], ids=["virtual", "simulated"])
def test_s7_1500_7_1_2_reenabled_unhomed_leader_keeps_its_position_and_the_follower_sees_no_step(leader):
    """Decision (issue 8): re-enabling an unhomed S7-1500 axis does not reset its position.  §9.1.1 says a
    geared follower follows its leading axis through the braking ramp and after the leader is enabled again;
    a position reset would be a leading value step the follower takes at once.  The follower's setpoint must
    change per servo cycle by no more than the leader's velocity limit allows."""
    b = Bench(leader, follower=True)
    gear, rel = MC_GearIn(), MC_MoveRelative()
    b.steps.append(lambda: gear(Master=b.lead, Slave=b.fol, Execute=True, RatioNumerator=1, RatioDenominator=1))
    b.steps.append(lambda: rel(Axis=b.lead, Execute=gear.InGear, Distance=120.0))
    b.ctl.run_until(lambda: rel.Done, timeout=5.0)
    assert not b.lead.StatusWord.X5                       # not homed
    before = b.lead.Position
    assert before == pytest.approx(120.0)
    b.enable = False
    b.ctl.run_until(lambda: not b.p_lead.Status, timeout=2.0)
    b.ctl.run(0.05)
    b.enable = True
    b.ctl.run_until(lambda: b.p_lead.Status, timeout=2.0)
    b.ctl.run(0.05)
    assert gear.InGear, "disabling the leading axis does not end the gearing (§9.1.1)"
    assert b.lead.Position == pytest.approx(before)
    assert b.fol.Position == pytest.approx(before)
    f = np.array([r[2] for r in b.rows])
    # one application cycle of the leader's maximum velocity: the follower never jumps further
    assert np.abs(np.diff(f)).max() <= 500.0 * 0.004 + 1e-9


def test_s7_1500_7_1_2_homed_axis_and_first_enable_unchanged():
    """The first enable still starts an unhomed axis at 0; a homed axis keeps its position (both as before)."""
    b = Bench(VIRTUAL)
    assert b.lead.Position == 0.0 and b.lead.ActualPosition == 0.0
    home = MC_Home()
    b.steps.append(lambda: home(Axis=b.lead, Execute=True, Mode=0, Position=42.0))
    b.ctl.run_until(lambda: home.Done, timeout=1.0)
    b.enable = False
    b.ctl.run_until(lambda: not b.p_lead.Status, timeout=1.0)
    b.enable = True
    b.ctl.run_until(lambda: b.p_lead.Status, timeout=1.0)
    assert b.lead.StatusWord.X5 and b.lead.Position == pytest.approx(42.0)

