"""The fault injection component (``kernel.fault_injection.FaultInjection``): alone on a fake axis, then on a
kernel ``Controller`` axis through the public axis API (``inject_fault``, ``clear_fault``, ``disturb_load``,
``sensor_valid``, ``communication_ok``; docs/fault_injection.md), without any dialect.

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §12.8 16#8000 (drive not ready), 16#800A
(encoder alarm: 16#0034 hardware error, 16#0040 encoder station failure on the bus), 16#800C (drive alarm:
16#003E drive station failure), reaction "remove enable" for all; §2.5 an encoder error resets "homed";
§12.7 / §10.1 invalid actual values (StatusSensor.State <> 2) may be acknowledged to move without position
control; §11.1.2 MC_Reset acknowledges an alarm only once its cause is gone; §12.9.21/§12.9.22
StatusDrive/StatusSensor.CommunicationOK (a pulse output has no bus).
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.drives.spec import DriveSpec, EncoderInterface, EncoderSpec, SetpointInterface
from plcmotion.kernel import faults as F
from plcmotion.kernel.fault_injection import FaultInjection
from plcmotion.kernel.faults import Reaction


# --- the component alone --------------------------------------------------------------------------------
class FakeDrive:
    def __init__(self) -> None:
        self.faulty = False
        self.disturbances: list[dict] = []

    def set_fault(self, on: bool) -> None:
        self.faulty = on

    def disturb(self, **kw) -> None:
        self.disturbances.append(kw)


class FakeAxis:
    """A FaultHost: a homed PROFIdrive axis (or a PTO/simulated one) that records alarms and retentions."""

    def __init__(self, *, pto: bool = False, sim: bool = False,
                 setpoint: SetpointInterface = SetpointInterface.PROFIDRIVE,
                 encoder: EncoderInterface = EncoderInterface.DRIVE_TELEGRAM):
        self.name = "Fake"
        self.config = SimpleNamespace(drive=DriveSpec(interface=setpoint, encoder=EncoderSpec(interface=encoder)))
        self.drive = FakeDrive()
        self.pto, self.sim = pto, sim
        self.servo = not pto and not sim
        self.homed = True
        self.alarms: list[F.Fault] = []
        self.retained: list[object] = []
        self.ctl = SimpleNamespace(_retain_axis=self.retained.append)

    def raise_alarm(self, fault):
        self.alarms.append(fault)


def alarms(ax: FakeAxis) -> list[tuple[str, str, Reaction]]:
    return [(a.kind, a.detail, a.reaction) for a in ax.alarms]


def test_kernel_fault_injection_drive_fault_removes_enable_and_faults_the_drive():
    """S7-1200 V6 §12.8 16#800C: alarm message from the drive, reaction remove enable; the drive itself is
    faulty (not ready) until the fault is acknowledged."""
    ax = FakeAxis()
    fi = FaultInjection(ax)
    fi.inject("drive", "shutdown")
    assert alarms(ax) == [(F.DRIVE_ALARM, "shutdown", Reaction.REMOVE_ENABLE)]
    assert ax.drive.faulty and ax.homed                # a drive fault other than a station failure keeps "homed"
    assert fi.keeps_alarm(ax.alarms[0])                # the drive is still faulty
    fi.acknowledge()                                   # transient: the acknowledgement removes the cause
    assert fi.faults == {} and not ax.drive.faulty and not fi.keeps_alarm(ax.alarms[0])


@pytest.mark.parametrize("encoder, detail", [(EncoderInterface.PROFIDRIVE, "station"),
                                             (EncoderInterface.HIGH_SPEED_COUNTER, "hardware")])
def test_kernel_fault_injection_encoder_loss_invalidates_the_actual_value(encoder, detail):
    """S7-1200 V6 §12.8 16#800A: an encoder on the bus fails as a station (16#0040), a local one with a
    hardware error (16#0034); remove enable; §2.5 "homed" is reset (and kept so across a power cycle);
    StatusSensor.State not valid; CommunicationOK FALSE only for the station failure."""
    ax = FakeAxis(encoder=encoder)
    fi = FaultInjection(ax)
    fi.inject("encoder_loss")
    assert alarms(ax) == [(F.ENCODER, detail, Reaction.REMOVE_ENABLE)]
    assert ax.homed is False and ax.retained == [ax]
    assert fi.sensor_valid is False
    assert fi.communication_ok("encoder") is (detail != "station")
    assert fi.communication_ok("drive") is True


def test_kernel_fault_injection_bus_loss_takes_the_encoder_in_the_drive_telegram_with_it():
    """S7-1200 V6 §12.8 16#800C/16#003E drive station failure; the encoder travelling in the drive's
    telegram fails with it (16#800A/16#0040)."""
    ax = FakeAxis(encoder=EncoderInterface.DRIVE_TELEGRAM)
    fi = FaultInjection(ax)
    fi.inject("communication_loss")
    assert alarms(ax) == [(F.DRIVE_ALARM, "station", Reaction.REMOVE_ENABLE),
                          (F.ENCODER, "station", Reaction.REMOVE_ENABLE)]
    assert not fi.communication_ok("drive") and not fi.communication_ok("encoder")
    separate = FakeAxis(encoder=EncoderInterface.PROFIDRIVE)
    FaultInjection(separate).inject("communication_loss")
    assert [a[0] for a in alarms(separate)] == [F.DRIVE_ALARM]


def test_kernel_fault_injection_persistent_fault_survives_the_acknowledgement_until_cleared():
    """S7-1200 V6 §11.1.2: MC_Reset acknowledges an alarm only once its cause is removed; an invalid encoder
    may be acknowledged anyway to move without position control (§12.7)."""
    ax = FakeAxis()
    fi = FaultInjection(ax)
    fi.inject("drive", persistent=True)
    fi.inject("encoder", "dirty", persistent=True)
    drive_alarm, encoder_alarm = ax.alarms
    fi.acknowledge()
    assert fi.keeps_alarm(drive_alarm) and not fi.keeps_alarm(encoder_alarm)
    assert ax.drive.faulty and not fi.sensor_valid
    fi.clear("drive")
    fi.acknowledge()
    assert not fi.keeps_alarm(drive_alarm) and not ax.drive.faulty
    assert "encoder" in fi.faults                       # still persistent until cleared
    fi.clear()
    fi.acknowledge()
    assert fi.faults == {} and fi.sensor_valid


def test_kernel_fault_injection_refuses_faults_the_axis_cannot_have():
    """A simulated axis has no devices (§5.4.3.1), a pulse output no encoder and no bus (§12.9.21: no
    CommunicationOK), an analog drive no bus; details outside §12.8's ErrorInfos are refused."""
    with pytest.raises(ValueError, match="simulated axis"):
        FaultInjection(FakeAxis(sim=True)).inject("drive")
    pto = FakeAxis(pto=True)
    with pytest.raises(ValueError, match="no encoder"):
        FaultInjection(pto).inject("encoder")
    assert FaultInjection(pto).communication_ok("drive") is False
    with pytest.raises(ValueError, match="communication_loss needs a PROFIdrive axis"):
        FaultInjection(FakeAxis(setpoint=SetpointInterface.ANALOG)).inject("communication_loss")
    with pytest.raises(ValueError, match="detail"):
        FaultInjection(FakeAxis()).inject("drive", "melted")
    with pytest.raises(ValueError, match="fault kind"):
        FaultInjection(FakeAxis()).inject("brakes")


def test_kernel_fault_injection_load_disturbance_goes_to_the_drive_checked():
    """A load disturbance reaches the simulated drive; a stepper (open loop) can only lose steps; numbers
    beyond REAL's finite range are refused."""
    ax = FakeAxis()
    fi = FaultInjection(ax)
    fi.disturb_load(jump=2, force=5.0)
    fi.clear("load")
    assert ax.drive.disturbances == [{"jump": 2.0, "force": 5.0, "blocked": None}, {"force": 0.0, "blocked": False}]
    with pytest.raises(ValueError, match="finite"):
        fi.disturb_load(jump=float("nan"))
    with pytest.raises(ValueError, match="only a position jump"):
        FaultInjection(FakeAxis(pto=True)).disturb_load(force=1.0)


# --- through a kernel Controller axis ---------------------------------------------------------------------
OWNER = object()               # the enabling instruction


def enabled_axis():
    """A homed-free PROFIdrive axis with the encoder in the drive telegram and an enable output."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor.Type": 1, "Actor.Interface.EnableDriveOutput": "Q0.0", "Sensor[1].Interface.Type": 2,
        "DynamicLimits.MaxVelocity": 100.0, "DynamicDefaults.Acceleration": 500.0,
        "DynamicDefaults.Deceleration": 500.0, "DynamicDefaults.Jerk": 0.0})
    assert axis.power(OWNER, True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 1.0)
    return ctl, axis


def test_kernel_fault_injection_bus_loss_on_a_controller_axis():
    """S7-1200 V6 §12.8 16#800C/16#003E with 16#800A/16#0040, reaction remove enable: the axis is disabled,
    its enable output FALSE, the actual values invalid; §11.1.2 the acknowledgement clears a transient fault,
    and the axis can be enabled again (§11.1.1.1)."""
    ctl, axis = enabled_axis()
    axis.inject_fault("communication_loss")
    assert axis.state == "disabled" and ctl.outputs["Q0.0"] is False
    assert [(a.kind, a.detail) for a in axis.alarms] == [(F.DRIVE_ALARM, "station"), (F.ENCODER, "station")]
    assert axis.sensor_valid is False
    assert not axis.communication_ok("drive") and not axis.communication_ok("encoder")
    assert axis.fault_injection.faults == {"drive": ("station", False), "encoder": ("station", False)}
    assert axis.acknowledge() is None
    assert axis.alarms == [] and axis.sensor_valid and axis.communication_ok("drive")
    assert axis.power(OWNER, True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 1.0)
    assert ctl.outputs["Q0.0"] is True


def test_kernel_fault_injection_persistent_drive_fault_on_a_controller_axis():
    """S7-1200 V6 §11.1.2: while the drive stays faulty (persistent) MC_Reset returns its alarm; once the
    cause is cleared the acknowledgement succeeds."""
    ctl, axis = enabled_axis()
    axis.inject_fault("drive", "control_requested", persistent=True)
    assert axis.state == "disabled"
    pending = axis.acknowledge()
    assert pending is not None and (pending.kind, pending.detail) == (F.DRIVE_ALARM, "control_requested")
    axis.clear_fault("drive")
    assert axis.acknowledge() is None and axis.alarms == []
