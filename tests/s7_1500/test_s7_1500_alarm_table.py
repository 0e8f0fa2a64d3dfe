"""Technology alarms of the S7-1500 technology objects, provoked through instruction calls over cycles:
ErrorDetail.Number / Reaction, the ErrorWord bit, StatusWord.X3 (restart required), the instruction's 16#8001,
the reaction on the setpoint trace (stop with maximum dynamic values, emergency stop ramp, remove enable),
the acknowledgement with MC_Reset (or MC_Reset Restart), and the generated page docs/s7_1500/alarms.md.

S7-1500T synchronous operation V5 (seeds/001): §7.1.1 errors and warnings, §A.1.37 StatusWord, §A.1.39
ErrorWord, §A.1.40 ErrorDetail (reactions 0 ... 5), §A.1.41 WarningWord, §A.2.10 / §A.3.8 reactions of the
cam (6) and the leading axis proxy (13); §6.1.5.3 alarm 531, §6.1.5.6 alarms 521/541.  The numbers, bits,
reactions and restart needs are the CPU's alarm list (../shared/reference/s7-1500-errorids.md §4.2), typed
out below as literal data.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.s7_1500 import MC_GearIn, MC_Home, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_Reset
from plcmotion.s7_1500.technology import alarms as A

ROOT = Path(__file__).resolve().parents[2]

#: the CPU's alarm list (reference §4.2): number -> (axis reaction, word, bit, restart)
CPU_LIST = {
    101: (4, "E", 1, True), 104: (2, "E", 1, False), 201: (4, "E", 0, True), 304: (3, "E", 2, False),
    305: (3, "E", 2, False), 321: (3, "E", 3, False), 341: (2, "E", 10, False), 342: (3, "E", 10, False),
    411: (4, "E", 5, False), 412: (4, "E", 5, False), 421: (4, "E", 4, False), 431: (4, "E", 7, False),
    501: (0, "W", 6, False), 502: (0, "W", 6, False), 503: (0, "W", 6, False), 521: (4, "E", 11, False),
    522: (0, "W", 11, False), 531: (4, "E", 9, False), 533: (2, "E", 8, False), 534: (4, "E", 8, False),
    541: (4, "E", 12, False), 601: (2, "E", 14, False), 612: (4, "E", 2, False), 900: (0, "E", 2, False),
}

DT = 0.001
DYN = {"DynamicDefaults": {"Velocity": 100.0, "Acceleration": 500.0, "Deceleration": 800.0, "Jerk": 0.0,
                           "EmergencyDeceleration": 4000.0},
       "DynamicLimits": {"MaxVelocity": 1000.0, "Velocity": 1000.0, "MaxAcceleration": 5000.0,
                         "MaxDeceleration": 6000.0, "MaxJerk": 0.0}}
VIRTUAL = {"VirtualAxis": {"Mode": 1}, **DYN}
DRIVE = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0, "DynamicLimits.Velocity": 100.0,
         "DynamicDefaults.Velocity": 50.0, "DynamicDefaults.Acceleration": 500.0,
         "DynamicDefaults.Deceleration": 500.0, "DynamicDefaults.Jerk": 0.0,
         "DynamicDefaults.EmergencyDeceleration": 2000.0, "PositionControl.Kv": 10.0}


class Rig:
    """One S7-1500T axis enabled by MC_Power; application cycle = servo cycle, so every step is a trace row."""

    def __init__(self, params: dict, *, synchronous: bool = False, masters: int = 0):
        self.ctl = Controller(family="S7-1500T", servo_cycle=DT, app_cycle=DT)
        self.masters = [self.ctl.add_positioning_axis(f"M{i}", VIRTUAL) for i in range(masters)]
        if synchronous:
            self.axis = self.ctl.add_synchronous_axis("Axis", params, leading_values=["M0"] if masters else [])
        else:
            self.axis = self.ctl.add_positioning_axis("Axis", params)
        self.power = MC_Power()
        self.enable = True
        self.calls: list = []
        self.v: list[float] = []
        self.p: list[float] = []

        @self.ctl.program
        def main() -> None:
            self.power(Axis=self.axis, Enable=self.enable)
            for call in list(self.calls):
                call()
            self.v.append(self.axis.Velocity)
            self.p.append(self.axis.Position)
        self.ctl.run_until(lambda: self.power.Status, timeout=2.0)

    def call(self, fb, **inputs):
        self.calls.append(lambda: fb(Axis=self.axis, **inputs) if "Slave" not in inputs else fb(**inputs))
        return fb

    def homed(self) -> None:
        """Software limit switches act on a homed axis only (§6.1.5.3): MC_Home Mode 0 at 0."""
        home = self.call(MC_Home(), Execute=True, Mode=0, Position=0.0)
        self.ctl.run_until(lambda: home.Done, timeout=1.0)
        self.calls.clear()

    def moving(self, velocity: float = 100.0):
        mv = self.call(MC_MoveVelocity(), Execute=True, Velocity=velocity)
        self.ctl.run_until(lambda: mv.InVelocity, timeout=2.0)
        return mv

    def detail(self) -> tuple[int, int]:
        return self.axis.ErrorDetail.Number, self.axis.ErrorDetail.Reaction

    def reset(self, restart: bool = False):
        rs = MC_Reset()
        self.calls.append(lambda: rs(Axis=self.axis, Execute=True, Restart=restart))
        self.ctl.run_until(lambda: rs.Done or rs.Error, timeout=0.5)
        return rs


def braking(v: list[float], start: int) -> float:
    """The deceleration of the braking after row ``start`` (largest whole-cycle velocity drop)."""
    dv = -np.diff(np.abs(np.asarray(v[start:]))) / DT
    return float(dv.max())


# --- the table -------------------------------------------------------------------------------------------
def test_s7_1500_alarm_table_has_the_cpu_numbers_reactions_bits_and_restart_needs_s7_1_1():
    """§A.1.39-§A.1.41: every alarm plcmotion raises has the CPU's reaction, bit and restart need."""
    assert set(A.ALARMS) == set(CPU_LIST)
    for number, (reaction, word, bit, restart) in CPU_LIST.items():
        a = A.ALARMS[number]
        assert (a.reaction, a.word, a.bit, a.restart) == (reaction, word, bit, restart), number


@pytest.mark.parametrize("fault, owner, number", [
    (F.alarm(F.ENCODER, "station"), A.AXIS, 431), (F.alarm(F.DRIVE_ALARM, "sign_of_life"), A.AXIS, 431),
    (F.alarm(F.DRIVE_ALARM, "shutdown"), A.AXIS, 421), (F.alarm(F.ENCODER, "dirty"), A.AXIS, 411),
    (F.alarm(F.SW_LIMIT_MAX, "reached"), A.AXIS, 533), (F.alarm(F.SW_LIMIT_MIN, "exceeded"), A.AXIS, 534),
    (F.config_fault("DynamicLimits.Velocity", "too_low"), A.AXIS, 304),
    (F.config_fault("DynamicLimits.MaxDeceleration", "too_low"), A.AXIS, 305),
    (F.config_fault("PositionControl.Kv", "too_low"), A.AXIS, 101),
    (F.alarm(F.LV_INVALID), A.AXIS, 601), (F.alarm(F.LV_INVALID), A.PROXY, 900),
    (F.alarm(F.HW_LIMIT_FREE, "polarity"), A.AXIS, 531),
])
def test_s7_1500_kernel_faults_map_to_the_cpu_alarm_of_their_situation_s7_1_1(fault, owner, number):
    """§7.1.1: drive, encoder and data exchange errors each have their own bit; the alarm list's numbers."""
    assert A.number(fault, owner) == number


def test_s7_1500_error_detail_reactions_of_the_other_technology_objects_sA_2_10_sA_3_8():
    """§A.2.10 cam: 0 or 6; §A.3.8 leading axis proxy: 0 or 13; the external encoder is disabled (4)."""
    assert A.error_detail([F.alarm(F.LV_INVALID)], A.PROXY) == (900, 13)
    assert A.error_detail([F.alarm(F.INTERNAL)], A.CAM) == (201, 6)
    assert A.error_detail([F.alarm(F.ENCODER, "hardware")], A.ENCODER) == (411, 4)
    assert A.error_detail([], A.CAM) == (0, 0)


def test_s7_1500_error_detail_shows_the_alarm_with_the_strongest_reaction_sA_1_40():
    """§A.1.40 shows one alarm: with several pending, the one with the strongest reaction (decision)."""
    pending = [F.alarm(F.SW_LIMIT_MAX, "reached"), F.alarm(F.FOLLOWING_ERROR)]
    assert A.error_detail(pending) == (521, 4)
    assert A.error_bits(pending) == {8: True, 11: True}


def test_s7_1500_alarm_page_is_generated_from_the_table():
    """docs/s7_1500/alarms.md lists every alarm of the table (regenerate with
    ``python -m plcmotion.s7_1500.technology.alarms > docs/s7_1500/alarms.md``)."""
    page = (ROOT / "docs" / "s7_1500" / "alarms.md").read_text()
    assert page == A.render_markdown()
    for number in CPU_LIST:
        assert f"\n| {number} | " in page


# --- provoked through instruction calls --------------------------------------------------------------------
def test_s7_1500_alarm_104_swapped_limits_stop_with_maximum_dynamics_s7_1_1():
    """Reaction 2: the running motion brakes with DynamicLimits.MaxDeceleration (6000), not the job's 800."""
    r = Rig(VIRTUAL)
    mv = r.moving()
    n = len(r.v)
    r.axis.PositionLimits_SW.MinPosition = 500.0          # becomes effective with the next write:
    r.axis.PositionLimits_SW.MaxPosition = 400.0          # MinPosition > MaxPosition
    r.ctl.run(0.05)
    assert r.detail() == (104, 2) and r.axis.ErrorWord.ConfigFault and mv.Error and mv.ErrorID == 0x8001
    assert braking(r.v, n) == pytest.approx(6000.0, rel=1e-6) and r.v[-1] == 0.0
    assert r.axis.StatusWord.Enable and not r.axis.StatusWord.RestartRequired
    r.axis.PositionLimits_SW.MaxPosition = 10000.0
    r.axis.PositionLimits_SW.MinPosition = -10000.0
    assert r.reset().Done and r.detail() == (0, 0)


@pytest.mark.parametrize("path, number", [("DynamicLimits.Velocity", 304), ("DynamicLimits.MaxAcceleration", 305),
                                          ("DynamicLimits.MaxDeceleration", 305)])
def test_s7_1500_alarms_304_305_zero_limits_stop_with_the_emergency_ramp_s7_1_1(path, number):
    """Reaction 3: a dynamic limit written as 0 brakes the axis with EmergencyDeceleration (4000) without jerk."""
    r = Rig(VIRTUAL)
    mv = r.moving()
    n = len(r.v)
    r.axis.write_tag(path, 0.0)
    r.ctl.run(0.05)
    assert r.detail() == (number, 3) and r.axis.ErrorWord.UserFault and mv.ErrorID == 0x8001
    assert braking(r.v, n) == pytest.approx(4000.0, rel=1e-6) and r.v[-1] == 0.0
    r.axis.write_tag(path, 1000.0)
    assert r.reset().Done and r.detail() == (0, 0)


def test_s7_1500_alarm_321_unhomed_absolute_move_stops_a_running_motion_with_the_emergency_ramp_s7_1_1():
    """§7.1.1 "Job rejected (for example, technology object not homed)": alarm 321, ErrorWord.X3, reaction 3;
    the running velocity job ends with 16#8001 too."""
    r = Rig(VIRTUAL)
    mv = r.moving()
    n = len(r.v)
    ma = r.call(MC_MoveAbsolute(), Execute=True, Position=10.0, Velocity=10.0)
    r.ctl.run(0.05)
    assert ma.Error and ma.ErrorID == 0x8001 and mv.Error and mv.ErrorID == 0x8001
    assert r.detail() == (321, 3) and r.axis.ErrorWord.CommandNotAccepted
    assert braking(r.v, n) == pytest.approx(4000.0, rel=1e-6) and r.v[-1] == 0.0


def test_s7_1500_alarm_101_configuration_error_removes_enable_and_needs_a_restart_s7_1_1():
    """Reaction 4 and a fatal error: MC_Reset alone keeps it (StatusWord.X3 RestartRequired); disabling
    and MC_Reset with Restart = TRUE reloads the start values and clears it."""
    r = Rig(VIRTUAL)
    r.moving()
    r.axis.write_tag("PositionControl.Kv", 0.0)
    r.ctl.run(0.01)
    assert r.detail() == (101, 4) and r.axis.ErrorWord.ConfigFault and r.axis.StatusWord.RestartRequired
    assert not r.axis.StatusWord.Enable and r.v[-1] == 0.0 and not r.power.Status
    rs = r.reset()
    assert rs.Error and rs.ErrorID == 0x8015 and r.detail() == (101, 4)   # only a restart clears it
    r.enable = False
    r.ctl.run(0.01)
    assert r.reset(restart=True).Done
    assert r.detail() == (0, 0) and not r.axis.StatusWord.RestartRequired and int(r.axis.ErrorWord) == 0


def test_s7_1500_alarm_533_software_limit_stops_at_the_switch_s7_1_1():
    """§6.1.5.3 "an active motion comes to a stop at the position of the software limit switch": alarm 533
    (ErrorWord.X8), ErrorDetail.Reaction 2; the axis stands exactly at the switch position."""
    r = Rig({**VIRTUAL, "PositionLimits_SW": {"Active": True, "MinPosition": -50.0, "MaxPosition": 50.0}})
    r.homed()
    mv = r.call(MC_MoveVelocity(), Execute=True, Velocity=100.0)
    r.ctl.run_until(lambda: mv.Error, timeout=3.0)
    assert mv.ErrorID == 0x8001 and r.detail() == (533, 2) and r.axis.ErrorWord.SWLimit
    assert max(r.p) == pytest.approx(50.0, abs=1e-9) and r.v[-1] == 0.0
    # reaction 2: the braking at the switch uses DynamicLimits.MaxDeceleration (6000), not the job's 800
    assert braking(r.v, 0) == pytest.approx(6000.0, rel=1e-6)


def test_s7_1500_alarm_534_passed_software_limit_removes_enable_s7_1_1():
    """The switch moved behind the moving axis: alarm 534 (ErrorWord.X8), reaction 4 remove enable."""
    r = Rig(VIRTUAL)
    r.homed()
    r.moving()
    r.axis.PositionLimits_SW.MaxPosition = r.axis.Position - 1.0
    r.axis.PositionLimits_SW.Active = True
    r.ctl.run(0.5)
    assert r.detail() == (534, 4) and r.axis.ErrorWord.SWLimit and not r.axis.StatusWord.Enable


def test_s7_1500_alarm_601_unconfigured_leading_axis_stops_with_maximum_dynamics_s7_1_1():
    """ErrorWord.X14 "the leading axis ... was not configured as a possible leading axis": alarm 601,
    reaction 2 - the moving following axis brakes with MaxDeceleration; MC_Reset acknowledges."""
    r = Rig(VIRTUAL, synchronous=True, masters=2)
    mv = r.moving()
    n = len(r.v)
    gear = MC_GearIn()
    r.calls.append(lambda: gear(Master=r.masters[1], Slave=r.axis, Execute=True, RatioNumerator=1,
                                RatioDenominator=1))
    r.ctl.run(0.05)
    assert gear.Error and gear.ErrorID == 0x8001 and mv.Error and mv.ErrorID == 0x8001
    assert r.detail() == (601, 2) and r.axis.ErrorWord.SynchronousError
    assert braking(r.v, n) == pytest.approx(6000.0, rel=1e-6) and r.v[-1] == 0.0
    r.calls.clear()
    assert r.reset().Done and r.detail() == (0, 0)


def test_s7_1500_alarm_612_cam_not_interpolated_removes_enable_s7_1_1():
    """MC_CamIn with a cam MC_InterpolateCam has not interpolated: alarm 612 at the following axis (ErrorWord.X2
    UserFault), reaction 4 - the moving axis loses its enable at once; MC_CamIn and the running job end with
    16#8001; MC_Reset acknowledges (no restart)."""
    from plcmotion.s7_1500 import MC_CamIn
    r = Rig(VIRTUAL, synchronous=True, masters=1)
    cam = r.ctl.add_cam("Cam", [(0, 0), (180, 100), (360, 0)])
    mv = r.moving()
    camin = MC_CamIn()
    r.calls.append(lambda: camin(Master=r.masters[0], Slave=r.axis, Cam=cam, Execute=True))
    r.ctl.run(0.02)
    assert camin.Error and camin.ErrorID == 0x8001 and mv.Error and mv.ErrorID == 0x8001
    assert r.detail() == (612, 4) and r.axis.ErrorWord.UserFault and not r.axis.StatusWord.RestartRequired
    assert not r.axis.StatusWord.Enable and r.v[-1] == 0.0 and not r.power.Status
    r.calls.clear()
    assert r.reset().Done and r.detail() == (0, 0)


def test_s7_1500_alarm_201_internal_error_removes_enable_and_needs_a_restart_s7_1_1(monkeypatch):
    """A defect inside plcmotion (planted: the motion planner fails) is alarm 201 (ErrorWord.X0 SystemFault),
    reaction 4, a fatal error: the job ends with 16#8001, MC_Reset alone cannot acknowledge it (16#8015,
    StatusWord.X3), disabling and MC_Reset Restart = TRUE clear it.  (The kernel's fault injection acts on
    the simulated devices only, so the defect is planted here.)"""
    from plcmotion.kernel.profiles import PlanningError
    r = Rig(VIRTUAL)

    def defect(*args, **kw):
        raise PlanningError("planted defect")
    monkeypatch.setattr(r.axis.motion, "plan", defect)
    mr = r.call(MC_MoveRelative(), Execute=True, Distance=10.0)
    r.ctl.run(0.02)
    assert mr.Error and mr.ErrorID == 0x8001 and r.detail() == (201, 4) and r.axis.ErrorWord.SystemFault
    assert r.axis.StatusWord.RestartRequired and not r.axis.StatusWord.Enable and not r.power.Status
    monkeypatch.undo()
    r.calls.clear()
    rs = r.reset()
    assert rs.Error and rs.ErrorID == 0x8015 and r.detail() == (201, 4)
    r.enable = False
    r.ctl.run(0.01)
    assert r.reset(restart=True).Done and r.detail() == (0, 0) and not r.axis.StatusWord.RestartRequired


@pytest.mark.parametrize("kind, detail, number, bit", [
    ("drive", "", 421, 4), ("drive", "shutdown", 421, 4), ("encoder", "dirty", 411, 5),
    ("encoder", "", 411, 5), ("drive", "sign_of_life", 431, 7), ("communication_loss", "", 431, 7)])
def test_s7_1500_drive_encoder_and_communication_alarms_remove_enable_s7_1_1(kind, detail, number, bit):
    """§7.1.1 drive (X4), encoder (X5) and data exchange (X7) errors: reaction 4; MC_Reset acknowledges once
    the device is well again."""
    r = Rig(DRIVE)
    mv = r.moving(40.0)
    r.axis.inject_fault(kind, detail)
    r.ctl.run(0.02)
    assert r.detail() == (number, 4) and getattr(r.axis.ErrorWord, f"X{bit}")
    assert mv.Error and mv.ErrorID == 0x8001 and not r.power.Status and not r.axis.StatusDrive.InOperation
    r.calls.clear()
    assert r.reset().Done and r.detail() == (0, 0)
    r.ctl.run_until(lambda: r.power.Status, timeout=1.0)


def test_s7_1500_alarm_521_following_error_removes_enable_s6_1_5_6():
    """§6.1.5.6: a blocked load trips alarm 521 (ErrorWord.X11), reaction 4."""
    r = Rig(DRIVE)
    r.moving(40.0)
    r.axis.disturb_load(blocked=True)
    r.ctl.run_until(lambda: not r.power.Status, timeout=2.0)
    assert r.detail() == (521, 4) and r.axis.ErrorWord.FollowingErrorFault and not r.axis.StatusWord.Enable


def test_s7_1500_alarm_541_positioning_monitoring_removes_enable_s6_1_5_6():
    """§6.1.5.6: the target window is not reached in the tolerance time: alarm 541 (ErrorWord.X12), reaction 4."""
    r = Rig({**DRIVE, "PositioningMonitoring.ToleranceTime": 0.0, "PositioningMonitoring.Window": 1e-6,
             "PositionControl.Kv": 1.0})
    mr = MC_MoveRelative()
    r.call(mr, Execute=True, Distance=5.0, Velocity=50.0)
    r.ctl.run_until(lambda: mr.Error, timeout=3.0)
    assert mr.ErrorID == 0x8001 and r.detail() == (541, 4) and r.axis.ErrorWord.PositioningFault


HW = {"PositionLimits_HW.Active": True, "PositionLimits_HW.MinSwitchAddress": "I0.1",
      "PositionLimits_HW.MaxSwitchAddress": "I0.2", "PositionLimits_HW.MinSwitchLevel": True,
      "PositionLimits_HW.MaxSwitchLevel": True}


def _hw_rig() -> Rig:
    r = Rig({**DRIVE, **HW})
    r.ctl.plant.place_switch("I0.1", axis=r.axis, high=-500.0, name="low limit switch")
    r.ctl.plant.place_switch("I0.2", axis=r.axis, low=5.0, name="high limit switch")
    return r


def test_s7_1500_alarm_531_hardware_limit_switch_removes_enable_s6_1_5_3():
    """§6.1.5.3 "If a hardware limit switch is reached, technology alarm 531 is output, and the technology
    object is disabled": ErrorWord.X9, reaction 4; MC_Reset acknowledges (no restart)."""
    r = _hw_rig()
    mv = r.moving(40.0)
    r.ctl.run_until(lambda: not r.power.Status, timeout=2.0)
    assert r.detail() == (531, 4) and r.axis.ErrorWord.HWLimit and mv.ErrorID == 0x8001
    assert not r.axis.StatusWord.RestartRequired


def test_s7_1500_alarm_531_with_both_switches_actuated_needs_a_restart_s6_1_5_3():
    """Both hardware limit switches at once (wiring): alarm 531 that only a restart clears (StatusWord.X3)."""
    r = _hw_rig()
    r.ctl.plant.switch("I0.1").stick(True)
    r.ctl.plant.switch("I0.2").stick(True)
    r.ctl.run_until(lambda: r.axis.StatusWord.Error, timeout=1.0)
    assert r.detail() == (531, 4) and r.axis.StatusWord.RestartRequired
    r.ctl.plant.switch("I0.1").repair()
    r.ctl.plant.switch("I0.2").repair()
    rs = r.reset()
    assert rs.Error and rs.ErrorID == 0x8015 and r.detail() == (531, 4)
    r.enable = False
    r.ctl.run(0.01)
    assert r.reset(restart=True).Done and r.detail() == (0, 0)


def test_s7_1500_alarm_341_homing_velocity_zero_stops_with_maximum_dynamics_s7_1_1():
    """Active homing with Homing.ReferencingVelocity 0: alarm 341 (ErrorWord.X10 HomingError), reaction 2."""
    r = Rig({**VIRTUAL, "VirtualAxis": {"Mode": 0}, "Actor": {"Type": 1},
             "DynamicLimits": {**DYN["DynamicLimits"], "MaxDeceleration": 3000.0},
             "Homing": {"ReferencingVelocity": 0.0}, "Sensor": {"Sensor[1]": {"ActiveHoming": {"Mode": 0}}}})
    mv = r.moving(50.0)
    n = len(r.v)
    home = r.call(MC_Home(), Execute=True, Mode=3)
    r.ctl.run(0.05)
    assert home.Error and home.ErrorID == 0x8001 and r.detail() == (341, 2) and r.axis.ErrorWord.HomingError
    assert mv.Error and braking(r.v, n) == pytest.approx(3000.0, rel=1e-6) and r.v[-1] == 0.0


def test_s7_1500_alarm_412_modulo_actual_value_jump_removes_enable_s7_1_1():
    """The actual value of a modulo axis jumps by more than one modulo length in a servo cycle: alarm 412
    (ErrorWord.X5 SensorFault), reaction 4."""
    r = Rig({**DRIVE, "Properties.MotionType": 1, "Units.LengthUnit": 1005, "Modulo.Enable": True,
             "Modulo.Length": 360.0, "FollowingError.MaxValue": 1e6, "FollowingError.MinValue": 1e6})
    r.axis.disturb_load(jump=400.0)
    r.ctl.run(0.02)
    assert r.detail() == (412, 4) and r.axis.ErrorWord.SensorFault and not r.power.Status


def test_s7_1500_alarm_342_homing_mark_not_found_between_the_limit_switches_s6_1_5_5():
    """Active homing with reversal at the hardware limit switches that finds no homing mark between them:
    alarm 342 (ErrorWord.X10), reaction 3 emergency stop ramp; the job ends with 16#8001."""
    r = Rig({**DRIVE, **HW, "Homing.AutoReversal": True, "Homing.ApproachVelocity": 20.0,
             "Sensor[1].ActiveHoming.Mode": 2, "Sensor[1].ActiveHoming.DigitalInputAddress": "I0.3",
             "Plant.HomingSwitchPosition": 1.0e6})
    r.ctl.plant.place_switch("I0.1", axis=r.axis, high=-5.0, name="low limit switch")
    r.ctl.plant.place_switch("I0.2", axis=r.axis, low=5.0, name="high limit switch")
    home = r.call(MC_Home(), Execute=True, Mode=3)
    r.ctl.run_until(lambda: home.Error, timeout=5.0)
    assert home.ErrorID == 0x8001 and r.detail() == (342, 3) and r.axis.ErrorWord.HomingError
    r.ctl.run(0.1)
    assert r.v[-1] == 0.0
