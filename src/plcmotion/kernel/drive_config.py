"""The drive specification of an axis from its kernel parameters.

This module is the one place that knows which configuration tags describe an axis's drive, encoder and
simulated machine.  The kernel's parameters are still named like the S7-1200 technology object data block
(S7-1200 Motion Control V6 §12.9: ``Actor.*``, ``Sensor[1].*``, ``Mechanics.*``, plus plcmotion's own
``Plant.*``); the S7-1500 maps its tags onto them.  :func:`drive_spec` turns them into the neutral
:class:`~plcmotion.drives.spec.DriveSpec` that drive models take, so that a drive never reads a tag path;
a family with its own schema will produce the spec directly later.

The spec is part of the axis's typed configuration: ``kernel.axis_config.axis_config`` builds it whenever
configuration changes become effective (``axis.config.drive``), and the axis hands it to
``DriveChannel.reconfigure``.
"""
from __future__ import annotations

from typing import Any, Mapping

from ..drives.spec import (ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, PlantSpec,
                           SetpointInterface)
from .plant_schema import plant_spec

_S = "Sensor[1]"

#: Actor.Type (§12.9.5): 0 analog output, 1 PROFIdrive telegram, 2 pulse output (PTO)
_SETPOINT_INTERFACE = {0: SetpointInterface.ANALOG, 1: SetpointInterface.PROFIDRIVE, 2: SetpointInterface.PULSES}
#: Sensor[1].Type (§12.9.6): 0 incremental, 1 absolute, 2 cyclic absolute
_ENCODER_KIND = {0: EncoderKind.INCREMENTAL, 1: EncoderKind.ABSOLUTE, 2: EncoderKind.CYCLIC_ABSOLUTE}
#: Sensor[1].Interface.Type (§12.9.6): 0 PROFIdrive encoder, 1 technology module, 2 encoder on drive, 4 HSC
_ENCODER_INTERFACE = {0: EncoderInterface.PROFIDRIVE, 1: EncoderInterface.TECHNOLOGY_MODULE,
                      2: EncoderInterface.DRIVE_TELEGRAM, 4: EncoderInterface.HIGH_SPEED_COUNTER}


def drive_spec(p: Mapping[str, Any]) -> DriveSpec:
    """The drive, encoder and simulated machine of an axis with kernel parameters ``p`` (valid values)."""
    actor = p["Actor.Type"]
    if actor == 2:
        actuator = ActuatorKind.PULSE
    elif p["Simulation.Mode"] == 1:
        actuator = ActuatorKind.IDEAL
    else:
        actuator = ActuatorKind.SPEED_SERVO
    return DriveSpec(
        actuator=actuator,
        interface=_SETPOINT_INTERFACE[actor] if actuator is not ActuatorKind.IDEAL else SetpointInterface.NONE,
        telegram=p["Actor.Interface.Telegram"],
        reference_speed=p["Actor.DriveParameter.ReferenceSpeed"],
        max_speed=p["Actor.DriveParameter.MaxSpeed"],
        length_per_revolution=p["Mechanics.LeadScrew"],
        pulses_per_revolution=p["Actor.DriveParameter.PulsesPerDriveRevolution"],
        ready_delay=p["Plant.ReadyDelay"],
        off_ramp_time=p["Plant.OffRampTime"],
        encoder=_encoder(p),
        plant=_plant(p),
    )


def _encoder(p: Mapping[str, Any]) -> EncoderSpec:
    kind = _ENCODER_KIND[p[f"{_S}.Type"]]
    # the encoder turns with the motor (mounting 0: one revolution per lead) or with the load (2: external,
    # its own distance per revolution), §12.9.6.3
    per_rev = (p["Mechanics.LeadScrew"] if p[f"{_S}.MountingMode"] == 0
               else p[f"{_S}.Parameter.DistancePerRevolution"])
    return EncoderSpec(
        kind=kind,
        rotary=p[f"{_S}.System"] == 1,
        steps_per_revolution=p[f"{_S}.Parameter.StepsPerRevolution"],
        fine_bits=p[f"{_S}.Parameter.FineResolutionXist1"],
        fine_bits_absolute=p[f"{_S}.Parameter.FineResolutionXist2"],
        distance_per_revolution=per_rev,
        step_length=p[f"{_S}.Parameter.Resolution"],
        determinable_revolutions=(p[f"{_S}.Parameter.DeterminableRevolutions"]
                                  if kind is not EncoderKind.INCREMENTAL else 0),
        inverse_direction=bool(p[f"{_S}.InverseDirection"]),
        interface=_ENCODER_INTERFACE[p[f"{_S}.Interface.Type"]],
    )


def _plant(p: Mapping[str, Any]) -> PlantSpec:
    return plant_spec(p, hw_min=(p["PositionLimits_HW.MinSwitchAddress"], p["PositionLimits_HW.MinSwitchLevel"]),
                      hw_max=(p["PositionLimits_HW.MaxSwitchAddress"], p["PositionLimits_HW.MaxSwitchLevel"]),
                      homing_inputs=[(p[f"{_S}.{kind}.DigitalInputAddress"], p[f"{_S}.{kind}.SwitchLevel"])
                                     for kind in ("ActiveHoming", "PassiveHoming")],
                      ready_input=p["Actor.Interface.DriveReadyInput"] or "")
