"""The limit switches component (``kernel.limit_switches.LimitSwitches``): alone on a fake axis, then on a
kernel ``Controller`` axis driven by kernel jobs (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §5.4.4.3 "Position limits" (switches stay
actuated beyond their position; 'Select level': low level = NC contact, 0 V means approached; high level =
NO contact; PTO axes brake with the emergency deceleration and stay enabled, PROFIdrive/analog axes lose
their enable), §5.4.3.1 (simulation: switches have no effect), §5.4.4.2 (modulo range), §12.8 16#8003 /
16#8004 (low/high switch reached), 16#800E/16#0042 (illegal free travel direction), 16#0043 (polarity
reversed), 16#0044 (both switches active), 16#800B/16#0039, 16#003A, 16#003B (actual value range).
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.drives.spec import DriveSpec, EncoderKind, EncoderSpec
from plcmotion.kernel import faults as F
from plcmotion.kernel.axis_config import HardwareLimits, Modulo
from plcmotion.kernel.faults import Reaction
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.limit_switches import LimitSwitches
from plcmotion.kernel.profiles import Planner


# --- the component alone --------------------------------------------------------------------------------
class FakeDrive:
    def __init__(self) -> None:
        self.mech = 0.0

    def mechanical_position(self) -> float:
        return self.mech


class FakeAxis:
    """A LimitSwitchHost: an enabled drive axis moving at ``v`` with switches on I0.1 (low) and I0.2 (high)."""

    def __init__(self, *, active_high: bool = True, enabled: bool = True, pto: bool = False, sim: bool = False,
                 encoder: EncoderSpec | None = None, modulo: Modulo | None = None, v: float = 0.0):
        hw = HardwareLimits(enabled=enabled, min_input="I0.1", max_input="I0.2",
                            min_active_high=active_high, max_active_high=active_high)
        self.config = SimpleNamespace(hardware_limits=hw, modulo=modulo or Modulo(),
                                      drive=DriveSpec(encoder=encoder or EncoderSpec()))
        self.ctl = SimpleNamespace(inputs={"I0.1": not active_high, "I0.2": not active_high},
                                   bank=SimpleNamespace(sp_v=np.array([v])))
        self.index = 0
        self.drive = FakeDrive()
        self.state = "enabled"
        self.job: Job | None = None
        self.pto, self.sim = pto, sim
        self.servo = not pto and not sim
        self.alarms: list[F.Fault] = []
        self.homing_reverses = False

    def raise_alarm(self, fault, job=None):
        self.alarms.append(fault)

    def _homing_hw_limit(self, side, t):
        return self.homing_reverses


def approach(ax: FakeAxis, side: str, switches: LimitSwitches, active_high: bool = True) -> None:
    ax.ctl.inputs["I0.1" if side == "min" else "I0.2"] = active_high
    switches.check(0.0)


@pytest.mark.parametrize("active_high", [True, False], ids=["NO contact", "NC contact"])
def test_kernel_limit_switches_level_selects_what_counts_as_approached(active_high):
    """S7-1200 V6 §5.4.4.3 'Select level': high level (NO contact) = TRUE at the input is approached, low
    level (NC contact) = 0 V (FALSE) is approached."""
    ax = FakeAxis(active_high=active_high, v=-10.0)
    switches = LimitSwitches(ax)
    switches.check(0.0)
    assert switches.approached == {"min": False, "max": False} and not ax.alarms
    approach(ax, "min", switches, active_high)
    assert switches.approached == {"min": True, "max": False}


@pytest.mark.parametrize("pto, reaction", [(False, Reaction.REMOVE_ENABLE), (True, Reaction.EMERGENCY)],
                         ids=["drive", "PTO"])
@pytest.mark.parametrize("side, v, kind", [("min", -10.0, F.HW_LIMIT_MIN), ("max", 10.0, F.HW_LIMIT_MAX)])
def test_kernel_limit_switches_reaching_a_switch_stops_the_axis(pto, reaction, side, v, kind):
    """S7-1200 V6 §12.8 16#8003/16#8004: PTO - stop with the emergency stop ramp; PROFIdrive/analog -
    remove enable."""
    ax = FakeAxis(pto=pto, v=v)
    switches = LimitSwitches(ax)
    approach(ax, side, switches)
    assert [(a.kind, a.reaction) for a in ax.alarms] == [(kind, reaction)]
    switches.check(0.001)                       # still actuated: one alarm per approach, not per cycle
    assert len(ax.alarms) == 1


def test_kernel_limit_switches_both_switches_cannot_be_freed():
    """S7-1200 V6 §12.8 16#800E/16#0044: both hardware limit switches active, remove enable."""
    ax = FakeAxis(v=5.0)
    switches = LimitSwitches(ax)
    ax.ctl.inputs.update({"I0.1": True, "I0.2": True})
    switches.check(0.0)
    assert [(a.kind, a.detail, a.reaction) for a in ax.alarms] == [(F.HW_LIMIT_FREE, "both", Reaction.REMOVE_ENABLE)]


def test_kernel_limit_switches_switch_reached_while_moving_away_means_swapped_switches():
    """S7-1200 V6 §12.8 16#800E/16#0043: polarity of the switches reversed (the low switch answers while
    the axis moves up), remove enable."""
    ax = FakeAxis(v=+10.0)
    switches = LimitSwitches(ax)
    approach(ax, "min", switches)
    assert [(a.kind, a.detail) for a in ax.alarms] == [(F.HW_LIMIT_FREE, "polarity")]


def test_kernel_limit_switches_only_the_free_direction_may_be_commanded():
    """S7-1200 V6 §12.8 16#800E/16#0042: on an actuated low switch a motion down is an illegal free travel
    direction; a motion up frees the axis."""
    ax = FakeAxis(v=-10.0)
    switches = LimitSwitches(ax)
    approach(ax, "min", switches)
    down, up = Planner.cruise(0.0, 0.0, -1.0), Planner.cruise(0.0, 0.0, 1.0)
    fault = switches.direction_fault(down, 0.0)
    assert (fault.kind, fault.detail, fault.reaction) == (F.HW_LIMIT_FREE, "wrong_direction", Reaction.REMOVE_ENABLE)
    assert switches.direction_fault(up, 0.0) is None


def test_kernel_limit_switches_inactive_simulated_or_disabled_axis():
    """S7-1200 V6 §5.4.4.3 'Enable HW limit switches' off: no effect; §5.4.3.1 simulation: the switches have
    no effect; a disabled axis shows the switch (StatusBits.HWLimitMinActive) but has nothing to stop."""
    for ax in (FakeAxis(enabled=False, v=-1.0), FakeAxis(sim=True, v=-1.0)):
        switches = LimitSwitches(ax)
        approach(ax, "min", switches)
        assert switches.approached["min"] is False and not ax.alarms
    ax = FakeAxis(v=0.0)
    ax.state = "disabled"
    switches = LimitSwitches(ax)
    approach(ax, "min", switches)
    assert switches.approached["min"] is True and not ax.alarms


def test_kernel_limit_switches_active_homing_may_reverse_at_a_switch():
    """S7-1200 V6 §5.4.4.3: the hardware limit switches can reverse the direction during homing (§5.4.4.5
    auto reversal); the homing decides, and when it reverses there is no alarm."""
    ax = FakeAxis(v=-10.0)
    ax.job = Job(JobKind.HOME_ACTIVE)
    ax.homing_reverses = True
    switches = LimitSwitches(ax)
    approach(ax, "min", switches)
    assert not ax.alarms
    ax2 = FakeAxis(v=-10.0)
    ax2.job = Job(JobKind.HOME_ACTIVE)
    switches2 = LimitSwitches(ax2)
    approach(ax2, "min", switches2)
    assert [a.kind for a in ax2.alarms] == [F.HW_LIMIT_MIN]


def test_kernel_limit_switches_absolute_encoder_range():
    """S7-1200 V6 §12.8 16#800B: range violation in positive (16#0039) / negative (16#003A) direction of an
    absolute encoder: 8 determinable revolutions of 10 mm span [0, 80) mm; remove enable."""
    enc = EncoderSpec(kind=EncoderKind.ABSOLUTE, distance_per_revolution=10.0, determinable_revolutions=8)
    for mech, detail in ((79.9, None), (80.0, "positive"), (-0.1, "negative")):
        ax = FakeAxis(encoder=enc)
        switches = LimitSwitches(ax)
        assert switches.range_check
        ax.drive.mech = mech
        switches.check_range()
        assert [(a.kind, a.detail, a.reaction) for a in ax.alarms] == (
            [] if detail is None else [(F.POSITION_RANGE, detail, Reaction.REMOVE_ENABLE)])


def test_kernel_limit_switches_modulo_jump_beyond_the_modulo_length():
    """S7-1200 V6 §12.8 16#800B/16#003B: the actual position changes by more than the modulo length
    (§5.4.4.2, here 360) in one position control cycle."""
    ax = FakeAxis(modulo=Modulo(enabled=True, start=0.0, length=360.0))
    switches = LimitSwitches(ax)
    ax.drive.mech = 359.0
    switches.check_range()
    assert ax.alarms == []
    ax.drive.mech = 359.0 + 360.5
    switches.check_range()
    assert [(a.kind, a.detail) for a in ax.alarms] == [(F.POSITION_RANGE, "modulo_jump")]
    assert not LimitSwitches(FakeAxis()).range_check          # incremental, not modulo: nothing to check


# --- through a kernel Controller axis ---------------------------------------------------------------------
HW_MIN, HW_MAX = -200.0, 300.0
EMERGENCY = 1000.0
OWNER = object()                # the enabling instruction


def controller_axis(actor: int, start: float):
    """An enabled axis (1 PROFIdrive, 2 PTO) with NC limit switches at machine positions -200 and 300."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor.Type": actor, "DynamicLimits.MaxVelocity": 100.0,
        "DynamicLimits.MinVelocity": 1.0 if actor == 2 else 0.0,
        "DynamicDefaults.Acceleration": 200.0, "DynamicDefaults.Deceleration": 200.0,
        "DynamicDefaults.Jerk": 0.0, "DynamicDefaults.EmergencyDeceleration": EMERGENCY,
        "PositionLimits_HW.Active": True, "PositionLimits_HW.MinSwitchAddress": "I0.1",
        "PositionLimits_HW.MaxSwitchAddress": "I0.2", "PositionLimits_HW.MinSwitchLevel": False,
        "PositionLimits_HW.MaxSwitchLevel": False, "Actor.Interface.EnableDriveOutput": "Q0.0",
        "Plant.InitialPosition": start, "Plant.HWLimitMinPosition": HW_MIN, "Plant.HWLimitMaxPosition": HW_MAX})
    enable(ctl, axis)
    return ctl, axis


def enable(ctl, axis) -> None:
    """What MC_Power(Enable=TRUE) asks of the axis (also again after an error removed the enable)."""
    assert axis.power(OWNER, True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 1.0)


def test_kernel_limit_switches_drive_axis_loses_its_enable_at_the_high_switch():
    """S7-1200 V6 §5.4.4.3 / §12.8 16#8004: a PROFIdrive axis reaching the high switch is disabled (enable
    output FALSE), the job that moved it ends with the error, the switch shows as approached."""
    ctl, axis = controller_axis(1, 250.0)
    job = Job(JobKind.VELOCITY, velocity=50.0)
    axis.submit(job)
    ctl.run_until(lambda: not job.busy, 5.0)
    assert job.state == JobState.ERROR and job.fault.kind == F.HW_LIMIT_MAX
    assert axis.state == "disabled" and ctl.outputs["Q0.0"] is False
    assert axis.limit_switches.approached == {"min": False, "max": True}
    assert axis.hw_approached is axis.limit_switches.approached


def test_kernel_limit_switches_pto_axis_brakes_with_the_emergency_deceleration_and_moves_out_freely():
    """S7-1200 V6 §5.4.4.3 / §12.8 16#8003: a PTO axis brakes to standstill with the emergency deceleration
    (from 50 mm/s: 50/1000 = 0.05 s) and stays enabled; after the acknowledgement a motion further down is
    refused (16#800E/16#0042), a motion up leaves the switch."""
    ctl, axis = controller_axis(2, -150.0)
    job = Job(JobKind.VELOCITY, velocity=-50.0)
    axis.submit(job)
    ctl.run_until(lambda: not job.busy, 5.0)
    assert job.state == JobState.ERROR and job.fault.kind == F.HW_LIMIT_MIN
    t_hit = ctl.time
    ctl.run_until(lambda: float(ctl.bank.sp_v[axis.index]) == 0.0, 1.0)
    assert ctl.time - t_hit == pytest.approx(50.0 / EMERGENCY, abs=0.003)
    assert axis.state == "enabled" and ctl.outputs["Q0.0"] is True
    assert axis.acknowledge() is None
    down = Job(JobKind.VELOCITY, velocity=-20.0)
    axis.submit(down)
    assert down.state == JobState.ERROR and (down.fault.kind, down.fault.detail) == (F.HW_LIMIT_FREE, "wrong_direction")
    assert axis.acknowledge() is None and axis.state == "disabled"
    enable(ctl, axis)
    up = Job(JobKind.RELATIVE, position=20.0, velocity=20.0)
    axis.submit(up)
    ctl.run_until(lambda: not up.busy, 5.0)
    assert up.state == JobState.DONE and axis.limit_switches.approached["min"] is False
