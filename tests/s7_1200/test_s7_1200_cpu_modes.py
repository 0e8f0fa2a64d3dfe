"""CPU operating modes and their transitions, derived from the S7-1200 Motion Control V6 manual.

§2.2.7.4 "Operating modes": STOP (user program not processed, process outputs disabled, no Motion Control
jobs executed, technology DBs of position-controlled axes updated), STARTUP (jobs rejected), RUN; transitions
POWER ON -> STOP (restart of the TOs from load memory), STOP -> STARTUP (TOs initialised with the start
values), RUN -> STOP (all TOs disabled with the error response "remove enable", running jobs terminated).
§9.4 "Behavior of the Motion Control commands after POWER OFF and restart": jobs aborted, all CPU outputs
incl. pulse and direction outputs reset; afterwards TOs and jobs re-initialised, actual data and status /
error information reset; the axis must be enabled again with MC_Power and homed again if needed; an absolute
encoder keeps its homing.  §2.5 "Resetting the Homed status" (PTO: POWER OFF -> ON and CPU restart;
incremental actual values: POWER OFF -> ON).  §2.2.7.3: MC-Servo/MC-Interpolator also run in STOP.

API: ``ctl.stop()`` = RUN -> STOP, ``ctl.start()`` = STOP -> STARTUP -> RUN, ``ctl.power_cycle()`` =
POWER OFF -> ON -> RUN.
"""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (
    MC_CommandTable,
    MC_Home,
    MC_MoveAbsolute,
    MC_MoveRelative,
    MC_MoveVelocity,
    MC_Power,
    MC_Reset,
)

SERVO, APP = 0.001, 0.004
ENABLE_OUT = "Q0.1"


def pto_params(**extra) -> dict:
    params = {"Actor": {"Type": 2, "Interface": {"EnableDriveOutput": ENABLE_OUT}},
              "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0},
              "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "EmergencyDeceleration": 1000.0,
                                  "Jerk": 0.0}}
    params.update(extra)
    return params


def pd_params(absolute: bool = False, **extra) -> dict:
    params = {"Actor": {"Type": 1, "Interface": {"Telegram": 3, "EnableDriveOutput": ENABLE_OUT},
                        "DriveParameter": {"ReferenceSpeed": 3000.0, "MaxSpeed": 3000.0}},
              "Sensor[1].Interface.Type": 2, "Sensor[1].Type": 1 if absolute else 0,
              "DynamicLimits": {"MaxVelocity": 400.0},
              "DynamicDefaults": {"Acceleration": 1000.0, "Deceleration": 1000.0, "EmergencyDeceleration": 5000.0,
                                  "Jerk": 0.0},
              "Plant": {"OffRampTime": 0.5}}
    params.update(extra)
    return params


class Cpu:
    """A controller with one axis; the "user program" calls the registered instances every cycle (OB1)."""

    def __init__(self, params: dict):
        self.ctl = Controller(servo_cycle=SERVO, app_cycle=APP)
        self.axis = self.ctl.add_positioning_axis("Axis_1", params)
        self.power = MC_Power(Axis=self.axis, Enable=True)
        self.fbs: list = [self.power]
        self.calls = 0
        self.ctl.program(self._ob1, name="OB1")
        self.run_until(lambda: self.power.Status, "enabled")

    def _ob1(self) -> None:
        self.calls += 1
        for fb in self.fbs:
            fb()

    def add(self, fb):
        fb.Axis = self.axis
        self.fbs.append(fb)
        return fb

    def run_until(self, cond, what: str = "condition", max_cycles: int = 1000) -> None:
        for _ in range(max_cycles):
            self.ctl.step()
            if cond():
                return
        raise AssertionError(f"{what} not reached (t = {self.ctl.time:.3f} s)")

    def cycles(self, n: int) -> None:
        for _ in range(n):
            self.ctl.step()


# ==========================================================================================================
# RUN -> STOP
def test_s7_1200_2_2_7_4_run_to_stop_pto_axis_disabled_pulse_output_stopped():
    """§2.2.7.4 row 4 "RUN -> STOP: all technology objects are disabled in accordance with the error response
    'remove enablement'. Running Motion Control jobs are terminated."  §12.8 "Remove enable": setpoint zero,
    enable removed (PTO: the pulse output stops).  §9.4: the drive enable output is reset."""
    cpu = Cpu(pto_params())
    mv = cpu.add(MC_MoveVelocity(Execute=True, Velocity=50.0))
    cpu.run_until(lambda: mv.InVelocity, "InVelocity")
    assert cpu.ctl.outputs[ENABLE_OUT]
    cpu.ctl.stop()
    assert cpu.ctl.mode == "STOP"
    assert not cpu.axis.StatusBits.Enable and not cpu.ctl.outputs[ENABLE_OUT]
    cpu.ctl.step()
    p = cpu.axis.Position
    assert cpu.axis.Velocity == 0.0 and cpu.axis.ActualVelocity == 0.0
    cpu.cycles(50)
    assert cpu.axis.Position == p and cpu.axis.ActualPosition == pytest.approx(p, abs=0.01)
    assert not cpu.axis.StatusBits.VelocityCommand and cpu.axis.StatusBits.Done


def test_s7_1200_2_2_7_4_run_to_stop_profidrive_remove_enable_and_db_still_updated():
    """§2.2.7.4: RUN -> STOP disables the axis with "remove enable" (§12.8: setpoint zero, enable removed, the
    drive brakes by its own configuration); "In STOP mode ... The technology data blocks of the
    position-controlled axes are updated" -- the actual values follow the drive as it coasts down."""
    cpu = Cpu(pd_params())
    mv = cpu.add(MC_MoveVelocity(Execute=True, Velocity=200.0))
    cpu.run_until(lambda: mv.InVelocity, "InVelocity")
    cpu.ctl.stop()
    cpu.ctl.step()
    out, _ = cpu.axis.drive.telegrams()
    assert not out.STW1.On and out.NSOLL_B == 0, "setpoint zero and enable removed"
    assert not cpu.axis.StatusBits.Enable and not cpu.ctl.outputs[ENABLE_OUT]
    positions = []
    for _ in range(60):
        cpu.ctl.step()
        positions.append(cpu.axis.ActualPosition)
    assert positions[1] > positions[0], "actual values still updated in STOP while the drive ramps down"
    assert cpu.axis.ActualVelocity == pytest.approx(0.0, abs=1e-6)
    assert positions[-1] == positions[-2]


def test_s7_1200_2_2_7_4_user_program_not_processed_in_stop_servo_keeps_running():
    """§2.2.7.4 "In STOP mode the user program is not processed"; §2.2.7.3 MC-Servo and MC-Interpolator run
    in every application cycle also in CPU STOP (virtual time goes on)."""
    cpu = Cpu(pto_params())
    n = cpu.calls
    cpu.cycles(3)
    assert cpu.calls == n + 3
    cpu.ctl.stop()
    t = cpu.ctl.time
    cpu.cycles(10)
    assert cpu.calls == n + 3
    assert cpu.ctl.time == pytest.approx(t + 10 * APP)
    cpu.ctl.start()
    cpu.cycles(2)
    assert cpu.calls == n + 5


def test_s7_1200_2_2_7_4_no_motion_jobs_outside_run():
    """§2.2.7.4: STOP "no Motion Control jobs are executed", STARTUP "Motion Control jobs are rejected" --
    instructions called while the CPU is not in RUN neither enable nor move the axis."""
    cpu = Cpu(pto_params())
    cpu.ctl.stop()
    power = MC_Power(Axis=cpu.axis, Enable=True)
    mv = MC_MoveVelocity(Axis=cpu.axis, Execute=True, Velocity=20.0)
    for _ in range(20):
        power()
        mv()
        cpu.ctl.step()
    assert not power.Status and not cpu.axis.StatusBits.Enable
    assert mv.Error and not mv.Busy
    assert cpu.axis.Velocity == 0.0 and cpu.axis.Position == 0.0


def test_s7_1200_9_4_cpu_stop_resets_all_cpu_outputs():
    """§9.4 "A POWER OFF or CPU-STOP aborts all active motion control jobs. All CPU outputs, including pulse
    and direction outputs, are reset."; §2.2.7.4 "In STOP mode ... all process outputs are disabled"."""
    cpu = Cpu(pto_params())
    cpu.ctl.outputs["Q0.5"] = True              # an output the user program switched on
    assert cpu.ctl.outputs[ENABLE_OUT] and cpu.ctl.outputs["Q0.5"]
    cpu.ctl.stop()
    cpu.ctl.step()
    assert not cpu.ctl.outputs[ENABLE_OUT]
    assert not cpu.ctl.outputs["Q0.5"]


def test_s7_1200_9_4_stop_terminates_command_table():
    """§2.2.7.4 / §9.4: running Motion Control jobs are terminated -- also a command table; after the restart
    the axis is no longer controlled by MC_CommandTable (StatusBits.CommandTableActive FALSE)."""
    cpu = Cpu(pto_params())
    table = cpu.ctl.add_command_table("Table_1", [{"Type": 7, "Velocity": 30.0, "Duration": 10.0}])
    ct = cpu.add(MC_CommandTable(CommandTable=table, Execute=True, EndStep=1))
    cpu.run_until(lambda: cpu.axis.Velocity == pytest.approx(30.0), "table running")
    assert cpu.axis.StatusBits.CommandTableActive
    cpu.ctl.stop()
    cpu.ctl.step()
    assert not cpu.axis.StatusBits.CommandTableActive and cpu.axis.Velocity == 0.0
    cpu.ctl.start()
    assert not ct.Busy and not ct.Done and not ct.CommandAborted and not ct.Error


# ==========================================================================================================
# STOP -> RUN
def test_s7_1200_9_4_instance_status_reset_after_restart():
    """§9.4: after a restart (CPU RUN) "all status and error information of the previously active motion
    control jobs are reset to their initial values"."""
    cpu = Cpu(pto_params())
    mv = cpu.add(MC_MoveVelocity(Execute=True, Velocity=40.0))
    mr = cpu.add(MC_MoveRelative(Execute=True, Distance=1.0, Velocity=1000.0))    # 16#8402 latched
    cpu.run_until(lambda: mv.CommandAborted or mv.InVelocity, "started")
    cpu.cycles(2)
    assert mr.Error and mr.ErrorID == 0x8402
    cpu.ctl.stop()
    cpu.ctl.start()
    for fb in (mv, mr):
        assert not any(fb.outputs.get(k) for k in ("Busy", "Error", "CommandAborted", "Done")), fb.outputs
        assert fb.ErrorID == 0 and fb.ErrorInfo == 0
    assert not mv.InVelocity
    assert not cpu.power.Status and not cpu.power.Error


def test_s7_1200_9_4_axis_must_be_enabled_again_after_stop_run():
    """§9.4 "Before the axis can be reused, it must be enabled again using ... MC_Power": after STOP -> RUN
    the axis is disabled; a motion command before the enable gives 16#8200; the enable output stays reset
    until MC_Power enables the axis again."""
    cpu = Cpu(pto_params())
    cpu.ctl.stop()
    cpu.ctl.start()
    assert cpu.ctl.mode == "RUN"
    assert not cpu.axis.StatusBits.Enable and not cpu.ctl.outputs[ENABLE_OUT]
    cpu.fbs.remove(cpu.power)
    mr = cpu.add(MC_MoveRelative(Execute=True, Distance=5.0, Velocity=20.0))
    cpu.cycles(3)
    assert mr.Error and (mr.ErrorID, mr.ErrorInfo) == (0x8200, 0x0001)
    assert not cpu.ctl.outputs[ENABLE_OUT]
    cpu.fbs.insert(0, cpu.power)
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert cpu.axis.StatusBits.Enable and cpu.ctl.outputs[ENABLE_OUT]
    mr.Execute = False
    cpu.cycles(1)
    mr.Execute = True
    cpu.run_until(lambda: mr.Done, "moved after the new enable")
    assert cpu.axis.Position == pytest.approx(5.0)


def test_s7_1200_2_2_7_4_startup_initialises_tos_with_start_values():
    """§2.2.7.4 row 2 "STOP -> STARTUP: The technology objects are initialized with the start values of the
    CPU" (row 1 for POWER ON: values from the load memory); §9.7: runtime changes are only kept if written to
    the start values with WRIT_DBL."""
    for transition in ("start", "power_cycle"):
        cpu = Cpu(pto_params())
        cpu.axis.DynamicDefaults.Acceleration = 40.0
        cpu.cycles(1)
        assert cpu.axis.DynamicDefaults.Acceleration == 40.0
        cpu.ctl.stop()
        getattr(cpu.ctl, transition)()
        assert cpu.axis.DynamicDefaults.Acceleration == 100.0, transition


@pytest.mark.parametrize("transition", ["start", "power_cycle"])
def test_s7_1200_2_2_7_4_command_table_restarts_with_its_start_values(transition):
    """§2.2.7.4 rows 1 and 2: at POWER ON the technology objects are re-initialised from the load memory, at
    STOP -> STARTUP with their start values -- this includes the command table technology object (§6): step
    values changed by the user program (§6.4.3.7) are back at their configured values (§9.7: runtime changes
    survive only if written to the start values with WRIT_DBL)."""
    cpu = Cpu(pto_params())
    table = cpu.ctl.add_command_table("Table_1", [{"Type": 5, "Position": 10.0, "Velocity": 20.0, "StepCode": 3}])
    table.Command[1].Velocity = 50.0
    table.Command[1].StepCode = 9
    table.Command[2].Type = 151
    cpu.ctl.stop()
    getattr(cpu.ctl, transition)()
    assert table.Command[1].Velocity == 20.0 and table.Command[1].StepCode == 3
    assert table.Command[2].Type == 0


def test_s7_1200_9_4_pending_errors_reset_after_restart():
    """§9.4: "all status and error information ... reset to their initial values" -- an axis error waiting for
    MC_Reset (16#8008, direction not permitted) is gone after STOP -> RUN; the axis can be enabled at once."""
    cpu = Cpu(pto_params(Actor={"Type": 2, "DirectionMode": 1, "Interface": {"EnableDriveOutput": ENABLE_OUT}}))
    mv = cpu.add(MC_MoveVelocity(Execute=True, Velocity=-20.0))
    cpu.cycles(3)
    assert mv.Error and mv.ErrorID == 0x8008 and cpu.axis.StatusBits.Error
    cpu.fbs.remove(mv)
    cpu.ctl.stop()
    cpu.ctl.start()
    assert not cpu.axis.StatusBits.Error and not cpu.axis.ErrorBits.DirectionFault
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert not cpu.power.Error


# ==========================================================================================================
# homing after restart / POWER OFF -> ON
def _home(cpu: Cpu, mode: int = 0, position: float = 10.0) -> None:
    home = MC_Home(Axis=cpu.axis, Mode=mode, Position=position, Execute=True)
    cpu.fbs.append(home)
    cpu.run_until(lambda: home.Done, "homed")
    cpu.fbs.remove(home)
    assert cpu.axis.StatusBits.HomingDone


@pytest.mark.parametrize("transition", ["start", "power_cycle"])
def test_s7_1200_2_5_pto_axis_loses_homing_after_restart_and_power_cycle(transition):
    """§2.5 "Resetting the Homed status" for PTO: "After POWER OFF -> POWER ON of the CPU", "After CPU restart
    (RUN-STOP -> STOP-RUN)"; §9.4: the axis must be homed again (MC_MoveAbsolute: 16#8204); not homed, the
    position counts from the position at enable (§12.9.1)."""
    cpu = Cpu(pto_params())
    _home(cpu, position=10.0)
    mr = cpu.add(MC_MoveRelative(Execute=True, Distance=5.0, Velocity=50.0))
    cpu.run_until(lambda: mr.Done, "moved")
    cpu.fbs.remove(mr)
    assert cpu.axis.Position == pytest.approx(15.0)
    cpu.ctl.stop()
    getattr(cpu.ctl, transition)()
    assert not cpu.axis.StatusBits.HomingDone
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert not cpu.axis.StatusBits.HomingDone
    assert cpu.axis.Position == 0.0
    ma = cpu.add(MC_MoveAbsolute(Execute=True, Position=20.0, Velocity=50.0))
    cpu.cycles(2)
    assert ma.Error and (ma.ErrorID, ma.ErrorInfo) == (0x8204, 0x0001)


def test_s7_1200_2_5_incremental_encoder_loses_homing_at_power_cycle():
    """§2.5 incremental actual values: "After POWER OFF -> POWER ON of the CPU" the Homed status is reset;
    §9.4 the axis must be enabled and homed again."""
    cpu = Cpu(pd_params())
    _home(cpu, position=25.0)
    assert cpu.axis.ActualPosition == pytest.approx(25.0, abs=0.01)
    cpu.ctl.power_cycle()
    assert not cpu.axis.StatusBits.HomingDone and not cpu.axis.StatusBits.Enable
    out, _ = cpu.axis.drive.telegrams()
    assert not out.STW1.On, "drive enable (STW1 bit 0) reset by the power cycle"
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert not cpu.axis.StatusBits.HomingDone


def test_s7_1200_9_4_absolute_encoder_keeps_homing_after_power_off():
    """§9.4 "When an absolute encoder is used, homing is retained after POWER OFF" (adjusted with MC_Home
    Mode 7, §11.1.3); the actual position is that of the adjustment, not reset."""
    cpu = Cpu(pd_params(absolute=True))
    _home(cpu, mode=7, position=123.0)
    pos = cpu.axis.ActualPosition
    assert pos == pytest.approx(123.0, abs=0.01)
    cpu.ctl.power_cycle()
    assert cpu.axis.StatusBits.HomingDone
    assert cpu.axis.ActualPosition == pytest.approx(pos, abs=0.01)
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert cpu.axis.StatusBits.HomingDone
    assert cpu.axis.ActualPosition == pytest.approx(pos, abs=0.01)


def test_s7_1200_9_4_power_cycle_aborts_jobs_resets_outputs_and_needs_new_enable():
    """§9.4: POWER OFF aborts all jobs and resets all CPU outputs (the drive enable output); after POWER ON
    the TOs and jobs are re-initialised (instance outputs reset, axis disabled) and MC_Power has to enable the
    axis again."""
    cpu = Cpu(pto_params())
    mv = cpu.add(MC_MoveVelocity(Execute=True, Velocity=60.0))
    cpu.run_until(lambda: mv.InVelocity, "InVelocity")
    cpu.ctl.power_cycle()
    assert cpu.ctl.mode == "RUN"
    assert not cpu.ctl.outputs[ENABLE_OUT] and not cpu.axis.StatusBits.Enable
    assert cpu.axis.Velocity == 0.0
    assert not mv.Busy and not mv.InVelocity and not mv.CommandAborted and not mv.Error
    assert not cpu.power.Status
    cpu.fbs.remove(mv)
    cpu.run_until(lambda: cpu.power.Status, "enabled again")
    assert cpu.ctl.outputs[ENABLE_OUT] and cpu.axis.StatusBits.Enable


def test_s7_1200_11_1_2_reset_not_needed_but_possible_after_restart():
    """§9.4 / §11.1.2: after the restart there is nothing to acknowledge: MC_Reset completes with Done and
    StatusBits.Error stays FALSE."""
    cpu = Cpu(pto_params())
    cpu.ctl.stop()
    cpu.ctl.start()
    reset = cpu.add(MC_Reset(Execute=True))
    cpu.run_until(lambda: reset.Done or reset.Error, "reset")
    assert reset.Done and not cpu.axis.StatusBits.Error
