"""Drive enable / ready signals and device faults (drive, encoder) of the S7-1200 V6 positioning axis,
derived from the function manual.

Manual sections (S7-1200 Motion Control V6.0, seeds/000):
  §2.1.1, §5.4.3.2  optional enable output ('Drive enabled', set by MC_Power) and ready input ('Drive ready')
  §11.1.1.1         MC_Power: Status TRUE only once 'Drive ready' is present; an axis disabled by an error is
                    enabled again automatically once the error is removed and acknowledged, provided Enable
                    stayed TRUE (S-PWR-2 chart)
  §11.1.2           MC_Reset: success = Done TRUE and StatusBits.Error FALSE; acknowledges operating errors
                    whose cause is removed
  §2.5              'Resetting the Homed status': error in the encoder system / encoder failure (incremental and
                    absolute actual values)
  §10.1             'Encoder values are invalid' from StatusSensor.State (valid = 2, §12.8 16#8207/16#0054)
  §12.8             16#8000/16#0001 (Drive ready lost), 16#800A (0001, 0034 .. 0038, 0040, 0041; reaction remove
                    enable), 16#800C (0001, 003C .. 003F; remove enable)
Project decisions (docs/decisions.md): #25 (ErrorBits: DriveFault for 16#8000 and 16#800C, SensorFault for
16#800A), #38 (16#8000: remove enable), #52 (absolute encoder homed status in the state file).
"""
from __future__ import annotations

from typing import Any

import pytest

from _fb_program import FbProgram
from plcmotion import Controller
from plcmotion.s7_1200 import MC_Home, MC_MoveVelocity, MC_Power, MC_Reset

SERVO, APP = 0.001, 0.004


def _flat(tree: dict, prefix: str = "") -> dict:
    out: dict[str, Any] = {}
    for k, v in tree.items():
        path = f"{prefix}.{k}" if prefix else k
        if isinstance(v, dict):
            out.update(_flat(v, path))
        else:
            out[path] = v
    return out


def config(actor: int = 1, extra: dict | None = None) -> dict:
    base = {
        "Actor": {"Type": actor},
        "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0 if actor == 2 else 0.0},
        "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": 200.0, "Jerk": 0.0,
                            "EmergencyDeceleration": 1000.0},
        "Actor.Interface": {"DriveReadyInput": "", "EnableDriveOutput": "Q0.0"},
        "Plant": {"InitialPosition": 0.0},
    }
    cfg = _flat(base)
    cfg.update(_flat(extra or {}))
    return cfg


class Bench(FbProgram):
    """A controller with one axis and a program that calls every added instance once per application cycle."""

    def __init__(self, actor: int = 1, extra: dict | None = None, *, filt: float = 0.0064, enable: bool = True,
                 state_file: str | None = None):
        ctl = Controller(servo_cycle=SERVO, app_cycle=APP, input_filter=filt, state_file=state_file)
        super().__init__(ctl, ctl.add_positioning_axis("Axis_1", config(actor, extra)), MC_Power(Enable=enable),
                         enable=enable)

    def reset(self) -> MC_Reset:
        rs = self.start(MC_Reset())
        self.until(lambda: rs.Done or rs.Error, 0.1, "MC_Reset ended")
        out = dict(rs.outputs)
        rs.Execute = False
        self.ctl.step()
        return out

    def moving(self, velocity: float = 30.0) -> MC_MoveVelocity:
        mv = self.start(MC_MoveVelocity(), Velocity=velocity, Direction=0)
        self.until(lambda: mv.InVelocity, 1.0, "constant velocity")
        return mv

    def direct_home(self, position: float = 0.0) -> None:
        hm = self.start(MC_Home(), Mode=0, Position=position)
        self.until(lambda: hm.Done, 0.1, "MC_Home Mode 0")
        hm.Execute = False
        self.ctl.step()
        assert self.axis.StatusBits.HomingDone


def assert_disabled_with(b: Bench, error_id: int, error_info: int) -> None:
    """Reaction 'remove enable' (§12.8) with the error shown at MC_Power (§9.6)."""
    assert b.power.Error and (b.power.ErrorID, b.power.ErrorInfo) == (error_id, error_info), b.power.outputs
    assert not b.power.Status and not b.axis.StatusBits.Enable
    assert not b.ctl.outputs["Q0.0"], "drive enable output still TRUE"
    assert b.axis.StatusBits.Error


def assert_re_enabled(b: Bench) -> None:
    """§11.1.1.1: enabled again automatically after the acknowledgement (Enable stayed TRUE)."""
    b.until(lambda: b.power.Status, 0.5, "automatic re-enable")
    b.ctl.step()
    assert b.power.Status and not b.power.Error and b.axis.StatusBits.Enable
    assert b.ctl.outputs["Q0.0"] and not b.axis.StatusBits.Error


# ---------------------------------------------------------------------------------------------------------
# drive ready input
READY = {"Actor.Interface.DriveReadyInput": "I0.3"}


@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
def test_s7_1200_11_1_1_enable_waits_for_drive_ready_input(actor):
    """§11.1.1.1 'Enabling an axis with configured drive interface': the enable output is set, the CPU waits for
    'Drive ready'; Status (and StatusBits.Enable) TRUE only once the ready input is TRUE; §5.4.3.2."""
    b = Bench(actor, READY, enable=False)
    b.ctl.inputs.force("I0.3", False)                  # the drive does not report ready
    b.power.Enable = True
    b.steps(50)
    assert b.ctl.outputs["Q0.0"], "enable output set while waiting for 'Drive ready'"
    assert b.power.Busy and not b.power.Status and not b.axis.StatusBits.Enable
    b.ctl.inputs.force("I0.3", None)                   # ready from the drive again
    t0 = b.ctl.time
    b.until(lambda: b.power.Status, 0.2, "enabled once ready")
    assert b.ctl.time - t0 >= 0.0064                   # the input filter of the ready input
    assert b.axis.StatusBits.Enable and not b.power.Error


@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
def test_s7_1200_12_8_8000_drive_ready_lost(actor):
    """§12.8 16#8000/16#0001 'Drive error, loss of Drive ready' (remedy: acknowledge, restore the drive signal);
    decision #38: remove enable; decision #25: ErrorBits.DriveFault; S-PWR-2: error at MC_Power, Status FALSE,
    after removing the cause and MC_Reset the axis is enabled again (Enable stayed TRUE)."""
    b = Bench(actor, READY)
    mv = b.moving()
    b.ctl.inputs.force("I0.3", False)
    b.until(lambda: not b.power.Status, 0.1, "disabled")
    b.ctl.step()
    assert_disabled_with(b, 0x8000, 0x0001)
    assert mv.Error and (mv.ErrorID, mv.ErrorInfo) == (0x8000, 0x0001), mv.outputs
    assert b.axis.ErrorBits.DriveFault
    b.ctl.inputs.force("I0.3", None)
    rs = b.reset()
    assert rs["Done"], rs
    assert_re_enabled(b)
    assert not b.axis.ErrorBits.DriveFault


@pytest.mark.parametrize("actor", [2, 1], ids=["PTO", "PROFIdrive"])
def test_s7_1200_12_8_8000_injected_drive_not_ready(actor):
    """§12.8 16#8000/16#0001: the drive withdraws 'Drive ready' (fault injection); remove enable (decision #38),
    acknowledged by MC_Reset, re-enabled automatically."""
    b = Bench(actor, READY)
    b.moving()
    b.axis.inject_fault("drive_not_ready")
    b.steps(3)
    assert_disabled_with(b, 0x8000, 0x0001)
    assert b.axis.ErrorBits.DriveFault
    rs = b.reset()
    assert rs["Done"], rs
    assert_re_enabled(b)


# ---------------------------------------------------------------------------------------------------------
# drive faults 16#800C
DRIVE_FAULTS = [("", 0x0001), ("control_requested", 0x003C), ("shutdown", 0x003D), ("station", 0x003E),
                ("sign_of_life", 0x003F)]


@pytest.mark.parametrize("detail,info", DRIVE_FAULTS, ids=[f"16#{i:04X}" for _, i in DRIVE_FAULTS])
def test_s7_1200_12_8_800C_drive_fault(detail, info):
    """§12.8 16#800C 'Alarm message from drive' (16#0001), 'Control requested failed' (16#003C), 'drive has shut
    down' (16#003D), 'station failure' (16#003E), 'sign of life faulty' (16#003F): reaction remove enable; shown at
    the active instruction and MC_Power; decision #25: ErrorBits.DriveFault; acknowledged (cause gone) -> the axis
    is enabled again (§11.1.1.1)."""
    b = Bench(1)
    mv = b.moving()
    b.axis.inject_fault("drive", detail)
    b.steps(2)
    assert mv.Error and (mv.ErrorID, mv.ErrorInfo) == (0x800C, info), mv.outputs
    assert_disabled_with(b, 0x800C, info)
    assert b.axis.ErrorBits.DriveFault
    rs = b.reset()
    assert rs["Done"] and not rs["Error"], rs
    assert_re_enabled(b)


def test_s7_1200_12_8_800C_003D_analog_drive_shut_down():
    """§12.8 16#800C/16#003D 'PROFIdrive/analog: drive has shut down' on an analog drive: remove enable."""
    b = Bench(0)
    b.moving()
    b.axis.inject_fault("drive", "shutdown")
    b.steps(2)
    assert_disabled_with(b, 0x800C, 0x003D)
    b.reset()
    assert_re_enabled(b)


# ---------------------------------------------------------------------------------------------------------
# encoder faults 16#800A
ENCODER_FAULTS = [("", 0x0001), ("hardware", 0x0034), ("dirty", 0x0035), ("absolute_value", 0x0036),
                  ("zero_mark", 0x0037), ("parking", 0x0038), ("station", 0x0040), ("sign_of_life", 0x0041)]


@pytest.mark.parametrize("detail,info", ENCODER_FAULTS, ids=[f"16#{i:04X}" for _, i in ENCODER_FAULTS])
def test_s7_1200_12_8_800A_encoder_fault_resets_homing_done(detail, info):
    """§12.8 16#800A (16#0001 alarm from encoder, 16#0034 hardware error, 16#0035 dirty, 16#0036 absolute value,
    16#0037 zero mark monitoring, 16#0038 parking, 16#0040 station failure, 16#0041 sign of life), reaction remove
    enable; §2.5 incremental actual values: 'Error in the encoder system, or encoder failure' resets HomingDone;
    §10.1 StatusSensor.State not 2 (values invalid) while the fault is there; decision #25 ErrorBits.SensorFault."""
    b = Bench(1)
    b.direct_home(0.0)
    mv = b.moving()
    assert b.axis.StatusSensor.State == 2
    b.axis.inject_fault("encoder", detail)
    b.steps(2)
    assert mv.Error and (mv.ErrorID, mv.ErrorInfo) == (0x800A, info), mv.outputs
    assert_disabled_with(b, 0x800A, info)
    assert b.axis.ErrorBits.SensorFault
    assert not b.axis.StatusBits.HomingDone
    assert b.axis.StatusSensor.State != 2
    rs = b.reset()
    assert rs["Done"], rs
    assert_re_enabled(b)
    assert b.axis.StatusSensor.State == 2 and not b.axis.ErrorBits.SensorFault
    assert not b.axis.StatusBits.HomingDone, "homed status is not restored by the acknowledgement"


ABS = {"Sensor[1].Type": 1, "Sensor[1].Interface.Type": 2, "Sensor[1].Parameter.DeterminableRevolutions": 4096,
       "Plant.InitialPosition": 37.5}


def test_s7_1200_2_5_absolute_encoder_fault_resets_homing_done(tmp_path):
    """§2.5 'Technology objects with absolute actual values': 'Errors in the sensor system/encoder failure' reset
    the Homed status; it is not restored by a later POWER OFF -> ON (the retentive homed status was lost with
    the error, decision #52)."""
    state = str(tmp_path / "retain.json")
    b = Bench(1, ABS, state_file=state)
    hm = b.start(MC_Home(), Mode=7, Position=100.0)
    b.until(lambda: hm.Done, 0.1, "mode 7")
    assert b.axis.StatusBits.HomingDone
    b.axis.inject_fault("encoder", "hardware")
    b.steps(2)
    assert_disabled_with(b, 0x800A, 0x0034)
    assert not b.axis.StatusBits.HomingDone
    b.reset()
    assert_re_enabled(b)
    assert not b.axis.StatusBits.HomingDone
    b.ctl.power_cycle()
    b.steps(2)
    assert not b.axis.StatusBits.HomingDone, "POWER ON must not bring back the homed status lost by the error"
    b2 = Bench(1, ABS, state_file=state)
    assert not b2.axis.StatusBits.HomingDone


# ---------------------------------------------------------------------------------------------------------
# persistent faults, acknowledgement, automatic re-enable
@pytest.mark.parametrize("kind,detail,error_id,info", [
    ("encoder", "dirty", 0x800A, 0x0035),
    ("drive", "shutdown", 0x800C, 0x003D),
])
def test_s7_1200_11_1_2_persistent_fault_not_acknowledged_until_cleared(kind, detail, error_id, info):
    """§11.1.2.1 MC_Reset: requirement 'cause of a pending error removed'; success = Done and StatusBits.Error
    FALSE.  While the cause persists the error stays (StatusBits.Error TRUE, MC_Power shows it, the axis is not
    enabled); once it is removed, MC_Reset acknowledges it and the axis is enabled again (§11.1.1.1)."""
    b = Bench(1)
    b.moving()
    b.axis.inject_fault(kind, detail, persistent=True)
    b.steps(2)
    assert_disabled_with(b, error_id, info)
    b.reset()
    b.steps(20)
    assert b.axis.StatusBits.Error, "error acknowledged although its cause persists"
    assert_disabled_with(b, error_id, info)
    b.axis.clear_fault()
    b.steps(5)
    assert b.axis.StatusBits.Error, "the error must wait for MC_Reset"
    rs = b.reset()
    assert rs["Done"] and not rs["Error"], rs
    assert_re_enabled(b)


def test_s7_1200_11_1_1_no_re_enable_when_enable_was_reset():
    """§11.1.1.1: the automatic re-enable applies only 'provided Enable stayed TRUE'.  With Enable FALSE at the
    acknowledgement the axis stays disabled until a new enable."""
    b = Bench(1)
    b.moving()
    b.axis.inject_fault("drive", "")
    b.steps(2)
    assert_disabled_with(b, 0x800C, 0x0001)
    b.power.Enable = False
    b.steps(2)
    rs = b.reset()
    assert rs["Done"], rs
    b.steps(50)
    assert not b.power.Status and not b.axis.StatusBits.Enable and not b.ctl.outputs["Q0.0"]
    assert not b.axis.StatusBits.Error
    b.power.Enable = True
    assert_re_enabled(b)


def test_s7_1200_12_8_fault_during_standstill_disable_output():
    """§5.4.3.2 / §11.1.1.1: the drive enable output is controlled by MC_Power; §12.8 remove enable on a drive
    fault also at standstill: the output goes FALSE and MC_Power.Status FALSE."""
    b = Bench(1)
    assert b.ctl.outputs["Q0.0"] and b.power.Status
    b.axis.inject_fault("drive", "station")
    b.steps(2)
    assert_disabled_with(b, 0x800C, 0x003E)
